#pragma once
// Eigenwalker model files (format: docs/MODEL_FORMAT.md):
//   line 1  "EIGENWALKER-MODEL 1"
//   line 2  one line of JSON metadata: sizes, walker ids, subjects, provenance, and for
//           each array its shape and FNV-1a 64 checksum
//   line 3  "fnv1a64 <hex>": checksum of line 2
//   then    the arrays as little-endian IEEE-754 float64, column-major, in metadata order
// Doubles are stored bit for bit, so load(save(m)) == m exactly.

#include <filesystem>
#include <string>
#include <string_view>

#include "core/eigenwalker/model.h"

namespace ew {

inline constexpr int kModelFileVersion = 1;

// Writes atomically (temporary file, then rename): the target is never half-written.
// Throws Error(Io) naming the file when it cannot be written, Error(BadArgument) naming it
// (nothing written) for a model loadModel would refuse: inconsistent sizes, fewer than 2
// walkers, N ≥ R, non-finite values, a negative eigenvalue or a non-positive ω.
void saveModel(const EigenwalkerModel& model, const std::filesystem::path& file);

// Throws Error(Io) if unreadable, Error(Malformed) naming the file and the line or byte
// for a wrong magic, bad metadata, inconsistent sizes, truncation, trailing bytes or a
// checksum mismatch, a non-finite value, a negative eigenvalue or a non-positive ω
// (naming the array and the byte), Error(Unsupported) for a newer version.
EigenwalkerModel loadModel(const std::filesystem::path& file);

// The same from the file's bytes already in memory (loadModel reads the file and calls
// this); `name` is the file named in errors. Never reads outside `bytes`.
EigenwalkerModel parseModel(std::string_view bytes, const std::string& name);

}  // namespace ew
