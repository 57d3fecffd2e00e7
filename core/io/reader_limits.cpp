#include "core/io/reader_limits.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/common/errors.h"

namespace ew {
namespace {

bool plausibleRate(double rateHz) {
  return std::isfinite(rateHz) && rateHz >= kMinFrameRateHz && rateHz <= kMaxFrameRateHz;
}

std::string rateProblem(double rateHz) {
  std::ostringstream msg;
  msg << "frame rate " << rateHz << " Hz is outside the plausible " << kMinFrameRateHz << "-"
      << kMaxFrameRateHz << " Hz";
  if (std::isfinite(rateHz) && rateHz > 0 && rateHz < kMinFrameRateHz) {
    msg << " (a time column in milliseconds?)";
  }
  return msg.str();
}

}  // namespace

double skeletonPointFrameAllowance(std::size_t fileBytes) {
  return std::clamp(kPointFramesPerFileByte * static_cast<double>(fileBytes),
                    kMinPointFrameAllowance, kMaxPointFrames);
}

double checkedFileRateHz(double rateHz, const std::string& file, const std::string& where) {
  if (!plausibleRate(rateHz)) {
    throwMalformed(file, where,
                   rateProblem(rateHz) + "; set the rate override if the file is right");
  }
  return rateHz;
}

double checkedRateOverrideHz(double rateHz, const std::string& file) {
  return checkedGivenRateHz(rateHz, file, "frame-rate override");
}

double checkedGivenRateHz(double rateHz, const std::string& file, const std::string& option) {
  if (!plausibleRate(rateHz)) throw Error(ErrorKind::BadArgument, file, option, rateProblem(rateHz));
  return rateHz;
}

void checkPointFrames(double frames, double points, double allowance, const std::string& file,
                      const std::string& where) {
  if (frames * points <= allowance) return;
  std::ostringstream msg;
  msg << std::fixed;
  msg.precision(0);
  msg << frames << " frames of " << points << " points is more than this reader keeps for a file "
      << "of this size (at most " << allowance << " point-frames; docs/FORMATS.md, Limits)";
  throw Error(ErrorKind::Unsupported, file, where, msg.str());
}

}  // namespace ew
