#pragma once
// Where the viewer's files (shaders/, assets/) are found: next to the installed binary
// (<prefix>/share/eigenwalker, or beside the executable), else the source tree the build
// was configured from (a development build runs without installing anything).

#include <filesystem>

namespace ew::gl {

// The directory holding shaders/ and assets/. Throws std::runtime_error listing the
// places looked at when none has a shaders/ folder.
std::filesystem::path resourceRoot();

// resourceRoot() / relative, e.g. resourcePath("shaders/sphere.vert").
std::filesystem::path resourcePath(const std::filesystem::path& relative);

}  // namespace ew::gl
