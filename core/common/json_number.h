#pragma once
// A number for a JSON report: null where it is not finite (JSON has no NaN or infinity, and
// a measure the program could not take is said as null).

#include <cmath>
#include <nlohmann/json.hpp>

namespace ew {

inline nlohmann::json finiteOrNull(double x) { return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr); }

}  // namespace ew
