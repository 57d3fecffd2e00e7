#pragma once
// C3D writer (www.c3d.org "The C3D File Format User Guide"): what gait labs and their tools
// (Visual3D, Mokka, OpenSim's readers, ezc3d) open, and what our own reader
// (core/io/c3d_reader.h) reads back to the same points, rate and events.
//
// The file, as written:
//   block 1        the header: parameter block 2, key 0x50, point count, frames 1..last (last
//                  at most 65535), scale −1 (REAL), data block, rate; the 4-character event
//                  key (12345) with no header events — the events are in the EVENT group, as
//                  Vicon Nexus writes them (c3d-samples/sample03: key set, count 0), so a
//                  reader that merges both lists does not show every event twice
//   block 2 …      the parameters (processor type 84, Intel; the last record's offset to the
//                  next is 0, where the guide says the section ends), groups in this order:
//                  POINT   USED, SCALE (−1), RATE, FRAMES, DATA_START, UNITS ("mm"), LABELS,
//                          DESCRIPTIONS, X_SCREEN, Y_SCREEN (+ LONG_FRAMES past 65535 frames)
//                  ANALOG  USED 0, RATE (no analog channels)
//                  TRIAL   ACTUAL_START_FIELD, ACTUAL_END_FIELD (32-bit frame numbers as two
//                          16-bit words, low word first), CAMERA_RATE
//                  EVENT   USED, CONTEXTS ("Right"/"Left"), LABELS, DESCRIPTIONS, TIMES (2 × N
//                          floats: minutes, seconds from the first frame), ICON_IDS (1 strike,
//                          2 off, 0 other, as Nexus), GENERIC_FLAGS (bytes, 0)
//                  MANUFACTURER  COMPANY "Eigenwalker", SOFTWARE, and NOTES: free text lines
//   then           the data: per frame, per point, x y z and a residual word as 32-bit
//                  little-endian IEEE floats. A point present in a frame has residual 0 (the
//                  guide's "valid, but computed rather than measured by cameras"); a missing one
//                  (any coordinate not finite) has coordinates 0 and residual −1, the C3D mark
//                  of an invalid sample. Frame 1 is at 0 s.
//
// Long trials: the header's frame words are 16 bits; past 65535 frames the header says
// 1..65535 and POINT:FRAMES and POINT:LONG_FRAMES hold the count as a float, TRIAL's fields
// as 32-bit numbers (the guide's "Maintaining C3D frame count compatibility"). A float holds
// every whole number up to 2^24, so at most kC3dMaxFrames frames are written.

#include <Eigen/Core>
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "core/common/trial.h"

namespace ew {

// A parameter's dimension is one byte: at most 255 characters in a label, 255 labels.
inline constexpr std::size_t kC3dMaxTextChars = 255;
inline constexpr std::size_t kC3dMaxPoints = 255;
// EVENT:TIMES is 2 × N with N one byte.
inline constexpr std::size_t kC3dMaxEvents = 255;
// 2^24: the largest frame count a float POINT:FRAMES holds exactly.
inline constexpr long kC3dMaxFrames = 16777216;

// One named point over the trial: T × 3 positions in mm, in the file's axes. A row with any
// coordinate not finite is a missing sample.
struct C3dPointTrajectory {
  std::string label;        // POINT:LABELS: printable ASCII, 1–255 chars, no edge spaces, unique
  std::string description;  // POINT:DESCRIPTIONS (may be empty; UTF-8, as the guide allows)
  Eigen::MatrixX3d positionsMm;
};

struct C3dContent {
  double rateHz = 0.0;  // frames per second, within the readers' [1, 10000] Hz
  std::vector<C3dPointTrajectory> points;  // all with the same number of frames (≥ 1)
  // Times in seconds from the first frame (≥ 0). The label, when empty, is the type's
  // ("Foot Strike", "Foot Off", "Event"); the context is the side ("Right", "Left").
  std::vector<GaitEvent> events;
  std::string eventDescription;  // EVENT:DESCRIPTIONS of every event (may be empty)
  std::string xScreen = "+Y", yScreen = "+Z";  // POINT:X_SCREEN / Y_SCREEN: the lab's axes
                                               // drawn right and up on screen
  std::vector<std::string> notes;  // MANUFACTURER:NOTES (UTF-8); lines longer than 255 bytes
                                   // are cut into several
};

// Writes `content` to `file` atomically (core/io/atomic_write.h). Throws Error(BadArgument)
// naming the file and the problem — a rate that is not a frame rate, no points or no frames,
// points of different lengths, a label empty, too long, not printable or repeated, more points,
// events or frames than C3D holds, an event time not finite or negative, a coordinate beyond a
// float — before anything is written; Error(Io) when the file cannot be written.
void writeC3d(const std::filesystem::path& file, const C3dContent& content);

// The 15 joints of a T × 45 walker (METHOD §1) as named points, in METHOD's order and names.
std::vector<C3dPointTrajectory> jointPointTrajectories(
    const Eigen::Ref<const Eigen::MatrixXd>& framesX45, const std::string& description);

// A 3D walker (T × 45 joints, mm, any axes with the body upright along one of them) as C3D:
// the 15 joints, then `extraPoints` (feet markers, …), and the gait events its own kinematics
// give (gaitEventsFromKinematics, core/gait/gait_events.h, on a copy turned to z up and facing
// +y; none when a joint sample is missing, and a note says so; past kC3dMaxEvents the first
// 255 are written and a note says how many were left out). X_SCREEN / Y_SCREEN name the
// walker's forward and up axes, so a viewer shows it from the side. `notes` go to
// MANUFACTURER:NOTES.
void writeWalkerC3d(const std::filesystem::path& file,
                    const Eigen::Ref<const Eigen::MatrixXd>& framesX45, double rateHz,
                    const std::vector<std::string>& notes = {},
                    const std::vector<C3dPointTrajectory>& extraPoints = {});

// The feet's points of a T × 12 JointTrial::feetMm (FootPoint order) as named points r_heel,
// r_toe, l_heel, l_toe; a point with no finite sample is left out. None for another shape.
std::vector<C3dPointTrajectory> footPointTrajectories(const Eigen::MatrixXd& feetX12,
                                                      const std::string& description);

// writeWalkerC3d with the feet where known (feetX12: T × 12 in the joints' axes; empty or of
// another shape: none): their points after the 15 joints, and the gait events from the heel and
// the toe (gaitEventsFromFeet) where they are seen throughout. The program's C3D reader reads
// such a file back to the same joints, feet and events.
// feetInSagittalPlanes: the feet were lifted from one view (core/camera/lifted_feet.h); their
// points are described as kSagittalFootDescription (core/common/trial.h), which our reader
// takes back as JointTrial::feetInSagittalPlanes.
void writeWalkerWithFeetC3d(const std::filesystem::path& file,
                            const Eigen::Ref<const Eigen::MatrixXd>& framesX45,
                            const Eigen::MatrixXd& feetX12, double rateHz,
                            const std::vector<std::string>& notes = {},
                            const std::vector<C3dPointTrajectory>& extraPoints = {},
                            bool feetInSagittalPlanes = false);

}  // namespace ew
