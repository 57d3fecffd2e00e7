#pragma once
// Snippet prior files (format: docs/SNIPPET_FORMAT.md), shaped like the eigenwalker model
// file (docs/MODEL_FORMAT.md, core/io/binary_arrays.h):
//   line 1  "EIGENWALKER-SNIPPET-PRIOR 1"
//   line 2  one line of JSON metadata: frames, rate, dimension D, training snippets, EM
//           iterations, subjects, and per cluster its weight, members, σ², q and each
//           array's shape and FNV-1a 64 checksum
//   line 3  "fnv1a64 <hex>": checksum of line 2
//   then    per cluster, little-endian IEEE-754 float64, column-major: mean (D),
//           basis (D × q), variances (q)
// Doubles are stored bit for bit, so load(save(p)) == p exactly.

#include <filesystem>
#include <string>
#include <string_view>

#include "core/snippet/snippet_prior.h"

namespace ew {

inline constexpr int kSnippetPriorFileVersion = 1;

// Writes atomically (temporary file, then rename): the target is never half-written.
// Throws Error(Io) naming the file when it cannot be written, Error(BadArgument) naming it
// (nothing written) for a prior loadSnippetPrior would refuse: one checkSnippetPrior
// rejects, frames outside 0…301 (0: not S·45 values), D outside 1…301·45, more than 256
// clusters, q > D, a rate that is not positive and finite, a negative count.
void saveSnippetPrior(const SnippetPrior& prior, const std::filesystem::path& file);

// Throws Error(Io) if unreadable, Error(Malformed) naming the file and the line or byte for
// a wrong magic, bad metadata, inconsistent or absurd sizes, truncation, trailing bytes, a
// checksum mismatch or a non-finite value, and for a prior checkSnippetPrior rejects;
// Error(Unsupported) for another version.
SnippetPrior loadSnippetPrior(const std::filesystem::path& file);

// The same from the file's bytes already in memory (loadSnippetPrior reads the file and
// calls this); `name` is the file named in errors. Never reads outside `bytes`, and checks
// the payload's size against the bytes there before allocating any array.
SnippetPrior parseSnippetPrior(std::string_view bytes, const std::string& name);

}  // namespace ew
