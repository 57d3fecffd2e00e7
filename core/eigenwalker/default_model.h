#pragma once
// The default model of real walkers: built from the 24 walkers of the shared data
// (../shared/data/walkers.csv: 18 Schreiber & Moissenet 2019 subjects, 6 CMU subjects),
// shipped as assets/models/real-walkers.ewm and compiled into ew_core. It is what a
// user's own trial is reconstructed with when no model is given (the CLI's `reconstruct`,
// the viewer with no population loaded). How to rebuild it, what it was built from and
// the data's citations: assets/README.md.

#include <string>

#include "core/eigenwalker/model.h"

namespace ew {

// The embedded asset's name ("models/real-walkers.ewm").
inline constexpr const char* kDefaultRealModelAsset = "models/real-walkers.ewm";

// The default model, parsed from the embedded asset once (thread-safe) and kept for the
// program's life. Throws ew::Error naming "assets/models/real-walkers.ewm" when the asset
// is missing (Io) or damaged (Malformed, from parseModel); a later call tries again.
const EigenwalkerModel& defaultRealModel();

// What the default model is, for headers and reports: "24 real walkers (default)", the
// count read from the model (so a rebuilt model names itself correctly).
std::string defaultRealModelName();

}  // namespace ew
