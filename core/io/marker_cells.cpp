#include "core/io/marker_cells.h"

#include <cmath>

#include "core/common/errors.h"
#include "core/io/text_table.h"

namespace ew {

std::optional<Eigen::Vector3d> markerCells(const std::vector<std::string_view>& fields,
                                           const std::array<size_t, 3>& columns, bool zeroIsGap,
                                           const std::string& file, int line) {
  Eigen::Vector3d p = Eigen::Vector3d::Constant(std::nan(""));
  for (Eigen::Index axis = 0; axis < 3; ++axis) {
    const size_t c = columns[static_cast<size_t>(axis)];
    if (c < fields.size() && !parseDouble(fields[c], p[axis], true))
      throwMalformed(file, linePosition(line, static_cast<int>(c + 1)), "not a number: " + shownWord(fields[c]));
  }
  if (!p.allFinite() || (zeroIsGap && p.isZero(0.0))) return std::nullopt;
  return p;
}

}  // namespace ew
