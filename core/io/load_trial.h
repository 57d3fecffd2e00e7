#pragma once
// One entry point for every motion-capture format. Chooses the reader by extension and
// checks the content agrees (a .c3d that is really text is a clear error, not garbage).

#include <filesystem>
#include <optional>
#include <string>

#include "core/common/trial.h"

namespace ew {

struct LoadOptions {
  // Frame rate to use instead of the file's (AMC stores none: 120 Hz CMU default).
  std::optional<double> rateHzOverride;
  // Length unit to use instead of the file's ("mm", "cm", "m", "in"): a wrong unit is the
  // commonest mocap mistake, so the user can always override it.
  std::optional<std::string> unitsOverride;
  // A user joint mapping file (core/mapping/mapping_file.h) used instead of the marker-set
  // tables for marker files (C3D, TRC).
  std::optional<std::filesystem::path> mappingFile;
};

enum class FileFormat { C3d, Bvh, AsfAmc, Trc, Csv, Tsv };

// Format from the extension (.c3d .bvh .amc .asf .trc .csv .tsv, case-insensitive).
// Throws Error(Unsupported) naming the file for anything else.
FileFormat formatFromExtension(const std::filesystem::path& file);
std::string formatName(FileFormat format);

// Reads the file into points in the file's axes, in millimetres.
RawTrial readRawTrial(const std::filesystem::path& file, const LoadOptions& options = {});

// A .csv's text: a Vicon Nexus export (core/io/nexus_csv.h) when its first line names a Nexus
// section, else the 15-joint CSV (core/io/joint_csv.h).
RawTrial parseCsvTrial(std::string_view text, const std::string& name, const LoadOptions& options = {});

// The 15 joints of a raw trial: through options.mappingFile when given (marker files
// only; Error(BadArgument) for a skeleton or joint file), else toJointTrial. A body of no
// human size for the unit read is warned about (core/gait/body_size.h).
JointTrial mapRawTrial(const RawTrial& raw, const LoadOptions& options);

// Factor that converts a length in `unit` to millimetres; throws Error(BadArgument)
// for an unknown unit. Accepts mm, cm, m, in/inch/inches (case-insensitive).
double unitToMm(const std::string& unit, const std::string& file);

}  // namespace ew
