#pragma once
// Writes the current default framebuffer (the whole window, as drawn, or a part of it)
// to a PNG, atomically (a temporary sibling, then a rename).

#include <filesystem>
#include <optional>
#include <vector>

#include "ui/pixel_rect.h"

namespace ew::ui {

// Reads back width × height pixels of the framebuffer that was just drawn and writes them
// (or only `crop`, clamped to the framebuffer) as an RGB PNG (top row first), creating the
// folder if needed. Throws std::runtime_error naming the file when it cannot be written.
void writeScreenshot(const std::filesystem::path& file, int width, int height,
                     std::optional<PixelRect> crop = std::nullopt);
// The same for RGB rows already read (bottom row first, as GL reads them).
void writeRgbPng(const std::filesystem::path& file, std::vector<unsigned char> rgb, int width, int height,
                 std::optional<PixelRect> crop = std::nullopt);

}  // namespace ew::ui
