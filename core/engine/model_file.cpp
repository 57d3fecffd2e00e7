#include "core/engine/model_file.h"

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>

#include "core/common/errors.h"
#include "core/engine/fourier.h"
#include "core/io/atomic_write.h"

namespace ew {
namespace {

using nlohmann::json;

constexpr std::string_view kMagic = "EIGENWALKER-MODEL";

// [SECTION] Arrays and checksums

struct ArraySpec {
  std::string name;
  Eigen::Index rows = 0, cols = 0;
  std::uint64_t checksum = 0;
  Eigen::Index count() const { return rows * cols; }
};

std::uint64_t fnv1a64(const char* data, size_t size) {
  std::uint64_t h = 14695981039346656037ull;
  for (size_t i = 0; i < size; ++i) {
    h ^= static_cast<unsigned char>(data[i]);
    h *= 1099511628211ull;
  }
  return h;
}

std::string hex64(std::uint64_t v) {
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(v));
  return buf;
}

// Little-endian bytes of the values, whatever the host's byte order.
std::string encode(const double* values, Eigen::Index count) {
  std::string out(static_cast<size_t>(count) * 8, '\0');
  for (Eigen::Index i = 0; i < count; ++i) {
    const auto bits = std::bit_cast<std::uint64_t>(values[i]);
    for (int b = 0; b < 8; ++b)
      out[static_cast<size_t>(i) * 8 + static_cast<size_t>(b)] = static_cast<char>((bits >> (8 * b)) & 0xff);
  }
  return out;
}

void decode(const char* bytes, Eigen::Index count, double* values) {
  for (Eigen::Index i = 0; i < count; ++i) {
    std::uint64_t bits = 0;
    for (int b = 0; b < 8; ++b)
      bits |= static_cast<std::uint64_t>(static_cast<unsigned char>(bytes[i * 8 + b])) << (8 * b);
    values[i] = std::bit_cast<double>(bits);
  }
}

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

std::string byteAt(size_t offset) { return "byte " + std::to_string(offset); }

std::vector<std::string> stringList(const json& meta, const char* key,
                                    const std::string& file) {
  if (!meta.contains(key) || !meta[key].is_array())
    malformed(file, "line 2", std::string("metadata has no list '") + key + "'");
  std::vector<std::string> out;
  for (const auto& v : meta[key]) {
    if (!v.is_string()) malformed(file, "line 2", std::string("'") + key + "' holds a non-string");
    out.push_back(v.get<std::string>());
  }
  return out;
}

long long integer(const json& meta, const char* key, const std::string& file) {
  if (!meta.contains(key) || !meta[key].is_number_integer())
    malformed(file, "line 2", std::string("metadata has no integer '") + key + "'");
  return meta[key].get<long long>();
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

// The shapes each array must have, from the declared sizes.
void checkShapes(const std::vector<ArraySpec>& arrays, long long dims, long long walkers,
                 long long components, long long spectrum, const std::string& file) {
  const std::vector<std::tuple<std::string, long long, long long>> expected = {
      {"mean", dims, 1},           {"eigenwalkers", dims, components},
      {"eigenvalues", components, 1}, {"spectrum", spectrum, 1},
      {"coefficients", components, walkers}, {"omegas_rad_s", walkers, 1}};
  if (arrays.size() != expected.size())
    malformed(file, "line 2", "expected 6 arrays, metadata lists " + std::to_string(arrays.size()));
  for (size_t i = 0; i < arrays.size(); ++i) {
    const auto& [name, rows, cols] = expected[i];
    if (arrays[i].name != name || arrays[i].rows != rows || arrays[i].cols != cols) {
      malformed(file, "line 2",
                "array " + std::to_string(i) + " should be '" + name + "' " + std::to_string(rows) +
                    " x " + std::to_string(cols) + ", metadata says '" + arrays[i].name + "' " +
                    std::to_string(arrays[i].rows) + " x " + std::to_string(arrays[i].cols));
    }
  }
}

std::vector<ArraySpec> arraySpecs(const json& meta, const std::string& file) {
  if (!meta.contains("arrays") || !meta["arrays"].is_array())
    malformed(file, "line 2", "metadata has no 'arrays' list");
  std::vector<ArraySpec> specs;
  for (const auto& a : meta["arrays"]) {
    if (!a.is_object() || !a.contains("name") || !a["name"].is_string() ||
        !a.contains("rows") || !a["rows"].is_number_integer() || !a.contains("cols") ||
        !a["cols"].is_number_integer() || !a.contains("fnv1a64") || !a["fnv1a64"].is_string())
      malformed(file, "line 2", "an 'arrays' entry lacks name, rows, cols or fnv1a64");
    ArraySpec s;
    s.name = a["name"].get<std::string>();
    s.rows = a["rows"].get<Eigen::Index>();
    s.cols = a["cols"].get<Eigen::Index>();
    const auto hex = a["fnv1a64"].get<std::string>();
    char* end = nullptr;
    s.checksum = std::strtoull(hex.c_str(), &end, 16);
    if (hex.size() != 16 || end != hex.c_str() + hex.size())
      malformed(file, "line 2", "bad checksum text for array '" + s.name + "'");
    if (s.rows < 0 || s.cols < 0 || s.rows > 1'000'000 || s.cols > 1'000'000)
      malformed(file, "line 2", "absurd size for array '" + s.name + "'");
    specs.push_back(s);
  }
  return specs;
}

std::string readAll(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw Error(ErrorKind::Io, file.string(), "", "cannot open model file");
  std::ostringstream buffer;
  buffer << in.rdbuf();
  if (in.bad()) throw Error(ErrorKind::Io, file.string(), "", "read failed");
  return std::move(buffer).str();
}

// Returns the end of the line starting at `begin` (the '\n'), or throws.
size_t lineEnd(std::string_view bytes, size_t begin, int line, const std::string& file) {
  const size_t end = bytes.find('\n', begin);
  if (end == std::string::npos)
    malformed(file, "line " + std::to_string(line),
              "truncated: the header line has no end (" + std::to_string(bytes.size()) + " bytes in file)");
  return end;
}

int parseVersion(std::string_view first, const std::string& file) {
  const std::string prefix = std::string(kMagic) + " ";
  if (first.rfind(prefix, 0) != 0)
    malformed(file, "byte 0", "not an eigenwalker model file (expected \"" + std::string(kMagic) + " <version>\")");
  const std::string v(first.substr(prefix.size()));
  if (v.empty() || v.find_first_not_of("0123456789") != std::string::npos || v.size() > 6)
    malformed(file, "line 1", "bad version \"" + v + "\"");
  return std::stoi(v);
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
  std::string payload;
  json list = json::array();
  for (const auto& [name, m] : arrays) {
    const std::string bytes = encode(m->data(), m->size());
    list.push_back({{"name", name}, {"rows", m->rows()}, {"cols", m->cols()},
                    {"fnv1a64", hex64(fnv1a64(bytes.data(), bytes.size()))}});
    payload += bytes;
  }
  meta["arrays"] = list;
  meta["payload_bytes"] = payload.size();
  const std::string metaLine = meta.dump();
  const std::string header = std::string(kMagic) + " " + std::to_string(kModelFileVersion) + "\n" +
                             metaLine + "\n" + "fnv1a64 " +
                             hex64(fnv1a64(metaLine.data(), metaLine.size())) + "\n";
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
  const size_t end1 = lineEnd(bytes, 0, 1, file);
  const int version = parseVersion(bytes.substr(0, end1), file);
  if (version != kModelFileVersion)
    throw Error(ErrorKind::Unsupported, file, "line 1",
                "model file version " + std::to_string(version) + " (this build reads version " +
                    std::to_string(kModelFileVersion) + ")");
  const size_t end2 = lineEnd(bytes, end1 + 1, 2, file);
  const size_t end3 = lineEnd(bytes, end2 + 1, 3, file);
  const std::string_view sumLine = bytes.substr(end2 + 1, end3 - end2 - 1);
  if (sumLine.rfind("fnv1a64 ", 0) != 0 || sumLine.size() != 8 + 16)
    malformed(file, "line 3", "expected \"fnv1a64 <16 hex digits>\"");
  if (sumLine.substr(8) != hex64(fnv1a64(bytes.data() + end1 + 1, end2 - end1 - 1)))
    malformed(file, "line 2", "metadata checksum mismatch: the file is damaged");
  json meta;
  try {
    meta = json::parse(bytes.begin() + static_cast<std::ptrdiff_t>(end1 + 1),
                       bytes.begin() + static_cast<std::ptrdiff_t>(end2));
  } catch (const json::exception& e) {
    malformed(file, "line 2", std::string("bad metadata JSON: ") + e.what());
  }
  if (!meta.is_object()) malformed(file, "line 2", "metadata is not a JSON object");
  const long long dims = integer(meta, "dims", file), walkers = integer(meta, "walkers", file);
  const long long components = integer(meta, "components", file);
  const long long spectrum = integer(meta, "spectrum_size", file);
  if (dims != kFourierDims3) malformed(file, "line 2", "dims must be 225, got " + std::to_string(dims));
  if (walkers < 2 || components < 1 || components >= walkers || spectrum < components ||
      spectrum >= walkers)
    malformed(file, "line 2", "inconsistent sizes: walkers " + std::to_string(walkers) +
                                  ", components " + std::to_string(components) + ", spectrum " +
                                  std::to_string(spectrum));
  const auto specs = arraySpecs(meta, file);
  checkShapes(specs, dims, walkers, components, spectrum, file);

  EigenwalkerModel model;
  model.walkerIds = stringList(meta, "walker_ids", file);
  model.subjects = stringList(meta, "subjects", file);
  model.provenance = stringList(meta, "provenance", file);
  model.sigma2Optimum = sigma2FromJson(meta, file);
  if (static_cast<long long>(model.walkerIds.size()) != walkers ||
      static_cast<long long>(model.subjects.size()) != walkers)
    malformed(file, "line 2", "walker_ids and subjects must list " + std::to_string(walkers) + " walkers");

  size_t expectedBytes = 0;
  for (const auto& s : specs) expectedBytes += static_cast<size_t>(s.count()) * 8;
  const size_t payloadStart = end3 + 1, available = bytes.size() - payloadStart;
  if (available < expectedBytes)
    malformed(file, byteAt(bytes.size()),
              "truncated: payload has " + std::to_string(available) + " of " +
                  std::to_string(expectedBytes) + " bytes");
  if (available > expectedBytes)
    malformed(file, byteAt(payloadStart + expectedBytes),
              std::to_string(available - expectedBytes) + " unexpected bytes after the payload");

  std::vector<Eigen::MatrixXd> values;
  size_t offset = payloadStart;
  for (const auto& s : specs) {
    const size_t size = static_cast<size_t>(s.count()) * 8;
    if (fnv1a64(bytes.data() + offset, size) != s.checksum)
      malformed(file, "bytes " + std::to_string(offset) + "-" + std::to_string(offset + size),
                "checksum mismatch in array '" + s.name + "': the file is damaged");
    Eigen::MatrixXd m(s.rows, s.cols);
    decode(bytes.data() + offset, s.count(), m.data());
    checkValues(m, s.name, offset, file);
    values.push_back(std::move(m));
    offset += size;
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
