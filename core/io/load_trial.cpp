#include "core/io/load_trial.h"

#include <algorithm>

#include "core/common/errors.h"
#include "core/gait/body_size.h"
#include "core/io/asf_amc_reader.h"
#include "core/io/bvh_reader.h"
#include "core/io/c3d_reader.h"
#include "core/io/file_bytes.h"
#include "core/io/joint_csv.h"
#include "core/io/nexus_csv.h"
#include "core/io/qtm_tsv.h"
#include "core/io/text_table.h"
#include "core/io/trc_reader.h"
#include "core/mapping/joint_mapping.h"
#include "core/mapping/mapping_file.h"

namespace ew {

FileFormat formatFromExtension(const std::filesystem::path& file) {
  const auto ext = toLower(file.extension().string());
  if (ext == ".c3d") return FileFormat::C3d;
  if (ext == ".bvh") return FileFormat::Bvh;
  if (ext == ".amc") return FileFormat::AsfAmc;
  if (ext == ".trc") return FileFormat::Trc;
  if (ext == ".csv") return FileFormat::Csv;
  if (ext == ".tsv") return FileFormat::Tsv;
  if (ext == ".asf") {
    throw Error(ErrorKind::Unsupported, file.string(), "",
                "an .asf file is a skeleton only: open the .amc motion file beside it");
  }
  throw Error(ErrorKind::Unsupported, file.string(), "",
              "unknown file type '" + ext + "' (expected .c3d, .bvh, .amc, .trc, .csv or .tsv)");
}

std::string formatName(FileFormat format) {
  switch (format) {
    case FileFormat::C3d: return "C3D";
    case FileFormat::Bvh: return "BVH";
    case FileFormat::AsfAmc: return "ASF/AMC";
    case FileFormat::Trc: return "TRC";
    case FileFormat::Csv: return "CSV";
    case FileFormat::Tsv: return "QTM TSV";
  }
  return "unknown";
}

double unitToMm(const std::string& unit, const std::string& file) {
  const auto u = toLower(trim(unit));
  if (u == "mm" || u == "millimeters" || u == "millimetres") return 1.0;
  if (u == "cm" || u == "centimeters" || u == "centimetres") return 10.0;
  if (u == "m" || u == "meters" || u == "metres") return 1000.0;
  if (u == "in" || u == "inch" || u == "inches") return 25.4;
  // CMU's ASF length unit: `:units length 0.45` means 1 unit = 1/0.45 inch.
  if (u == "cmu") return 25.4 / 0.45;
  throw Error(ErrorKind::BadArgument, file, "",
              "unknown length unit '" + unit + "' (use mm, cm, m, in or cmu)");
}

RawTrial readRawTrial(const std::filesystem::path& file, const LoadOptions& options) {
  switch (formatFromExtension(file)) {
    case FileFormat::C3d: return readC3d(file, options);
    case FileFormat::Bvh: return readBvh(file, options);
    case FileFormat::AsfAmc: return readAsfAmc(file, options);
    case FileFormat::Trc: return readTrc(file, options);
    case FileFormat::Csv: return parseCsvTrial(readFileText(file), file.string(), options);
    case FileFormat::Tsv: return readQtmTsv(file, options);
  }
  throw Error(ErrorKind::Unsupported, file.string(), "", "unknown format");
}

RawTrial parseCsvTrial(std::string_view text, const std::string& name, const LoadOptions& options) {
  return looksLikeNexusCsv(text) ? parseNexusCsv(text, name, options) : parseJointCsv(text, name, options);
}

namespace {

JointTrial mapRawPoints(const RawTrial& raw, const LoadOptions& options) {
  if (!options.mappingFile) return toJointTrial(raw);
  const std::string mapping = options.mappingFile->string();
  if (raw.kind != PointKind::Markers) {
    throw Error(ErrorKind::BadArgument, mapping, "",
                "a joint mapping applies to marker files (C3D, TRC), not to " + raw.format +
                    " " + raw.file);
  }
  return applyJointMapping(raw, readJointMappingFile(*options.mappingFile), mapping);
}

}  // namespace

JointTrial mapRawTrial(const RawTrial& raw, const LoadOptions& options) {
  JointTrial t = mapRawPoints(raw, options);
  // A wrong --units scales everything after it; said here, so it shows even when the trial
  // then fails as walking (info lists the joints' warnings beside the error).
  if (auto size = bodySizeWarning(t)) t.warnings.push_back(*size);
  return t;
}

}  // namespace ew
