#pragma once
// Writes the current default framebuffer (the whole window, as drawn) to a PNG.

#include <filesystem>

namespace ew::ui {

// Reads back width × height pixels of the framebuffer that was just drawn and writes them
// as an RGB PNG (top row first), creating the folder if needed. Throws
// std::runtime_error naming the file when it cannot be written.
void writeScreenshot(const std::filesystem::path& file, int width, int height);

}  // namespace ew::ui
