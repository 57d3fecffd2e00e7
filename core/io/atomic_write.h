#pragma once
// Output files are never left half-written: write to a temporary file in the same folder,
// flush, then rename over the target (atomic on POSIX file systems).

#include <filesystem>
#include <functional>
#include <ostream>

namespace ew {

// Calls `write` with a stream to a temporary file; on success renames it to `target`.
// On any failure (exception in `write`, stream error) the temporary file is removed,
// `target` is untouched, and Error(Io) is thrown naming `target`.
void writeFileAtomically(const std::filesystem::path& target,
                         const std::function<void(std::ostream&)>& write);

}  // namespace ew
