#include "ui/gl/resources.h"

#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>

namespace ew::gl {

namespace {

std::filesystem::path executableDir() {
  std::error_code ec;
  const auto exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  return ec ? std::filesystem::path{} : exe.parent_path();
}

}  // namespace

std::filesystem::path resourceRoot() {
  std::vector<std::filesystem::path> candidates;
  if (const auto dir = executableDir(); !dir.empty()) {
    candidates.push_back(dir / "../share/eigenwalker");
    candidates.push_back(dir);
  }
  candidates.emplace_back(EW_RESOURCE_SOURCE_DIR);
  std::string looked;
  for (const auto& c : candidates) {
    std::error_code ec;
    if (std::filesystem::is_directory(c / "shaders", ec)) return c.lexically_normal();
    looked += "\n  " + (c / "shaders").string();
  }
  throw std::runtime_error("viewer resources not found; looked for" + looked);
}

std::filesystem::path resourcePath(const std::filesystem::path& relative) {
  return resourceRoot() / relative;
}

}  // namespace ew::gl
