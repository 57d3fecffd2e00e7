#pragma once
// Vicon Nexus's CSV export ("Export ASCII": File > Export > CSV), the text form most gait
// laboratories keep next to their C3D files. The file is made of sections, each:
//   Trajectories                      <- the section's name (also Devices, Model Outputs, …)
//   100                               <- its rate (Hz)
//   ,,Subject:LASI,,,Subject:RASI,,,  <- a name at the first column of each quantity
//   Frame,Sub Frame,X,Y,Z,X,Y,Z       <- the components
//   ,,mm,mm,mm,mm,mm,mm               <- their units
//   1,0,123.4,…                       <- one row a frame, an empty cell where a marker is gone
// and a blank line before the next section. Only the Trajectories section is read (the
// markers, which the marker-set tables map to the 15 joints like a C3D's); a marker's X, Y and
// Z are found by the components row, so exports with velocities or accelerations beside them
// read too. Nexus's ".txt" export is the same with tabs: a tab-separated file reads the same.

#include <string>
#include <string_view>

#include "core/common/trial.h"
#include "core/io/load_trial.h"

namespace ew {

// True when the text's first non-blank line names a Nexus section (Trajectories, Devices,
// Model Outputs, Joints, Segments, Events). The Trajectories section may come after megabytes of
// force-plate samples, so it is looked for when the file is read, not here.
bool looksLikeNexusCsv(std::string_view text);

RawTrial parseNexusCsv(std::string_view text, const std::string& name, const LoadOptions& options = {});

}  // namespace ew
