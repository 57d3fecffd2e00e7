#pragma once
// C3D reader (www.c3d.org "The C3D File Format User Guide"): header, parameter section
// (from the header's parameter-block pointer), Intel / DEC / MIPS processor types,
// INT and REAL storage, POINT:SCALE/RATE/UNITS/LABELS/LABELS2/USED/FRAMES/LONG_FRAMES,
// first/last frame, negative residual = missing (NaN), EVENT group.
//
// What comes out (RawTrial): kind Markers (CanonicalJoints when the labels are exactly our 15
// joints in METHOD §1's order, as core/io/c3d_writer.h writes a walker), format "C3D", one label per 3D point (trimmed,
// in file order, POINT:LABELS then LABELS2, LABELS3, …), positions in millimetres in the
// file's own axes, NaN where the residual is negative (or a coordinate is not finite),
// firstFrame = the header's first frame number, upAxis from POINT:Y_SCREEN when present,
// gait events from the EVENT group with times relative to the first frame.
// Analog data is skipped (the layout is honoured, the values are not kept).
//
// Every problem in the bytes throws Error(Malformed) or Error(Unsupported) naming the file
// and the place ("byte 1234", "parameter POINT:LABELS"); oddities that can be read past
// (missing POINT:UNITS, header/parameter disagreements) go to RawTrial::warnings.

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>

#include "core/common/trial.h"
#include "core/io/load_trial.h"

namespace ew {

inline constexpr std::size_t kC3dBlockBytes = 512;  // header, parameter and data blocks

RawTrial readC3d(const std::filesystem::path& file, const LoadOptions& options = {});

// Parses C3D bytes already in memory; `name` is used in errors. Never reads outside
// `bytes`, never allocates more than the bytes can hold.
RawTrial parseC3d(std::span<const std::uint8_t> bytes, const std::string& name,
                  const LoadOptions& options = {});

// Converts a 4-byte DEC (VAX F_floating) value, as stored in a C3D file of processor
// type 85, to a float. Exposed for tests. Exponent 0 is +0 (sign 0) or NaN (the VAX
// "reserved operand", sign 1).
float decodeVaxFloat(const std::uint8_t bytes[4]);

}  // namespace ew
