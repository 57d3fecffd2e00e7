#pragma once
// Whole-file reads with clear errors. Motion-capture files are small (KB to tens of MB),
// so readers parse from memory; a size cap stops a mistaken path to a huge file.

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace ew {

inline constexpr std::uintmax_t kMaxInputFileBytes = 1ull << 30;  // 1 GiB

// Throw Error(Io) naming the file when it is missing, a directory, unreadable or too big.
std::vector<std::uint8_t> readFileBytes(const std::filesystem::path& file);
std::string readFileText(const std::filesystem::path& file);

// What a sniffer looks at to tell a file's kind: its first 64 KiB at most ("" when it cannot
// be read). Never throws: a file that cannot be read is simply not of the kind.
inline constexpr std::size_t kSniffBytes = 64 * 1024;
std::string readFileStart(const std::filesystem::path& file, std::size_t bytes = kSniffBytes);

}  // namespace ew
