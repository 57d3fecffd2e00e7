#include "core/eigenwalker/model_file.h"

#include <cmath>
#include <cstdint>
#include <fstream>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>

#include "core/common/errors.h"
#include "core/eigenwalker/fourier.h"
#include "core/io/atomic_write.h"
#include "core/io/binary_arrays.h"

namespace ew {
namespace {

using nlohmann::json;

constexpr std::string_view kMagic = "EIGENWALKER-MODEL";
// A stored walker speed above this is no walk (the fastest race walkers manage 4.5 m/s).
constexpr double kMaxWalkerSpeedMps = 10.0;

// [SECTION] Arrays

// The model's arrays in file order.
std::vector<std::pair<std::string, const Eigen::MatrixXd*>> arraysOf(const EigenwalkerModel& m,
                                                                     std::vector<Eigen::MatrixXd>& tmp) {
  tmp = {m.mean, m.eigenwalkers, m.eigenvalues, m.spectrum, m.coefficients, m.omegasRadS};
  return {{"mean", &tmp[0]},     {"eigenwalkers", &tmp[1]}, {"eigenvalues", &tmp[2]},
          {"spectrum", &tmp[3]}, {"coefficients", &tmp[4]}, {"omegas_rad_s", &tmp[5]}};
}

// [SECTION] Reading helpers

// `file` names the model in errors: the path given to loadModel, or parseModel's name.
[[noreturn]] void malformed(const std::string& file, const std::string& position,
                            const std::string& problem) {
  throwMalformed(file, position, problem);
}

// [SECTION] σ² optimum (optional: files written before it was stored lack the key)

json sigma2Json(const Sigma2Optimum& o) {
  return {{"sigma2_mm2", o.sigma2Mm2}, {"mean_abs_error_mm2", o.meanAbsErrorMm2},
          {"grid_mm2", o.gridMm2},     {"angles_deg", o.anglesDeg},
          {"criterion", o.criterion},  {"at_grid_edge", o.atGridEdge}};
}

std::vector<double> numberList(const json& o, const char* key, const std::string& file) {
  if (!o.contains(key) || !o[key].is_array())
    malformed(file, "line 2", std::string("sigma2_optimum has no list '") + key + "'");
  std::vector<double> out;
  for (const auto& v : o[key]) {
    if (!v.is_number() || !std::isfinite(v.get<double>()))
      malformed(file, "line 2", std::string("sigma2_optimum '") + key + "' holds a non-number");
    out.push_back(v.get<double>());
  }
  return out;
}

std::optional<Sigma2Optimum> sigma2FromJson(const json& meta, const std::string& file) {
  if (!meta.contains("sigma2_optimum")) return std::nullopt;
  const json& o = meta["sigma2_optimum"];
  const auto number = [&](const char* key) {
    if (!o.is_object() || !o.contains(key) || !o[key].is_number() ||
        !std::isfinite(o[key].get<double>()))
      malformed(file, "line 2", std::string("sigma2_optimum has no finite number '") + key + "'");
    return o[key].get<double>();
  };
  Sigma2Optimum s;
  s.sigma2Mm2 = number("sigma2_mm2");
  if (!(s.sigma2Mm2 > 0.0))
    malformed(file, "line 2",
              "sigma2_optimum: sigma2_mm2 must be > 0, got " + std::to_string(s.sigma2Mm2));
  s.meanAbsErrorMm2 = number("mean_abs_error_mm2");
  s.gridMm2 = numberList(o, "grid_mm2", file);
  s.anglesDeg = numberList(o, "angles_deg", file);
  if (!o.contains("criterion") || !o["criterion"].is_string() || !o.contains("at_grid_edge") ||
      !o["at_grid_edge"].is_boolean())
    malformed(file, "line 2",
              "sigma2_optimum lacks the text 'criterion' or the flag 'at_grid_edge'");
  s.criterion = o["criterion"].get<std::string>();
  s.atGridEdge = o["at_grid_edge"].get<bool>();
  return s;
}

// [SECTION] Walkers' speeds (optional: files written before they were stored lack the key)

json speedsJson(const std::vector<std::optional<double>>& speeds) {
  json out = json::array();
  for (const auto& v : speeds) out.push_back(v ? json(*v) : json(nullptr));
  return out;
}

bool plausibleSpeed(double v) { return std::isfinite(v) && v > 0.0 && v < kMaxWalkerSpeedMps; }

std::vector<std::optional<double>> speedsFromJson(const json& meta, long long walkers, const std::string& file) {
  if (!meta.contains("speeds_mps")) return {};
  const json& list = meta["speeds_mps"];
  if (!list.is_array() || static_cast<long long>(list.size()) != walkers)
    malformed(file, "line 2", "speeds_mps must list " + std::to_string(walkers) + " speeds (m/s or null)");
  std::vector<std::optional<double>> out;
  for (const auto& v : list) {
    if (v.is_null()) {
      out.emplace_back();
      continue;
    }
    if (!v.is_number() || !plausibleSpeed(v.get<double>()))
      malformed(file, "line 2", "speeds_mps holds " + v.dump() + " (a speed in m/s, > 0 and < " +
                                    std::to_string(static_cast<int>(kMaxWalkerSpeedMps)) + ", or null)");
    out.emplace_back(v.get<double>());
  }
  return out;
}

// The shapes each array must have, from the declared sizes.
void checkShapes(const std::vector<ArraySpec>& arrays, long long dims, long long walkers,
                 long long components, long long spectrum, const std::string& file) {
  const auto spec = [](const char* name, long long rows, long long cols) {
    return ArraySpec{name, static_cast<Eigen::Index>(rows), static_cast<Eigen::Index>(cols), 0};
  };
  checkArrayShapes(arrays,
                   {spec("mean", dims, 1), spec("eigenwalkers", dims, components),
                    spec("eigenvalues", components, 1), spec("spectrum", spectrum, 1),
                    spec("coefficients", components, walkers), spec("omegas_rad_s", walkers, 1)},
                   "metadata", file);
}

std::string readAll(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw Error(ErrorKind::Io, file.string(), "", "cannot open model file");
  std::ostringstream buffer;
  buffer << in.rdbuf();
  if (in.bad()) throw Error(ErrorKind::Io, file.string(), "", "read failed");
  return std::move(buffer).str();
}

// [SECTION] Values

// A checksum only proves the bytes are the ones written: the values must also be usable.
// Every array finite; eigenvalues and spectrum ≥ 0 (1/λ is the MAP prior); ω > 0.
void checkValues(const Eigen::MatrixXd& m, const std::string& name, size_t offset,
                 const std::string& file) {
  const bool nonNegative = name == "eigenvalues" || name == "spectrum";
  const bool positive = name == "omegas_rad_s";
  for (Eigen::Index i = 0; i < m.size(); ++i) {
    const double v = m.data()[i];
    if (std::isfinite(v) && !(nonNegative && v < 0.0) && !(positive && v <= 0.0)) continue;
    malformed(file, byteAt(offset + static_cast<size_t>(i) * 8),
              "model file: array '" + name + "' holds " + std::to_string(v) + " at index " +
                  std::to_string(i) +
                  (std::isfinite(v) ? (positive ? " (must be > 0)" : " (must be ≥ 0)")
                                    : " (must be finite)"));
  }
}

// What loadModel would refuse is not written: Error(BadArgument) naming the file.
void checkSavable(const EigenwalkerModel& m, const std::string& file) {
  const auto bad = [&](const std::string& problem) {
    throw Error(ErrorKind::BadArgument, file, "", "model file: cannot save: " + problem);
  };
  try {
    checkModel(m, "model file: cannot save");
  } catch (const Error& e) {
    throw Error(e.kind(), file, "", e.problem());  // the same problem, naming the file
  }
  const Eigen::Index r = m.walkerCount(), n = m.componentCount();
  if (r < 2 || n >= r || static_cast<Eigen::Index>(m.subjects.size()) != r ||
      m.omegasRadS.size() != r || m.coefficients.rows() != n || m.coefficients.cols() != r ||
      m.spectrum.size() < n || m.spectrum.size() >= r)
    bad("inconsistent sizes: " + std::to_string(r) + " walker ids, " +
        std::to_string(m.subjects.size()) + " subjects, " + std::to_string(m.omegasRadS.size()) +
        " frequencies, " + std::to_string(n) + " components, coefficients " +
        std::to_string(m.coefficients.rows()) + " x " + std::to_string(m.coefficients.cols()) +
        ", spectrum " + std::to_string(m.spectrum.size()));
  if (!m.coefficients.allFinite() || !m.spectrum.allFinite() || (m.spectrum.array() < 0.0).any() ||
      !m.omegasRadS.allFinite() || (m.omegasRadS.array() <= 0.0).any())
    bad("non-finite coefficients or spectrum, a negative spectrum value or a non-positive ω");
  if (!m.speedsMps.empty() && static_cast<Eigen::Index>(m.speedsMps.size()) != r)
    bad(std::to_string(m.speedsMps.size()) + " walker speeds for " + std::to_string(r) + " walkers");
  for (const auto& v : m.speedsMps)
    if (v && !plausibleSpeed(*v)) bad("a walker speed of " + std::to_string(*v) + " m/s");
  if (m.sigma2Optimum &&
      !(m.sigma2Optimum->sigma2Mm2 > 0.0 && std::isfinite(m.sigma2Optimum->sigma2Mm2) &&
        std::isfinite(m.sigma2Optimum->meanAbsErrorMm2)))
    bad("the stored σ² optimum must be positive and finite");
}

}  // namespace

// [SECTION] Save

void saveModel(const EigenwalkerModel& model, const std::filesystem::path& file) {
  checkSavable(model, file.string());
  std::vector<Eigen::MatrixXd> tmp;
  const auto arrays = arraysOf(model, tmp);
  json meta;
  meta["format"] = kMagic;
  meta["version"] = kModelFileVersion;
  meta["dims"] = model.mean.size();
  meta["walkers"] = model.walkerCount();
  meta["components"] = model.componentCount();
  meta["spectrum_size"] = model.spectrum.size();
  meta["byte_order"] = "little";
  meta["units"] = {{"mean", "mm"}, {"eigenwalkers", "1 (orthonormal)"}, {"eigenvalues", "mm^2"},
                   {"spectrum", "mm^2"}, {"coefficients", "mm"}, {"omegas_rad_s", "rad/s"}};
  meta["walker_ids"] = model.walkerIds;
  meta["subjects"] = model.subjects;
  meta["provenance"] = model.provenance;
  if (model.sigma2Optimum) meta["sigma2_optimum"] = sigma2Json(*model.sigma2Optimum);
  if (!model.speedsMps.empty()) meta["speeds_mps"] = speedsJson(model.speedsMps);
  std::string payload;
  json list = json::array();
  for (const auto& [name, m] : arrays) appendArray(list, payload, name, *m);
  meta["arrays"] = list;
  meta["payload_bytes"] = payload.size();
  const std::string header = headerText(kMagic, kModelFileVersion, meta.dump());
  writeFileAtomically(file, [&](std::ostream& out) {
    out.write(header.data(), static_cast<std::streamsize>(header.size()));
    out.write(payload.data(), static_cast<std::streamsize>(payload.size()));
  });
}

// [SECTION] Load

EigenwalkerModel loadModel(const std::filesystem::path& file) {
  return parseModel(readAll(file), file.string());
}

EigenwalkerModel parseModel(std::string_view bytes, const std::string& file) {
  const int version = parseHeaderVersion(bytes, kMagic, "eigenwalker model file", file);
  if (version != kModelFileVersion)
    throw Error(ErrorKind::Unsupported, file, "line 1",
                "model file version " + std::to_string(version) + " (this build reads version " +
                    std::to_string(kModelFileVersion) + ")");
  const HeaderMetadata header = readHeaderMetadata(bytes, file);
  const json meta = parseMetadataJson(header.line, file);
  const long long dims = metadataInteger(meta, "dims", "metadata", file);
  const long long walkers = metadataInteger(meta, "walkers", "metadata", file);
  const long long components = metadataInteger(meta, "components", "metadata", file);
  const long long spectrum = metadataInteger(meta, "spectrum_size", "metadata", file);
  if (dims != kFourierDims3) malformed(file, "line 2", "dims must be 225, got " + std::to_string(dims));
  if (walkers < 2 || components < 1 || components >= walkers || spectrum < components ||
      spectrum >= walkers)
    malformed(file, "line 2", "inconsistent sizes: walkers " + std::to_string(walkers) +
                                  ", components " + std::to_string(components) + ", spectrum " +
                                  std::to_string(spectrum));
  const auto specs = metadataArraySpecs(meta, "metadata", file);
  checkShapes(specs, dims, walkers, components, spectrum, file);

  EigenwalkerModel model;
  model.walkerIds = metadataStrings(meta, "walker_ids", "metadata", file);
  model.subjects = metadataStrings(meta, "subjects", "metadata", file);
  model.provenance = metadataStrings(meta, "provenance", "metadata", file);
  model.sigma2Optimum = sigma2FromJson(meta, file);
  model.speedsMps = speedsFromJson(meta, walkers, file);
  if (static_cast<long long>(model.walkerIds.size()) != walkers ||
      static_cast<long long>(model.subjects.size()) != walkers)
    malformed(file, "line 2", "walker_ids and subjects must list " + std::to_string(walkers) + " walkers");

  size_t expectedBytes = 0;
  for (const auto& s : specs) expectedBytes += s.byteCount();
  checkPayloadSize(bytes, header.payloadStart, expectedBytes, file);

  std::vector<Eigen::MatrixXd> values;
  size_t offset = header.payloadStart;
  for (const auto& s : specs) {
    Eigen::MatrixXd m = readFloat64Array(bytes, offset, s, "array '" + s.name + "'", file);
    checkValues(m, s.name, offset, file);
    values.push_back(std::move(m));
    offset += s.byteCount();
  }
  model.mean = values[0];
  model.eigenwalkers = std::move(values[1]);
  model.eigenvalues = values[2];
  model.spectrum = values[3];
  model.coefficients = std::move(values[4]);
  model.omegasRadS = values[5];
  return model;
}

}  // namespace ew
