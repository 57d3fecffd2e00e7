#include "core/snippet/snippet_file.h"

#include <climits>
#include <cmath>
#include <nlohmann/json.hpp>

#include "core/common/errors.h"
#include "core/io/atomic_write.h"
#include "core/io/binary_arrays.h"
#include "core/io/file_bytes.h"

namespace ew {
namespace {

using nlohmann::json;

constexpr std::string_view kMagic = "EIGENWALKER-SNIPPET-PRIOR";
constexpr std::string_view kDescription = "eigenwalker snippet prior file";

// Bounds on what a file may declare, so that a hostile header cannot ask for a huge
// allocation: the snippet lengths and cluster counts SnippetPriorOptions allows.
constexpr long long kMaxFrames = 301;
constexpr long long kMaxDimension = kMaxFrames * kSnippetJointValues;  // 13,545
constexpr long long kMaxClusters = 256;

std::string clusterName(size_t j) { return "cluster " + std::to_string(j); }

// [SECTION] Saving helpers

// What the file cannot hold beyond checkSnippetPrior's rules ("" when nothing).
std::string fileProblem(const SnippetPrior& prior) {
  const long long d = prior.components.front().mean.size();
  if (prior.frames < 0 || prior.frames > kMaxFrames)
    return "frames must be 0…301, got " + std::to_string(prior.frames);
  if (d < 1 || d > kMaxDimension) return "dimension must be 1…13545, got " + std::to_string(d);
  if (static_cast<long long>(prior.components.size()) > kMaxClusters)
    return "at most 256 clusters, got " + std::to_string(prior.components.size());
  if (!(prior.rateHz > 0.0 && std::isfinite(prior.rateHz)))
    return "the rate must be positive and finite, got " + std::to_string(prior.rateHz);
  if (prior.trainingSnippets < 0 || prior.emIterations < 0)
    return "negative training snippet or EM iteration count";
  for (size_t j = 0; j < prior.components.size(); ++j) {
    const PpcaComponent& c = prior.components[j];
    if (c.basis.cols() > d) return clusterName(j) + ": more components than dimensions";
    if (c.members < 0) return clusterName(j) + ": negative member count";
  }
  return "";
}

// What loadSnippetPrior would refuse is not written: Error(BadArgument) naming the file.
void checkSavable(const SnippetPrior& prior, const std::string& file) {
  const std::string context = "snippet prior file: cannot save: ";
  try {
    checkSnippetPrior(prior);
  } catch (const Error& e) {
    throw Error(ErrorKind::BadArgument, file, "", context + e.problem());
  }
  const std::string problem = fileProblem(prior);
  if (!problem.empty()) throw Error(ErrorKind::BadArgument, file, "", context + problem);
}

json clusterJson(const PpcaComponent& c, std::string& payload) {
  json arrays = json::array();
  appendArray(arrays, payload, "mean", c.mean);
  appendArray(arrays, payload, "basis", c.basis);
  appendArray(arrays, payload, "variances", c.variances);
  return {{"weight", c.weight},
          {"members", c.members},
          {"noise_variance_mm2", c.noiseVariance},
          {"components", c.basis.cols()},
          {"arrays", arrays}};
}

// [SECTION] Loading helpers

// Integer `key` of `object` in [low, high], else Malformed at line 2.
long long boundedInteger(const json& object, const char* key, long long low, long long high,
                         std::string_view owner, const std::string& file) {
  const long long v = metadataInteger(object, key, owner, file);
  if (v < low || v > high)
    throwMalformed(file, "line 2",
                   std::string(owner) + ": '" + key + "' must be " + std::to_string(low) + "…" +
                       std::to_string(high) + ", got " + std::to_string(v));
  return v;
}

// A checksum only proves the bytes are the ones written: the values must also be finite.
void checkFinite(const Eigen::MatrixXd& m, const std::string& what, size_t offset,
                 const std::string& file) {
  for (Eigen::Index i = 0; i < m.size(); ++i) {
    if (std::isfinite(m.data()[i])) continue;
    throwMalformed(file, byteAt(offset + static_cast<size_t>(i) * 8),
                   "snippet prior file: " + what + " holds " + std::to_string(m.data()[i]) +
                       " at index " + std::to_string(i) + " (must be finite)");
  }
}

// One cluster's metadata: its scalars and the specs of its three arrays.
struct ClusterHeader {
  PpcaComponent scalars;  // weight, members, σ²; arrays empty
  std::vector<ArraySpec> arrays;
};

ClusterHeader clusterHeader(const json& c, size_t j, Eigen::Index d, const std::string& file) {
  const std::string owner = clusterName(j);
  if (!c.is_object()) throwMalformed(file, "line 2", owner + " is not a JSON object");
  ClusterHeader h;
  h.scalars.weight = metadataNumber(c, "weight", owner, file);
  h.scalars.members = static_cast<int>(boundedInteger(c, "members", 0, INT_MAX, owner, file));
  h.scalars.noiseVariance = metadataNumber(c, "noise_variance_mm2", owner, file);
  const auto q = static_cast<Eigen::Index>(boundedInteger(c, "components", 0, d, owner, file));
  h.arrays = metadataArraySpecs(c, owner, file);
  checkArrayShapes(h.arrays, {{"mean", d, 1, 0}, {"basis", d, q, 0}, {"variances", q, 1, 0}}, owner,
                   file);
  return h;
}

}  // namespace

// [SECTION] Save

void saveSnippetPrior(const SnippetPrior& prior, const std::filesystem::path& file) {
  checkSavable(prior, file.string());
  json meta;
  meta["format"] = kMagic;
  meta["version"] = kSnippetPriorFileVersion;
  meta["frames"] = prior.frames;
  meta["rate_hz"] = prior.rateHz;
  meta["dimension"] = prior.components.front().mean.size();
  meta["training_snippets"] = prior.trainingSnippets;
  meta["em_iterations"] = prior.emIterations;
  meta["subjects"] = prior.subjects;
  meta["byte_order"] = "little";
  meta["units"] = {{"mean", "mm"},
                   {"basis", "1 (orthonormal)"},
                   {"variances", "mm^2"},
                   {"noise_variance_mm2", "mm^2"}};
  std::string payload;
  json clusters = json::array();
  for (const PpcaComponent& c : prior.components) clusters.push_back(clusterJson(c, payload));
  meta["clusters"] = clusters;
  meta["payload_bytes"] = payload.size();
  std::string metaLine;
  try {
    metaLine = meta.dump();
  } catch (const json::exception& e) {  // a subject that is not valid UTF-8
    throw Error(ErrorKind::BadArgument, file.string(), "",
                std::string("snippet prior file: cannot save: ") + e.what());
  }
  const std::string header = headerText(kMagic, kSnippetPriorFileVersion, metaLine);
  writeFileAtomically(file, [&](std::ostream& out) {
    out.write(header.data(), static_cast<std::streamsize>(header.size()));
    out.write(payload.data(), static_cast<std::streamsize>(payload.size()));
  });
}

// [SECTION] Load

SnippetPrior loadSnippetPrior(const std::filesystem::path& file) {
  return parseSnippetPrior(readFileText(file), file.string());
}

SnippetPrior parseSnippetPrior(std::string_view bytes, const std::string& file) {
  const int version = parseHeaderVersion(bytes, kMagic, kDescription, file);
  if (version != kSnippetPriorFileVersion)
    throw Error(ErrorKind::Unsupported, file, "line 1",
                "snippet prior file version " + std::to_string(version) +
                    " (this build reads version " + std::to_string(kSnippetPriorFileVersion) + ")");
  const HeaderMetadata header = readHeaderMetadata(bytes, file);
  const json meta = parseMetadataJson(header.line, file);

  // Sizes first, each bounded, so the payload's size can be known before any allocation.
  SnippetPrior prior;
  prior.frames = static_cast<int>(boundedInteger(meta, "frames", 0, kMaxFrames, "metadata", file));
  prior.rateHz = metadataNumber(meta, "rate_hz", "metadata", file);
  if (!(prior.rateHz > 0.0))
    throwMalformed(file, "line 2",
                   "the rate must be positive, got " + std::to_string(prior.rateHz));
  const auto d = static_cast<Eigen::Index>(
      boundedInteger(meta, "dimension", 1, kMaxDimension, "metadata", file));
  if (prior.frames > 0 && d != prior.dimension())
    throwMalformed(file, "line 2",
                   "dimension " + std::to_string(d) +
                       " is not frames · 45 = " + std::to_string(prior.dimension()));
  prior.trainingSnippets =
      static_cast<int>(boundedInteger(meta, "training_snippets", 0, INT_MAX, "metadata", file));
  prior.emIterations =
      static_cast<int>(boundedInteger(meta, "em_iterations", 0, INT_MAX, "metadata", file));
  prior.subjects = metadataStrings(meta, "subjects", "metadata", file);
  if (!meta.contains("clusters") || !meta["clusters"].is_array() || meta["clusters"].empty() ||
      meta["clusters"].size() > static_cast<size_t>(kMaxClusters))
    throwMalformed(file, "line 2", "metadata must list 1…256 'clusters'");
  std::vector<ClusterHeader> clusters;
  size_t expectedBytes = 0;
  for (const json& c : meta["clusters"]) {
    clusters.push_back(clusterHeader(c, clusters.size(), d, file));
    for (const ArraySpec& s : clusters.back().arrays) expectedBytes += s.byteCount();
  }
  const long long declared = metadataInteger(meta, "payload_bytes", "metadata", file);
  if (declared < 0 || static_cast<size_t>(declared) != expectedBytes)
    throwMalformed(file, "line 2",
                   "payload_bytes says " + std::to_string(declared) +
                       ", the clusters' arrays take " + std::to_string(expectedBytes));
  checkPayloadSize(bytes, header.payloadStart, expectedBytes, file);

  size_t offset = header.payloadStart;
  for (size_t j = 0; j < clusters.size(); ++j) {
    std::vector<Eigen::MatrixXd> values;
    for (const ArraySpec& s : clusters[j].arrays) {
      const std::string what = clusterName(j) + " array '" + s.name + "'";
      values.push_back(readFloat64Array(bytes, offset, s, what, file));
      checkFinite(values.back(), what, offset, file);
      offset += s.byteCount();
    }
    PpcaComponent c = std::move(clusters[j].scalars);
    c.mean = values[0];
    c.basis = std::move(values[1]);
    c.variances = values[2];
    prior.components.push_back(std::move(c));
  }
  try {
    checkSnippetPrior(prior);
  } catch (const Error& e) {
    throwMalformed(file, "", "snippet prior: " + e.problem());
  }
  return prior;
}

}  // namespace ew
