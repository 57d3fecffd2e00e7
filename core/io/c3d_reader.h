#pragma once
// C3D reader (www.c3d.org "The C3D File Format User Guide"): header, parameter section
// (from the header's parameter-block pointer), Intel / DEC / MIPS processor types,
// INT and REAL storage, POINT:SCALE/RATE/UNITS/LABELS/LABELS2/USED/FRAMES/LONG_FRAMES,
// first/last frame, negative residual = missing (NaN), EVENT group.

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>

#include "core/common/trial.h"
#include "core/io/load_trial.h"

namespace ew {

RawTrial readC3d(const std::filesystem::path& file, const LoadOptions& options = {});

// Parses C3D bytes already in memory; `name` is used in errors. Never reads outside
// `bytes`, never allocates more than the bytes can hold.
RawTrial parseC3d(std::span<const std::uint8_t> bytes, const std::string& name,
                  const LoadOptions& options = {});

}  // namespace ew
