#pragma once
// Helpers for the line-oriented text formats (our CSV, TRC, manifests): split lines
// (LF or CRLF), split fields, parse numbers strictly, with positions for errors.

#include <string>
#include <string_view>
#include <vector>

namespace ew {

struct TextLine {
  int number = 0;         // 1-based line number in the file
  std::string_view text;  // without the line ending
};

// Splits on LF, dropping a trailing CR; keeps empty lines (TRC has meaningful blanks).
std::vector<TextLine> splitLines(std::string_view text);

// Splits on a single delimiter; fields are trimmed of spaces (and quotes for CSV).
std::vector<std::string_view> splitFields(std::string_view line, char delimiter);

// Splits on runs of tabs/spaces (TRC headers); empty fields are kept only for tabs.
std::vector<std::string_view> splitTabs(std::string_view line);

// Splits on runs of spaces, tabs and other blanks except line breaks (BVH, ASF/AMC).
std::vector<std::string_view> splitWords(std::string_view line);

// A word as an error message shows it: quoted, at most 40 characters, control bytes as '?'
// (a hostile file cannot put terminal escapes into the message).
std::string shownWord(std::string_view s);

// Finite numbers only, an optional leading '+': "nan", "inf", overflow and trailing junk are
// all refused.
bool parseFinite(std::string_view s, double& out);

std::string_view trim(std::string_view s);

// The text without a UTF-8 byte order mark at its start (a spreadsheet's or Windows tool's).
std::string_view withoutBom(std::string_view s);
std::string toLower(std::string_view s);

// Parses a finite or NaN double; an empty field is NaN when allowEmpty. Returns false on
// anything else (garbage, trailing characters, inf).
bool parseDouble(std::string_view field, double& out, bool allowEmpty);

// "line 12, column 3"
std::string linePosition(int line, int column = 0);

// A row's frame number (the first column of Nexus's and QTM's exports): a whole number, one
// more than the row before's when there is one. Throws Error(Malformed) naming the file and line.
long consecutiveFrameNumber(std::string_view field, const long* previous, const std::string& file, int line);

}  // namespace ew
