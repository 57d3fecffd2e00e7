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

// A folder path as users type it, without trailing separators ("results/" → "results",
// "a//" → "a"), lexically normalised, so its filename() names the folder: the atomic
// writers put a temporary sibling beside it and rename it into place. "/" stays "/".
std::filesystem::path folderPathWithoutTrailingSeparator(const std::filesystem::path& path);

}  // namespace ew
