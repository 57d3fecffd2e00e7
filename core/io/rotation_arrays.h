#pragma once
// 3×3 rotations as plain row-major arrays for the BVH and ASF/AMC readers' forward kinematics.
// Not Eigen: forward kinematics runs frames × bones times and the malformed-input tests parse
// skeletons thousands of times; Eigen's fixed-size products are tens of times slower in the
// Debug/ASan builds tests run in.

#include <array>
#include <cmath>
#include <cstddef>

namespace ew {

using Mat3 = std::array<double, 9>;  // row-major

inline constexpr Mat3 kIdentity3{1, 0, 0, 0, 1, 0, 0, 0, 1};

inline Mat3 transposed(const Mat3& m) {
  return {m[0], m[3], m[6], m[1], m[4], m[7], m[2], m[5], m[8]};
}

inline Mat3 multiply(const Mat3& a, const Mat3& b) {
  Mat3 out;
  for (std::size_t r = 0; r < 3; ++r) {
    for (std::size_t c = 0; c < 3; ++c) {
      out[3 * r + c] = a[3 * r] * b[c] + a[3 * r + 1] * b[3 + c] + a[3 * r + 2] * b[6 + c];
    }
  }
  return out;
}

// m <- m · R_axis(radians), axis 0, 1, 2 for x, y, z: only the two columns orthogonal to the
// axis change.
inline void postRotate(Mat3& m, int axis, double radians) {
  const double c = std::cos(radians), s = std::sin(radians);
  const int i = (axis + 1) % 3, j = (axis + 2) % 3;
  for (int row = 0; row < 3; ++row) {
    const auto at = [row](int col) { return static_cast<std::size_t>(3 * row + col); };
    const double a = m[at(i)], b = m[at(j)];
    m[at(i)] = c * a + s * b;
    m[at(j)] = c * b - s * a;
  }
}

}  // namespace ew
