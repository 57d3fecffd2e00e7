#include "core/camera/focal_length.h"

#include <cmath>
#include <sstream>

namespace ew {

bool isPlausibleFocalPx(double focalPx) {
  return std::isfinite(focalPx) && focalPx >= kMinFocalPx && focalPx <= kMaxFocalPx;
}

std::string focalLengthProblem(double focalPx) {
  if (isPlausibleFocalPx(focalPx)) return "";
  std::ostringstream s;
  // Six significant digits: 5e-324 and 1e+308 shown as they were given, not as 0 or inf.
  s.precision(6);
  s << "focal length " << focalPx << " px: a camera's is finite and " << kMinFocalPx << "-" << kMaxFocalPx << " px";
  return s.str();
}

}  // namespace ew
