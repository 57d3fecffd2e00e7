#pragma once
// Typed errors. Every parser and every data check throws one of these, carrying the
// file and a position ("byte 512", "line 40", "frame 12", "parameter POINT:SCALE"),
// so the CLI and the viewer can say exactly what is wrong and where.

#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace ew {

enum class ErrorKind {
  Io,               // cannot open / read the file
  Malformed,        // the bytes or text break the format (truncated, bad number, absurd count)
  Unsupported,      // valid but not something we read (e.g. several BVH roots)
  UnknownMarkerSet, // labels do not match any marker set or skeleton we know
  BadData,          // readable, but unusable: NaNs, gaps, too short, not walking, too few subjects
  BadArgument,      // a caller or user passed something invalid
};

std::string_view errorKindName(ErrorKind kind);

class Error : public std::runtime_error {
 public:
  Error(ErrorKind kind, std::string file, std::string position, std::string problem);

  ErrorKind kind() const { return kind_; }
  const std::string& file() const { return file_; }
  const std::string& position() const { return position_; }  // may be empty
  const std::string& problem() const { return problem_; }

 private:
  ErrorKind kind_;
  std::string file_, position_, problem_;
};

// Names for a message, at most `limit` of them, then how many were left out:
// "a, b, c, … (12 more)".
std::string listForMessage(const std::vector<std::string>& items, std::size_t limit,
                           std::string_view separator = ", ");

// Convenience constructors; message reads "FILE: POSITION: PROBLEM".
[[noreturn]] void throwMalformed(const std::string& file, const std::string& position,
                                 const std::string& problem);
[[noreturn]] void throwBadData(const std::string& file, const std::string& position,
                               const std::string& problem);

}  // namespace ew
