#pragma once
// The missing value every numeric array of the project uses (a joint not seen, a measure that
// cannot be had).

#include <limits>

namespace ew {

inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

}  // namespace ew
