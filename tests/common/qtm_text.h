#pragma once
// A marker trial written as Qualisys Track Manager's TSV export writes it (core/io/qtm_tsv.h):
// for the reader's tests and the fuzz seeds. Test code only: the program reads QTM exports, it
// does not write them.

#include <cmath>
#include <sstream>
#include <string>

#include "core/common/trial.h"

namespace ew::test {

struct QtmLayout {
  bool frameAndTime = true;   // the Frame and Time columns before the coordinates
  bool columnHeader = true;   // with their `Frame Time LASI X …` row (newer QTM)
  bool zerosForGaps = false;  // a gap as 0, 0, 0 (older QTM) instead of empty cells
  bool events = false;        // an EVENT line in the header
};

inline std::string qtmText(const RawTrial& t, const QtmLayout& layout = {}) {
  const auto n = static_cast<Eigen::Index>(t.labels.size());
  std::ostringstream out;
  out.precision(10);
  out << "NO_OF_FRAMES\t" << t.positionsMm.rows() << "\nNO_OF_CAMERAS\t8\nNO_OF_MARKERS\t" << n
      << "\nFREQUENCY\t" << t.rateHz << "\nNO_OF_ANALOG\t0\nANALOG_FREQUENCY\t0\nDESCRIPTION\t--\n"
      << "TIME_STAMP\t2026-11-28, 10:39:38.777\t406646.66137317\nDATA_INCLUDED\t3D\n";
  if (layout.events) out << "EVENT\tLeft Foot Strike\t12\t0.110\n";
  out << "MARKER_NAMES";
  for (const auto& label : t.labels) out << '\t' << label;
  out << "\nTRAJECTORY_TYPES";
  for (Eigen::Index m = 0; m < n; ++m) out << "\tMeasured";
  out << "\n";
  if (layout.frameAndTime && layout.columnHeader) {
    out << "Frame\tTime";
    for (const auto& label : t.labels) out << '\t' << label << " X\t" << label << " Y\t" << label << " Z";
    out << "\t\n";
  }
  for (Eigen::Index r = 0; r < t.positionsMm.rows(); ++r) {
    if (layout.frameAndTime) out << r + t.firstFrame << '\t' << static_cast<double>(r) / t.rateHz << '\t';
    for (Eigen::Index c = 0; c < 3 * n; ++c) {
      const double v = t.positionsMm(r, c);
      if (std::isfinite(v)) out << v;
      else if (layout.zerosForGaps) out << "0.000";
      out << '\t';
    }
    out << "\n";
  }
  return out.str();
}

}  // namespace ew::test
