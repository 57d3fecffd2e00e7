#pragma once
// Order statistics over a copy of the values (NaN for none): the project's one median.

#include <vector>

namespace ew {

// The upper median (the element at index n/2 once sorted; for an even count the larger of
// the two middle values), NaN for no values.
double median(std::vector<double> values);

// The p-quantile (0 ≤ p ≤ 1), linear between the order statistics; NaN for no values.
double percentile(std::vector<double> values, double p);

}  // namespace ew
