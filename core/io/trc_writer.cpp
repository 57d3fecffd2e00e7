#include "core/io/trc_writer.h"

#include <cmath>
#include <iomanip>

#include "core/common/errors.h"
#include "core/common/skeleton.h"
#include "core/io/atomic_write.h"
#include "core/io/c3d_writer.h"
#include "core/io/joint_csv.h"
#include "core/io/text_table.h"

namespace ew {
namespace {

void checkTrcInput(const std::filesystem::path& file, const Eigen::Ref<const Eigen::MatrixXd>& m,
                   double rateHz, const std::string& units) {
  if (m.cols() != kDims3)
    throw Error(ErrorKind::BadArgument, file.string(), "", "expected 45 columns, got " + std::to_string(m.cols()));
  if (!(rateHz > 0) || !std::isfinite(rateHz))
    throw Error(ErrorKind::BadArgument, file.string(), "", "frame rate must be > 0");
  if (units != "mm" && units != "m")
    throw Error(ErrorKind::BadArgument, file.string(), "", "TRC units must be mm or m, not '" + units + "'");
}

void writeHeader(std::ostream& out, const std::filesystem::path& file, Eigen::Index frames, double rateHz,
                 const std::string& units) {
  out << "PathFileType\t4\t(X/Y/Z)\t" << file.filename().string() << "\n";
  out << "DataRate\tCameraRate\tNumFrames\tNumMarkers\tUnits\tOrigDataRate\tOrigDataStartFrame\tOrigNumFrames\n";
  out << std::fixed << std::setprecision(6) << rateHz << '\t' << rateHz << '\t' << frames << '\t' << kJointCount
      << '\t' << units << '\t' << rateHz << "\t1\t" << frames << "\n";
  out << "Frame#\tTime";
  for (const auto& name : kJointNames) out << '\t' << name << "\t\t";
  out << "\n\t";
  for (int k = 1; k <= kJointCount; ++k) out << "\tX" << k << "\tY" << k << "\tZ" << k;
  out << "\n\n";
}

}  // namespace

Eigen::Vector3d canonicalToOpenSim(const Eigen::Vector3d& p) { return {p.y(), p.z(), p.x()}; }
Eigen::Vector3d openSimToCanonical(const Eigen::Vector3d& p) { return {p.z(), p.x(), p.y()}; }

void writeTrc(const std::filesystem::path& file, const Eigen::Ref<const Eigen::MatrixXd>& m, double rateHz,
              const std::string& units) {
  checkTrcInput(file, m, rateHz, units);
  const double scale = units == "m" ? 0.001 : 1.0;
  writeFileAtomically(file, [&](std::ostream& out) {
    writeHeader(out, file, m.rows(), rateHz, units);
    for (Eigen::Index r = 0; r < m.rows(); ++r) {
      out << std::fixed << std::setprecision(6) << (r + 1) << '\t' << static_cast<double>(r) / rateHz;
      out << std::setprecision(units == "m" ? 8 : 5);
      for (int j = 0; j < kJointCount; ++j) {
        const Eigen::Vector3d p = canonicalToOpenSim(m.block<1, 3>(r, 3 * j).transpose()) * scale;
        for (int a = 0; a < 3; ++a) {
          out << '\t';
          if (std::isfinite(p[a])) out << p[a];
        }
      }
      out << "\n";
    }
  });
}

bool writesC3d(const std::filesystem::path& file) { return toLower(file.extension().string()) == ".c3d"; }

void writeJointTrajectories(const std::filesystem::path& file, const Eigen::MatrixXd& framesMm, double rateHz,
                            const std::vector<std::string>& commentLines, const Eigen::MatrixXd& feetMm,
                            bool feetInSagittalPlanes) {
  if (toLower(file.extension().string()) == ".trc") {
    writeTrc(file, framesMm, rateHz, "mm");
  } else if (writesC3d(file)) {
    writeWalkerWithFeetC3d(file, framesMm, feetMm, rateHz, commentLines, {}, feetInSagittalPlanes);
  } else {
    writeJointCsv(file, framesMm, rateHz, commentLines);
  }
}

}  // namespace ew
