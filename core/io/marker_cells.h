#pragma once
// The cells of one marker in a row of a lab's text export (Vicon Nexus CSV, Qualisys TSV):
// the two readers' one rule for what is a point and what is a gap.

#include <Eigen/Core>
#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace ew {

// The marker's point from its X, Y and Z cells (`columns` into `fields`), or nothing when it
// is gone: a cell empty or past the row's end (one missing coordinate is a gap, not a point),
// and with `zeroIsGap` also 0, 0, 0 (older QTM writes a gap so). A cell that is not a number
// throws Error(Malformed) naming the file, line and column.
std::optional<Eigen::Vector3d> markerCells(const std::vector<std::string_view>& fields,
                                           const std::array<size_t, 3>& columns, bool zeroIsGap,
                                           const std::string& file, int line);

}  // namespace ew
