#pragma once
// The bounds every motion-capture reader enforces, in one place (docs/FORMATS.md, "Limits"):
// a frame rate a capture system can plausibly have, and how many positions a reader may
// fill in memory. Positions are frames x points x 3 doubles (24 bytes per point-frame).
//
// Skeleton formats (BVH, ASF/AMC) compute a point per joint per frame by forward
// kinematics, so a small file declaring many joints and many near-empty frames could expand
// a thousandfold; their allowance is therefore tied to the bytes the file actually holds.
// Real files hold 0.05 point-frames per byte (CMU BVH and AMC: 38 points in ~800 bytes a
// frame); the allowance is 80 times that, and never less than a floor that any small test
// file fits in.

#include <cstddef>
#include <string>

namespace ew {

// Frame (point) rates: motion capture records at 10-2000 Hz, high-speed systems up to
// 10 kHz; video at 1-240 fps. Anything outside is a corrupt header or a wrong unit
// (a time column in milliseconds gives 0.001 Hz).
inline constexpr double kMinFrameRateHz = 1.0;
inline constexpr double kMaxFrameRateHz = 10000.0;

// Positions any reader keeps: 5e6 point-frames = 120 MB a copy (CMU's longest BVH trials:
// ~1e6; a 15-joint CSV: 5.5 hours at 100 Hz; 60 markers: 14 minutes at 100 Hz). The load
// path holds a few copies at once, so a file at this cap peaks below 600 MB.
inline constexpr double kMaxPointFrames = 5.0e6;
// Skeleton readers: at most this many point-frames per byte of the file, but always at
// least kMinPointFrameAllowance (24 MB).
inline constexpr double kPointFramesPerFileByte = 4.0;
inline constexpr double kMinPointFrameAllowance = 1.0e6;

// The point-frames a skeleton file of `fileBytes` bytes may expand to.
double skeletonPointFrameAllowance(std::size_t fileBytes);

// Throws Error(Malformed) naming the file and `where` ("DataRate", "Frame Time",
// "POINT:RATE") when a rate stated in a file is not finite or outside
// [kMinFrameRateHz, kMaxFrameRateHz]. Returns the rate.
double checkedFileRateHz(double rateHz, const std::string& file, const std::string& where);

// The same for a rate the user gave (LoadOptions::rateHzOverride): Error(BadArgument).
double checkedRateOverrideHz(double rateHz, const std::string& file);
// A rate the user gave as `option` ("--fps"): Error(BadArgument) naming it.
double checkedGivenRateHz(double rateHz, const std::string& file, const std::string& option);

// Throws Error(Unsupported) naming the file when frames x points exceeds `allowance`.
void checkPointFrames(double frames, double points, double allowance, const std::string& file,
                      const std::string& where);

}  // namespace ew
