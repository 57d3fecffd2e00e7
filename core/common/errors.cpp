#include "core/common/errors.h"

namespace ew {
namespace {

std::string composeMessage(const std::string& file, const std::string& position,
                           const std::string& problem) {
  std::string msg = file.empty() ? std::string("<input>") : file;
  if (!position.empty()) msg += ": " + position;
  msg += ": " + problem;
  return msg;
}

}  // namespace

std::string listForMessage(const std::vector<std::string>& items, std::size_t limit, std::string_view separator) {
  std::string out;
  for (std::size_t i = 0; i < items.size() && i < limit; ++i) {
    if (i > 0) out += separator;
    out += items[i];
  }
  if (items.size() > limit) out += std::string(separator) + "… (" + std::to_string(items.size() - limit) + " more)";
  return out;
}

std::string_view errorKindName(ErrorKind kind) {
  switch (kind) {
    case ErrorKind::Io: return "io";
    case ErrorKind::Malformed: return "malformed";
    case ErrorKind::Unsupported: return "unsupported";
    case ErrorKind::UnknownMarkerSet: return "unknown-marker-set";
    case ErrorKind::BadData: return "bad-data";
    case ErrorKind::BadArgument: return "bad-argument";
  }
  return "error";
}

Error::Error(ErrorKind kind, std::string file, std::string position, std::string problem)
    : std::runtime_error(composeMessage(file, position, problem)),
      kind_(kind),
      file_(std::move(file)),
      position_(std::move(position)),
      problem_(std::move(problem)) {}

void throwMalformed(const std::string& file, const std::string& position,
                    const std::string& problem) {
  throw Error(ErrorKind::Malformed, file, position, problem);
}

void throwBadData(const std::string& file, const std::string& position,
                  const std::string& problem) {
  throw Error(ErrorKind::BadData, file, position, problem);
}

}  // namespace ew
