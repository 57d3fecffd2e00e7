#pragma once
// A marker trial written as Vicon Nexus's Export ASCII writes it (core/io/nexus_csv.h): for
// the reader's tests and the fuzz seeds. Test code only: the program reads Nexus exports, it
// does not write them.

#include <cmath>
#include <sstream>
#include <string>

#include "core/common/trial.h"

namespace ew::test {

struct NexusLayout {
  char delimiter = ',';
  bool velocities = false;   // X', Y', Z' after each marker's X, Y, Z (Nexus's derivative option)
  bool devicesFirst = true;  // a force-plate section at 10 times the rate before the markers
  std::string subject = "Subject01";
};

// A marker trial written as Nexus's Export ASCII writes it (frames numbered from firstFrame).
inline std::string nexusText(const RawTrial& t, const NexusLayout& layout = {}) {
  const char d = layout.delimiter;
  const int perMarker = layout.velocities ? 6 : 3;
  std::ostringstream out;
  out.precision(10);
  if (layout.devicesFirst) {
    out << "Devices\n" << t.rateHz * 10 << "\n" << d << d << "Imported AMTI OR6 Series Force Plate #1 - Force\n";
    out << "Frame" << d << "Sub Frame" << d << "Fx" << d << "Fy" << d << "Fz\n" << d << d << "N" << d << "N" << d << "N\n";
    for (int f = 0; f < 3; ++f)
      for (int sub = 0; sub < 10; ++sub) out << f + t.firstFrame << d << sub << d << "0.1" << d << "-0.2" << d << "3.5\n";
    out << "\n";
  }
  out << "Trajectories\n" << t.rateHz << "\n" << d << d;
  for (size_t m = 0; m < t.labels.size(); ++m) {
    out << layout.subject << ":" << t.labels[m];
    if (m + 1 < t.labels.size()) out << std::string(static_cast<size_t>(perMarker), d);
  }
  out << "\nFrame" << d << "Sub Frame";
  for (size_t m = 0; m < t.labels.size(); ++m) {
    out << d << "X" << d << "Y" << d << "Z";
    if (layout.velocities) out << d << "X'" << d << "Y'" << d << "Z'";
  }
  out << "\n" << d;
  for (size_t m = 0; m < t.labels.size(); ++m)
    for (int k = 0; k < perMarker; ++k) out << d << (k < 3 ? "mm" : "mm/s");
  out << "\n";
  for (Eigen::Index r = 0; r < t.positionsMm.rows(); ++r) {
    out << r + t.firstFrame << d << 0;
    for (Eigen::Index m = 0; m < static_cast<Eigen::Index>(t.labels.size()); ++m) {
      for (int k = 0; k < perMarker; ++k) {
        const double v = k < 3 ? t.positionsMm(r, 3 * m + k) : 12.5;
        out << d;
        if (std::isfinite(t.positionsMm(r, 3 * m))) out << v;
      }
    }
    out << "\n";
  }
  out << "\n";
  return out.str();
}

}  // namespace ew::test
