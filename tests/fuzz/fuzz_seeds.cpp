// fuzz_seeds: writes the seed corpus of every harness of tests/fuzz/ into a build folder,
// from the project's own writers and fixtures, so no seed is committed as a big file:
//
//   fuzz_seeds OUT_DIR [--data SHARED_DATA_DIR]
//
// OUT_DIR/<harness>/ gets (each folder emptied first):
//   - walking trials of the synthetic population (core/synth) written by our writers:
//     BVH (formatBvh), 15-joint CSV (writeJointCsv), and Plug-in Gait markers around the
//     walker's joints as TRC and as C3D (Intel REAL, Intel INT, MIPS REAL; a C3D writer
//     of our own below, only for seeds);
//   - trials at the edges of the gait stages (out and back, a one-frame 1 km glitch,
//     standing still, one frame, a missing joint, 1 Hz and 10 kHz, a treadmill);
//   - small hand-made files shaped like the fixtures of tests/io (a two-bone ASF/AMC,
//     a three-frame TRC, a tiny BVH, a CSV with gaps and comments, a C3D with events);
//   - a model file (saveModel of a three-walker synthetic model);
//   - when the shared data is present ($EIGENWALKER_DATA, --data, else the configured
//     ../shared/data), copies of small real files: C3D samples, one CMU BVH, CMU subject
//     35's skeleton with its walk 35_01, the Pose2Sim TRC. Never into the
//     source tree.
// pipeline/ gets the walking seeds of every format behind their format byte
// (fuzz_pipeline.cpp: 0 C3D, 1 BVH, 2 ASF+AMC, 3 TRC, 4 CSV).

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/common/errors.h"
#include "core/eigenwalker/model_file.h"
#include "core/snippet/snippet_file.h"
#include "core/snippet/snippet_prior.h"
#include "core/mapping/mapping_file.h"
#include "core/eigenwalker/walker_set.h"
#include "core/io/bvh_writer.h"
#include "core/io/file_bytes.h"
#include "core/io/joint_csv.h"
#include "core/keypoints/keypoint_layout.h"
#include "core/keypoints/openpose_writer.h"
#include "core/synth/population.h"
#include "core/tracking/keyframes.h"
#include "tests/camera/filmed_walk.h"
#include "tests/common/nexus_text.h"
#include "tests/common/qtm_text.h"
#include "tests/fuzz/fuzz_common.h"

#ifndef EW_SHARED_DATA_DIR
#define EW_SHARED_DATA_DIR ""
#endif

namespace {

namespace fs = std::filesystem;
using Eigen::MatrixXd;
using Eigen::Vector3d;

// [SECTION] Output folders

// pipeline's format byte for each reader (fuzz_pipeline.cpp).
enum class Format : std::uint8_t { C3d = 0, Bvh = 1, AsfAmc = 2, Trc = 3, Csv = 4 };

class SeedWriter {
 public:
  explicit SeedWriter(fs::path root) : root_(std::move(root)) {}

  // Empties (or creates) the harness's folder.
  void reset(const std::string& harness) {
    fs::remove_all(root_ / harness);
    fs::create_directories(root_ / harness);
  }

  void write(const std::string& harness, const std::string& name, std::string_view bytes) {
    std::ofstream out(root_ / harness / name, std::ios::binary);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    if (!out)
      throw ew::Error(ew::ErrorKind::Io, (root_ / harness / name).string(), "",
                      "cannot write seed");
    ++written_;
  }

  // The same seed for its reader's harness and, behind its format byte, for the pipeline.
  void writeBoth(const std::string& harness, Format format, const std::string& name,
                 std::string_view bytes) {
    write(harness, name, bytes);
    std::string prefixed(1, static_cast<char>(format));
    prefixed += bytes;
    write("pipeline", name, prefixed);
  }

  int written() const { return written_; }

 private:
  fs::path root_;
  int written_ = 0;
};

std::string readText(const fs::path& file) {
  const auto bytes = ew::readFileBytes(file);
  return {bytes.begin(), bytes.end()};
}

// [SECTION] Synthetic walkers

// Two walkers at 50 Hz over 3.5 cycles: long enough for a steady window and a Fourier
// fit, short enough that every seed stays small (values written to 0.1 mm).
std::vector<ew::SynthWalker> seedWalkers() {
  ew::PopulationOptions options;
  options.count = 2;
  options.simulation.rateHz = 50.0;
  options.simulation.cycles = 3.5;
  return ew::generatePopulation(options);
}

MatrixXd roundedTo01(const MatrixXd& m) { return (m.array() * 10.0).round() / 10.0; }

Vector3d jointOf(const MatrixXd& frames, int f, ew::Joint j) { return ew::jointAt(frames, f, j); }

// Plug-in Gait markers placed rigidly around the joints (canonical axes: x right,
// y forward, z up), with the model's joint-centre outputs that the mapper prefers.
struct Marker {
  std::string label;
  ew::Joint joint;
  Vector3d offsetMm;
};

const std::vector<Marker>& pigMarkers() {
  using ew::Joint;
  static const std::vector<Marker> markers = {
      {"LASI", Joint::LHip, {-30, 60, 80}},   {"RASI", Joint::RHip, {30, 60, 80}},
      {"LPSI", Joint::LHip, {40, -110, 90}},  {"RPSI", Joint::RHip, {-40, -110, 90}},
      {"LHJC", Joint::LHip, {0, 0, 0}},       {"RHJC", Joint::RHip, {0, 0, 0}},
      {"LKNE", Joint::LKnee, {-50, 0, 0}},    {"RKNE", Joint::RKnee, {50, 0, 0}},
      {"LKJC", Joint::LKnee, {0, 0, 0}},      {"RKJC", Joint::RKnee, {0, 0, 0}},
      {"LANK", Joint::LAnkle, {-40, 0, 0}},   {"RANK", Joint::RAnkle, {40, 0, 0}},
      {"LAJC", Joint::LAnkle, {0, 0, 0}},     {"RAJC", Joint::RAnkle, {0, 0, 0}},
      {"LSHO", Joint::LShoulder, {0, 0, 60}}, {"RSHO", Joint::RShoulder, {0, 0, 60}},
      {"LELB", Joint::LElbow, {-40, 0, 0}},   {"RELB", Joint::RElbow, {40, 0, 0}},
      {"LWRA", Joint::LWrist, {0, 25, 0}},    {"LWRB", Joint::LWrist, {0, -25, 0}},
      {"RWRA", Joint::RWrist, {0, 25, 0}},    {"RWRB", Joint::RWrist, {0, -25, 0}},
      {"C7", Joint::Sternum, {0, -60, 0}},    {"CLAV", Joint::Sternum, {0, 60, 0}},
      {"LFHD", Joint::Head, {-60, 80, 30}},   {"RFHD", Joint::Head, {60, 80, 30}},
      {"LBHD", Joint::Head, {-60, -80, 30}},  {"RBHD", Joint::Head, {60, -80, 30}},
  };
  return markers;
}

// Frames x 3·markers, mm.
MatrixXd markerFrames(const MatrixXd& joints) {
  const auto& markers = pigMarkers();
  MatrixXd out(joints.rows(), 3 * static_cast<Eigen::Index>(markers.size()));
  for (int f = 0; f < joints.rows(); ++f) {
    for (std::size_t k = 0; k < markers.size(); ++k) {
      out.block<1, 3>(f, 3 * static_cast<Eigen::Index>(k)) =
          (jointOf(joints, f, markers[k].joint) + markers[k].offsetMm).transpose();
    }
  }
  return roundedTo01(out);
}

std::vector<std::string> pigLabels() {
  std::vector<std::string> labels;
  for (const auto& m : pigMarkers()) labels.push_back(m.label);
  return labels;
}

// [SECTION] TRC text

std::string trcText(const std::vector<std::string>& labels, const MatrixXd& framesMm, double rateHz,
                    const std::string& units) {
  std::ostringstream out;
  const auto frames = framesMm.rows();
  out << "PathFileType\t4\t(X/Y/Z)\tseed.trc\n"
      << "DataRate\tCameraRate\tNumFrames\tNumMarkers\tUnits\tOrigDataRate\tOrigDataStartFrame"
         "\tOrigNumFrames\n"
      << rateHz << '\t' << rateHz << '\t' << frames << '\t' << labels.size() << '\t' << units
      << '\t' << rateHz << "\t1\t" << frames << "\n"
      << "Frame#\tTime";
  for (const auto& l : labels) out << '\t' << l << "\t\t";
  out << "\n\t";
  for (std::size_t k = 1; k <= labels.size(); ++k) out << "\tX" << k << "\tY" << k << "\tZ" << k;
  out << "\n\n";
  const double scale = units == "m" ? 0.001 : 1.0;
  for (Eigen::Index f = 0; f < frames; ++f) {
    out << f + 1 << '\t' << static_cast<double>(f) / rateHz;
    for (Eigen::Index c = 0; c < framesMm.cols(); ++c) {
      out << '\t';
      if (std::isfinite(framesMm(f, c))) out << framesMm(f, c) * scale;
    }
    out << "\n";
  }
  return out.str();
}

// The same markers as Vicon Nexus exports them (tests/common/nexus_text.h): with a force-plate
// section before them, or tab-separated with velocity columns beside the positions.
std::string nexusSeed(const MatrixXd& markersMm, double rateHz, bool tabsAndVelocities) {
  ew::RawTrial t;
  t.labels = pigLabels();
  t.positionsMm = markersMm;
  t.rateHz = rateHz;
  ew::test::NexusLayout layout;
  if (tabsAndVelocities) layout = {'\t', true, false, "Seed"};
  return ew::test::nexusText(t, layout);
}

// The same markers as Qualisys Track Manager exports them (tests/common/qtm_text.h): with the
// frame and time columns and their header row, or bare coordinates with gaps as zeros.
std::string qtmSeed(const MatrixXd& markersMm, double rateHz, bool bareWithZeros) {
  ew::RawTrial t;
  t.labels = pigLabels();
  t.positionsMm = markersMm;
  t.rateHz = rateHz;
  return ew::test::qtmText(t, bareWithZeros ? ew::test::QtmLayout{false, false, true, true} : ew::test::QtmLayout{});
}

// [SECTION] C3D bytes (a minimal writer of our own, for seeds only)

// Blocks of 512 bytes: header, one parameter block, then the data. Intel (84) or MIPS
// (86) byte order; REAL (POINT:SCALE < 0, float32) or INT (int16 · scale) storage.
class C3dBuilder {
 public:
  enum class Processor : std::uint8_t { Intel = 84, Mips = 86 };

  explicit C3dBuilder(Processor p) : processor_(p) {}

  struct Event {
    std::string context, label;  // "Left", "Foot Strike"
    float timeS = 0.0f;
  };

  std::string build(const std::vector<std::string>& labels, const MatrixXd& framesMm, double rateHz,
                    bool real, const std::vector<Event>& events = {}) {
    const auto points = static_cast<std::uint16_t>(labels.size());
    const auto frames = static_cast<std::uint16_t>(framesMm.rows());
    const double maxAbs =
        framesMm.array().isFinite().select(framesMm.array().abs(), 0.0).maxCoeff();
    const float scale =
        real ? -1.0f
             : static_cast<float>(std::max(0.01, std::ceil(maxAbs / 30000.0 * 100.0) / 100.0));

    // Parameter section (block 2, so the data starts at block 3 when it fits in one).
    std::string params;
    params += static_cast<char>(1);
    params += static_cast<char>(0x50);
    params += static_cast<char>(0);  // block count: patched below
    params += static_cast<char>(processor_);
    group(params, "POINT", 1);
    std::size_t labelLen = 4;
    for (const auto& l : labels) labelLen = std::max(labelLen, l.size());
    parameter(params, "USED", 1, 2, {}, word(points));
    parameter(params, "SCALE", 1, 4, {}, float32(scale));
    parameter(params, "RATE", 1, 4, {}, float32(static_cast<float>(rateHz)));
    parameter(params, "FRAMES", 1, 2, {}, word(frames));
    parameter(params, "UNITS", 1, -1, {2}, "mm");
    parameter(params, "Y_SCREEN", 1, -1, {2}, "+Z");
    parameter(params, "X_SCREEN", 1, -1, {2}, "+X");
    parameter(params, "LABELS", 1, -1,
              {static_cast<std::uint8_t>(labelLen), static_cast<std::uint8_t>(points)},
              padded(labels, labelLen));
    const std::size_t dataStartAt = parameter(params, "DATA_START", 1, 2, {}, word(0));
    if (!events.empty()) {
      group(params, "EVENT", 2);
      const auto n = static_cast<std::uint8_t>(events.size());
      std::vector<std::string> contexts, names;
      std::string times;
      for (const auto& e : events) {
        contexts.push_back(e.context);
        names.push_back(e.label);
        times += float32(0.0f) + float32(e.timeS);
      }
      parameter(params, "USED", 2, 2, {}, word(n));
      parameter(params, "CONTEXTS", 2, -1, {16, n}, padded(contexts, 16));
      parameter(params, "LABELS", 2, -1, {16, n}, padded(names, 16));
      parameter(params, "TIMES", 2, 4, {2, n}, times);
    }
    lastRecordEndsChain(params);
    const std::size_t paramBlocks = (params.size() + 511) / 512;
    params[2] = static_cast<char>(paramBlocks);
    const auto dataBlock = static_cast<std::uint16_t>(2 + paramBlocks);
    params.replace(dataStartAt, 2, word(dataBlock));
    params.resize(paramBlocks * 512, '\0');

    std::string header(512, '\0');
    header[0] = 2;
    header[1] = 0x50;
    put(header, 2, word(points));
    put(header, 4, word(0));
    put(header, 6, word(1));
    put(header, 8, word(frames));
    put(header, 10, word(10));
    put(header, 12, float32(scale));
    put(header, 16, word(dataBlock));
    put(header, 18, word(0));
    put(header, 20, float32(static_cast<float>(rateHz)));

    std::string data;
    for (Eigen::Index f = 0; f < framesMm.rows(); ++f) {
      for (Eigen::Index p = 0; p < static_cast<Eigen::Index>(points); ++p) {
        const Vector3d v = framesMm.block<1, 3>(f, 3 * p).transpose();
        const bool valid = v.allFinite();
        for (int c = 0; c < 3; ++c) {
          const double value = valid ? v(c) : 0.0;
          data += real ? float32(static_cast<float>(value))
                       : word(static_cast<std::uint16_t>(
                             static_cast<std::int16_t>(std::lround(value / scale))));
        }
        data += real ? float32(valid ? 0.0f : -1.0f) : word(valid ? 0 : 0xffff);
      }
    }
    data.resize((data.size() + 511) / 512 * 512, '\0');
    return header + params + data;
  }

 private:
  std::string word(std::uint16_t v) const {
    const char lo = static_cast<char>(v & 0xff), hi = static_cast<char>(v >> 8);
    return processor_ == Processor::Mips ? std::string{hi, lo} : std::string{lo, hi};
  }

  std::string float32(float f) const {
    std::uint32_t bits = 0;
    std::memcpy(&bits, &f, 4);
    std::string le(4, '\0');
    for (int b = 0; b < 4; ++b)
      le[static_cast<std::size_t>(b)] = static_cast<char>((bits >> (8 * b)) & 0xff);
    if (processor_ == Processor::Mips) std::reverse(le.begin(), le.end());
    return le;
  }

  static void put(std::string& s, std::size_t at, const std::string& bytes) {
    s.replace(at, bytes.size(), bytes);
  }

  static std::string padded(const std::vector<std::string>& items, std::size_t len) {
    std::string out;
    for (const auto& s : items)
      out += s.substr(0, len) + std::string(len - std::min(len, s.size()), ' ');
    return out;
  }

  // A record: name length, id, name, offset word to the next record, then `body`.
  // Returns where the body starts. The offset is counted from the offset word itself.
  std::size_t record(std::string& params, const std::string& name, int id,
                     const std::string& body) {
    params += static_cast<char>(name.size());
    params += static_cast<char>(static_cast<std::int8_t>(id));
    params += name;
    lastOffsetAt_ = params.size();
    params += word(static_cast<std::uint16_t>(2 + body.size()));
    const std::size_t bodyAt = params.size();
    params += body;
    return bodyAt;
  }

  void group(std::string& params, const std::string& name, int id) {
    record(params, name, -id, std::string(1, '\0'));  // empty description
  }

  // Returns where the values start.
  std::size_t parameter(std::string& params, const std::string& name, int group, int type,
                        const std::vector<std::uint8_t>& dims, const std::string& values) {
    std::string body;
    body += static_cast<char>(static_cast<std::int8_t>(type));
    body += static_cast<char>(dims.size());
    for (auto d : dims) body += static_cast<char>(d);
    const std::size_t valuesAt = body.size();
    body += values;
    body += '\0';  // empty description
    return record(params, name, group, body) + valuesAt;
  }

  void lastRecordEndsChain(std::string& params) const { params.replace(lastOffsetAt_, 2, word(0)); }

  Processor processor_;
  std::size_t lastOffsetAt_ = 0;
};

// [SECTION] Hand-made small files (shaped like the fixtures of tests/io)

// Root, bone "a" up +y with an rx dof, bone "b" along +x with its axis turned 90° about z.
const char* kTinyAsf =
    "# tiny skeleton\n:version 1.10\n:name tiny\n:units\n  mass 1.0\n  length 1.0\n  angle deg\n"
    ":documentation\n  free text: with a colon\n:root\n   order TX TY TZ RX RY RZ\n   axis XYZ\n"
    "   position 0 0 0\n   orientation 0 0 0\n:bonedata\n  begin\n     id 1\n     name a\n"
    "     direction 0 1 0\n     length 2\n     axis 0 0 0 XYZ\n    dof rx\n"
    "    limits (-180.0 180.0)\n  end\n  begin\n     id 2\n     name b\n     direction 1 0 0\n"
    "     length 1\n     axis 0 0 90 XYZ\n    dof rx rz\n    limits (-inf inf)\n           (-90 "
    "90)\n"
    "  end\n:hierarchy\n  begin\n    root a\n    a b\n  end\n";

const char* kTinyAmc =
    "#!OML:ASF tiny.asf\n:FULLY-SPECIFIED\n:DEGREES\n1\nroot 1 2 3 0 0 0\na 0\nb 0 0\n2\n"
    "root 1 2 3 0 0 0\na 90\nb 90 0\n3\nroot 0 0 0 0 0 90\n";

const char* kTinyTrc =
    "PathFileType\t4\t(X/Y/Z)\twalk.trc\r\n"
    "DataRate\tCameraRate\tNumFrames\tNumMarkers\tUnits\tOrigDataRate\tOrigDataStartFrame\tOrigNumF"
    "rames\r\n"
    "60.00\t60.00\t3\t2\tm\t60.00\t1\t3\r\n"
    "Frame#\tTime\tLASI\t\t\tRASI\t\t\r\n"
    "\t\tX1\tY1\tZ1\tX2\tY2\tZ2\r\n\r\n"
    "1\t0.000\t0.1\t0.9\t0.2\t0.3\t0.9\t0.2\r\n"
    "2\t0.0167\t0.1\t0.9\t0.2\t\t\t\r\n"
    "3\t0.0333\t0.1\t0.9\t0.2\t0.3\t0.9\t0.25\r\n";

// Sports2D's way: image points under "Units m", Z 0 (a 2D view, core/keypoints/planar_trc.cpp).
const char* kTinyPlanarTrc =
    "PathFileType\t4\t(X/Y/Z)\twalk_Sports2D_px_person00.trc\n"
    "DataRate\tCameraRate\tNumFrames\tNumMarkers\tUnits\tOrigDataRate\tOrigDataStartFrame\tOrigNumFrames\n"
    "30\t30\t3\t7\tm\t30\t0\t3\n"
    "Frame#\tTime\tNose\t\t\tRHip\t\t\tLHip\t\t\tRKnee\t\t\tLKnee\t\t\tRAnkle\t\t\tLAnkle\t\t\n"
    "\t\tX1\tY1\tZ1\tX2\tY2\tZ2\tX3\tY3\tZ3\tX4\tY4\tZ4\tX5\tY5\tZ5\tX6\tY6\tZ6\tX7\tY7\tZ7\n"
    "0\t0.0\t0.50\t-0.10\t0\t0.49\t-0.40\t0\t0.51\t-0.40\t0\t0.52\t-0.55\t0\t0.47\t-0.55\t0\t0.55\t-0.70\t0\t0.45\t-0.70\t0\n"
    "1\t0.033\t0.51\t-0.10\t0\t0.50\t-0.40\t0\t0.52\t-0.40\t0\t0.52\t-0.55\t0\t0.49\t-0.55\t0\t0.54\t-0.70\t0\t0\t0\t0\n"
    "2\t0.067\t0.52\t-0.10\t0\t0.51\t-0.40\t0\t0.53\t-0.40\t0\t0.53\t-0.55\t0\t0.51\t-0.55\t0\t0.53\t-0.70\t0\t0.50\t-0.70\t0\n";

const char* kTinyBvh =
    "HIERARCHY\nROOT Hips\n{\n  OFFSET 0 0 0\n"
    "  CHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation\n"
    "  JOINT LeftUpLeg\n  {\n    OFFSET 10 0 0\n    CHANNELS 3 Zrotation Xrotation Yrotation\n"
    "    End Site\n    {\n      OFFSET 0 -40 0\n    }\n  }\n"
    "  JOINT RightUpLeg\n  {\n    OFFSET -10 0 0\n    CHANNELS 3 Xrotation Yrotation Zrotation\n"
    "    End Site\n    {\n      OFFSET 0 -40 0\n    }\n  }\n}\n"
    "MOTION\nFrames: 3\nFrame Time: 0.0333333\n"
    "0 90 0 0 0 0 0 0 0 0 0 0\n0 90 1 0 0 0 10 0 0 -10 0 0\n0 90 2 0 0 0 20 0 0 -20 0 0\n";

std::string tinyCsv() {
  std::string text = "# a comment line\n# units=m\n# rate_hz=100\n" + ew::jointCsvHeader() + "\n";
  for (int f = 0; f < 3; ++f) {
    text += std::to_string(f) + "," + std::to_string(f * 0.01);
    for (int c = 0; c < ew::kDims3; ++c) {
      text += ",";
      if (f == 1 && c == 4) continue;  // an empty cell: a gap
      text += f == 2 && c == 7 ? "nan" : std::to_string(0.001 * (c + f));
    }
    text += "\n";
  }
  return text;
}

std::string asfAmc(std::string_view asf, std::string_view amc) {
  return std::string(asf) + "\n" + std::string(ew::fuzz::kAmcSeparator) + "\n" + std::string(amc);
}

// [SECTION] Seeds per harness

void syntheticSeeds(SeedWriter& out, const fs::path& tmp) {
  const auto walkers = seedWalkers();
  for (std::size_t i = 0; i < walkers.size(); ++i) {
    const auto& w = walkers[i];
    const std::string stem = "synthetic_" + w.trialId;
    const MatrixXd joints = roundedTo01(w.trial.positionsMm);
    const double rate = w.trial.rateHz;

    ew::BvhWriteOptions bvh;
    bvh.toesMm = w.toesMm;
    bvh.decimals = 2;
    out.writeBoth("bvh", Format::Bvh, stem + ".bvh", ew::formatBvh(joints, rate, bvh));

    const fs::path csvFile = tmp / (stem + ".csv");
    ew::writeJointCsv(csvFile, joints, rate, {"synthetic walker " + w.trialId + " (fuzz seed)"});
    out.writeBoth("joint_csv", Format::Csv, stem + ".csv", readText(csvFile));

    const MatrixXd markers = markerFrames(w.trial.positionsMm);
    out.writeBoth("trc", Format::Trc, stem + "_pig.trc", trcText(pigLabels(), markers, rate, "mm"));
    out.writeBoth("joint_csv", Format::Csv, stem + "_pig_nexus.csv", nexusSeed(markers, rate, i == 0));
    out.write("qtm_tsv", stem + "_pig.tsv", qtmSeed(markers, rate, i == 0));
    C3dBuilder intel(C3dBuilder::Processor::Intel);
    out.writeBoth("c3d", Format::C3d, stem + "_pig_intel_real.c3d",
                  intel.build(pigLabels(), markers, rate, true));
    if (i == 0) {
      out.writeBoth("trc", Format::Trc, stem + "_pig_m.trc",
                    trcText(pigLabels(), markers, rate, "m"));
      out.writeBoth("c3d", Format::C3d, stem + "_pig_intel_int.c3d",
                    intel.build(pigLabels(), markers, rate, false));
      C3dBuilder mips(C3dBuilder::Processor::Mips);
      out.writeBoth("c3d", Format::C3d, stem + "_pig_mips_real.c3d",
                    mips.build(pigLabels(), markers, rate, true));
    }
  }
}

// Trials at the edges of what the gait stages accept, as 15-joint CSV (and one TRC):
// where a crash after the readers is most likely (issue 11), and good starting points for
// the fuzzer's mutations of the later stages.
void gaitEdgeSeeds(SeedWriter& out, const fs::path& tmp) {
  const auto walkers = seedWalkers();
  const ew::SynthWalker& w = walkers.front();
  const MatrixXd walk = roundedTo01(w.trial.positionsMm);
  const double rate = w.trial.rateHz;
  const Eigen::Index frames = walk.rows();
  auto csv = [&](const std::string& name, const MatrixXd& m, double rateHz) {
    const fs::path file = tmp / name;
    ew::writeJointCsv(file, m, rateHz, {"edge case " + name + " (fuzz seed)"});
    out.writeBoth("joint_csv", Format::Csv, name, readText(file));
  };

  // Out and back: the walk, then the same walk turned round (180° about the vertical)
  // starting where the first leg ended, so the walker comes back to the start.
  MatrixXd outAndBack(2 * frames, ew::kDims3);
  outAndBack.topRows(frames) = walk;
  const Vector3d start = jointOf(walk, 0, ew::Joint::Pelvis),
                 end = jointOf(walk, static_cast<int>(frames - 1), ew::Joint::Pelvis);
  for (Eigen::Index f = 0; f < frames; ++f) {
    for (int j = 0; j < ew::kJointCount; ++j) {
      const Vector3d p = walk.block<1, 3>(f, 3 * j).transpose() - start;
      outAndBack.block<1, 3>(frames + f, 3 * j) =
          Vector3d(end.x() - p.x(), end.y() - p.y(), p.z() + start.z()).transpose();
    }
  }
  csv("edge_out_and_back.csv", outAndBack, rate);

  // One sample 1 km off for one frame (the pelvis in the CSV; a marker in the TRC).
  MatrixXd glitch = walk;
  glitch(frames / 2, 3 * ew::index(ew::Joint::Pelvis)) += 1.0e6;
  csv("edge_glitch_1km_one_frame.csv", glitch, rate);
  MatrixXd markers = markerFrames(w.trial.positionsMm);
  markers(frames / 2, 0) += 1.0e6;
  out.writeBoth("trc", Format::Trc, "edge_glitch_1km_one_frame_pig.trc",
                trcText(pigLabels(), markers, rate, "mm"));

  // Standing still, a single frame, a joint never seen, the rate bounds of the readers.
  csv("edge_standing_still.csv", walk.row(0).replicate(frames, 1), rate);
  csv("edge_single_frame.csv", walk.topRows(1), rate);
  MatrixXd noWrist = walk;
  noWrist.middleCols(3 * ew::index(ew::Joint::LWrist), 3).setConstant(std::nan(""));
  csv("edge_left_wrist_missing.csv", noWrist, rate);
  csv("edge_rate_1hz.csv", walk, 1.0);
  csv("edge_rate_10000hz.csv", walk, 10000.0);

  // On a treadmill: no progression.
  ew::PopulationOptions treadmill;
  treadmill.count = 1;
  treadmill.simulation.rateHz = 50.0;
  treadmill.simulation.cycles = 3.5;
  treadmill.simulation.treadmill = true;
  const auto onBelt = ew::generatePopulation(treadmill);
  csv("edge_treadmill.csv", roundedTo01(onBelt.front().trial.positionsMm),
      onBelt.front().trial.rateHz);
}

// Joint mapping files (docs/FORMATS.md): a lower-body one that applies to the harness's
// trial, and one with every kind of value (label, list, null).
void mappingSeeds(SeedWriter& out) {
  ew::JointMapping lower;
  lower.joints[ew::index(ew::Joint::Pelvis)] = {"LASI", "RASI"};
  lower.joints[ew::index(ew::Joint::LKnee)] = {"LKNE"};
  lower.joints[ew::index(ew::Joint::RKnee)] = {"RKNE"};
  lower.joints[ew::index(ew::Joint::LAnkle)] = {"LANK"};
  lower.joints[ew::index(ew::Joint::RAnkle)] = {"RANK"};
  out.write("mapping_file", "lower_body.json", ew::jointMappingToJson(lower));
  ew::JointMapping mixed = lower;
  mixed.joints[ew::index(ew::Joint::Head)] = {"HEAD"};
  mixed.joints[ew::index(ew::Joint::Sternum)] = {"GONE", "HEAD"};
  out.write("mapping_file", "mixed_with_unseen_marker.json", ew::jointMappingToJson(mixed));
}

void handMadeSeeds(SeedWriter& out) {
  out.writeBoth("asf_amc", Format::AsfAmc, "tiny_two_bones.asfamc", asfAmc(kTinyAsf, kTinyAmc));
  out.write("asf_amc", "tiny_skeleton_only.asfamc", kTinyAsf);
  out.writeBoth("trc", Format::Trc, "tiny_three_frames_crlf.trc", kTinyTrc);
  out.write("trc", "tiny_planar_sports2d.trc", kTinyPlanarTrc);
  out.writeBoth("bvh", Format::Bvh, "tiny_two_legs.bvh", kTinyBvh);
  out.writeBoth("joint_csv", Format::Csv, "tiny_gaps_comments.csv", tinyCsv());
  mappingSeeds(out);

  MatrixXd two(3, 6);
  two << 100, 900, 200, 300, 900, 200,    //
      101, 901, 201, std::nan(""), 0, 0,  //
      102, 902, 202, 302, 902, 202;
  C3dBuilder intel(C3dBuilder::Processor::Intel);
  const std::vector<C3dBuilder::Event> events = {{"Left", "Foot Strike", 0.01f},
                                                 {"Right", "Foot Off", 0.02f}};
  out.writeBoth("c3d", Format::C3d, "tiny_two_markers_events.c3d",
                intel.build({"LASI", "RASI"}, two, 100.0, true, events));
  out.write("c3d", "tiny_two_markers_int.c3d", intel.build({"LASI", "RASI"}, two, 100.0, false));
}

void modelSeeds(SeedWriter& out, const fs::path& tmp) {
  ew::PopulationOptions population;
  population.count = 3;
  population.simulation.rateHz = 50.0;
  population.simulation.cycles = 3.0;
  const auto walkers = ew::makeWalkers(ew::syntheticDataset(population));
  ew::ModelOptions options;
  options.components = 1;
  const fs::path file = tmp / "synthetic_three_walkers.ewm";
  ew::EigenwalkerModel model = ew::buildModel(walkers, options);
  model.speedsMps = {1.2, std::nullopt, 1.4};  // the optional speeds, one unknown
  ew::saveModel(model, file);
  out.write("model_file", "synthetic_three_walkers.ewm", readText(file));
  // A snippet prior of the same layout (the harness reads every input both ways): two
  // clusters over one-frame snippets.
  Eigen::MatrixXd snippets(45, 40);
  for (Eigen::Index i = 0; i < snippets.cols(); ++i)
    for (Eigen::Index r = 0; r < snippets.rows(); ++r)
      snippets(r, i) = 30.0 * static_cast<double>(i % 2) + static_cast<double>((r * 7 + i * 13) % 11);
  ew::SnippetPriorOptions snippet;
  snippet.frames = 1;
  snippet.clusters = 2;
  snippet.components = 2;
  const fs::path prior = tmp / "two_clusters.ewsp";
  ew::saveSnippetPrior(ew::fitSnippetMixture(snippets, snippet), prior);
  out.write("model_file", "two_clusters.ewsp", readText(prior));
}

// A calibration for the calibrated clip's seeds (fuzz_calibrated_clip.cpp): a 640 × 480 camera
// with a mild barrel, so that its keypoints are undistorted, not passed through.
constexpr std::string_view kClipCalibration =
    "[cam_01]\nname = \"cam_01\"\nsize = [ 640.0, 480.0]\n"
    "matrix = [ [ 600.0, 0.0, 320.0], [ 0.0, 600.0, 240.0], [ 0.0, 0.0, 1.0]]\n"
    "distortions = [ -0.05, 0.01, 0.0, 0.0]\n";

// The camera of the walking seed below (tests/camera/filmed_walk.h's, with a mild barrel).
constexpr std::string_view kWalkCalibration =
    "[side]\nname = \"side\"\nsize = [ 1920.0, 1080.0]\n"
    "matrix = [ [ 1400.0, 0.0, 960.0], [ 0.0, 1400.0, 540.0], [ 0.0, 0.0, 1.0]]\n"
    "distortions = [ -0.02, 0.005, 0.0, 0.0]\n";

std::string calibratedClip(std::string_view calibration, int reader, std::string_view keypoints) {
  return std::string(1, static_cast<char>(reader)) + std::string(calibration) + "\n%%KEYPOINTS%%\n" +
         std::string(keypoints);
}

void sharedDataSeeds(SeedWriter& out, const fs::path& data) {
  auto copy = [&](const std::string& harness, Format format, const fs::path& relative,
                  bool alsoPipeline) {
    const fs::path file = data / relative;
    if (!fs::is_regular_file(file)) return;
    const std::string name = "shared_" + file.filename().string();
    if (alsoPipeline)
      out.writeBoth(harness, format, name, readText(file));
    else
      out.write(harness, name, readText(file));
  };
  // C3D samples under 200 KB (every processor type and storage), one static and one
  // walking Schreiber-Moissenet trial.
  for (const char* f : {"c3d-samples/sample16_simi_invalid_residuals/basketball.c3d",
                        "c3d-samples/sample02_vicon370_encodings/pc_int.c3d",
                        "c3d-samples/sample02_vicon370_encodings/dec_real.c3d",
                        "c3d-samples/sample02_vicon370_encodings/sgi_int.c3d",
                        "c3d-samples/sample06_motion_analysis/MACsample.c3d",
                        "c3d-samples/sample08_header_pointers/TESTBPI.c3d",
                        "c3d-samples/sample03_vicon370_gait/gait-raw.c3d",
                        "schreiber-moissenet-2019/2014001/2014001_ST.c3d"})
    copy("c3d", Format::C3d, f, false);
  copy("c3d", Format::C3d, "schreiber-moissenet-2019/2014025/2014025_C4_04.c3d", true);
  copy("bvh", Format::Bvh, "cmu-mocap-bvh/08/08_01.bvh", true);
  copy("calibration", Format::Csv, "pose2sim-balancing/Calib_qualisys.toml", false);
  copy("calibration", Format::Csv, "video/sports2d-demo/Calib_demo.toml", false);
  const fs::path pose2sim = data / "pose2sim-balancing/pose/cam01_json/cam01.0000.json";
  if (fs::is_regular_file(pose2sim)) {
    out.write("keypoints", "shared_cam01.0000.json", std::string(1, '\0') + readText(pose2sim));
    const fs::path calib = data / "pose2sim-balancing/Calib_qualisys.toml";
    if (fs::is_regular_file(calib))
      out.write("calibrated_clip", "shared_cam01.0000.json", calibratedClip(readText(calib), 0, readText(pose2sim)));
  }
  copy("trc", Format::Trc, "pose2sim-balancing/pose-3d/S00_P00_T01_BalancingTrial_0-100.trc",
       false);
  const fs::path asf = data / "cmu-mocap-asfamc/35/35.asf",
                 amc = data / "cmu-mocap-asfamc/35/35_01.amc";
  if (fs::is_regular_file(asf) && fs::is_regular_file(amc)) {
    out.writeBoth("asf_amc", Format::AsfAmc, "shared_35_01.asfamc",
                  asfAmc(readText(asf), readText(amc)));
  }
}

// The filmed walk's OpenPose frames (tests/camera/filmed_walk.h) as one JSON list of frames.
std::string filmedWalkList(const fs::path& folder) {
  ew::test::writeFilmedOpenPose(folder, ew::test::crossingPinhole(1400, 3.0), 90, 30.0);
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(folder)) files.push_back(e.path());
  std::sort(files.begin(), files.end());
  std::string list = "[";
  for (const fs::path& f : files) list += (list.size() > 1 ? ",\n" : "") + readText(f);
  return list + "]\n";
}

// Keypoint files behind the harness's reader byte (fuzz_keypoints.cpp): an OpenPose frame of
// a walker (core's writer), AlphaPose, MMPose, MediaPipe, DeepLabCut and YOLO files written here,
// each also empty and of one frame (issue 53); every one also behind a calibration for
// fuzz_calibrated_clip.
void keypointSeeds(SeedWriter& out, const fs::path& tmp) {
  auto put = [&](int reader, const std::string& name, const std::string& text) {
    out.write("keypoints", name, std::string(1, static_cast<char>(reader)) + text);
    out.write("calibrated_clip", name, calibratedClip(kClipCalibration, reader, text));
  };
  Eigen::MatrixXd px(2, 30);
  for (int f = 0; f < 2; ++f)
    for (int j = 0; j < 15; ++j) px(f, 2 * j) = 500 + 10 * j + 40 * f, px(f, 2 * j + 1) = 200 + 40 * j;
  ew::writeOpenPoseBody25(tmp / "openpose", {{px, Eigen::MatrixXd()}});
  for (const auto& e : fs::directory_iterator(tmp / "openpose")) {
    put(0, "openpose_" + e.path().filename().string(), readText(e.path()));
    break;
  }
  std::string coco;
  for (int k = 0; k < 17; ++k) coco += (k ? "," : "") + std::to_string(300 + 5 * k) + "," + std::to_string(100 + 20 * k) + ",0.9";
  put(1, "alphapose.json", "[{\"image_id\": \"0.jpg\", \"category_id\": 1, \"keypoints\": [" + coco +
                               "], \"score\": 2.5}, {\"image_id\": \"1.jpg\", \"keypoints\": [" + coco + "], \"score\": 2.4}]");
  std::string xy, scores;
  for (int k = 0; k < 17; ++k) {
    xy += std::string(k ? "," : "") + "[" + std::to_string(300 + 5 * k) + "," + std::to_string(100 + 20 * k) + "]";
    scores += std::string(k ? "," : "") + "0.9";
  }
  put(2, "mmpose.json", "{\"meta_info\": {\"dataset_name\": \"coco\"}, \"instance_info\": [{\"frame_id\": 1, \"instances\": "
                            "[{\"keypoints\": [" + xy + "], \"keypoint_scores\": [" + scores + "]}]}]}");
  std::string header = "frame,time_s", row0 = "0,0", row1 = "1,0.033";
  for (const auto& p : ew::keypointLayoutNamed("MediaPipe-33").points) {
    header += "," + p + "_x," + p + "_y," + p + "_visibility";
    row0 += ",0.5,0.4,0.9";
    row1 += ",0.51,0.41,0.8";
  }
  put(3, "mediapipe.csv", header + "\n" + row0 + "\n" + row1 + "\n");
  put(4, "deeplabcut.csv",
      "scorer,DLC,DLC,DLC,DLC,DLC,DLC\nbodyparts,hip,hip,hip,ankle,ankle,ankle\n"
      "coords,x,y,likelihood,x,y,likelihood\n0,10,20,0.9,12,80,0.95\n1,11,20,0.9,13,80,0.2\n");
  std::string yolo = "0 0.5 0.5 0.2 0.6";
  for (int k = 0; k < 17; ++k) yolo += " " + std::to_string(0.45 + 0.005 * k) + " " + std::to_string(0.2 + 0.04 * k) + " 0.9";
  put(5, "yolo.txt", yolo + " 0.87 1\n" + yolo + " 0.62 2\n");
  // The empty result of every format (nobody detected), and one frame of each.
  put(0, "openpose_nobody.json", "{\"version\": 1.3, \"people\": []}");
  put(0, "openpose_no_frames.json", "[]");
  put(1, "alphapose_nobody.json", "[]");
  put(1, "alphapose_one_frame.json", "[{\"image_id\": \"0.jpg\", \"category_id\": 1, \"keypoints\": [" + coco +
                                         "], \"score\": 2.5}]");
  put(2, "mmpose_no_frames.json", "{\"meta_info\": {\"dataset_name\": \"coco\"}, \"instance_info\": []}");
  put(2, "mmpose_nobody.json", "[]");
  put(2, "mmpose_one_frame.json", "[{\"keypoints\": [" + xy + "], \"keypoint_scores\": [" + scores + "]}]");
  put(3, "mediapipe_header_only.csv", header + "\n");
  put(3, "mediapipe_one_frame.csv", header + "\n" + row0 + "\n");
  put(4, "deeplabcut_header_only.csv",
      "scorer,DLC,DLC,DLC\nbodyparts,hip,hip,hip\ncoords,x,y,likelihood\n");
  put(4, "deeplabcut_one_frame.csv", "scorer,DLC,DLC,DLC\nbodyparts,hip,hip,hip\ncoords,x,y,likelihood\n0,10,20,0.9\n");
  put(5, "yolo_empty.txt", "");
  put(5, "yolo_one_frame.txt", yolo + " 0.87 1\n");
  // A walk that gets through the gait cycles: the mean walker crossing a 1400 px camera for 3 s
  // at 30 fps, its OpenPose frames as one file's list, and behind that camera's calibration.
  const std::string walk = filmedWalkList(tmp / "walk");
  out.write("keypoints", "openpose_walk_list.json", std::string(1, '\0') + walk);
  out.write("calibrated_clip", "openpose_walk_list.json", calibratedClip(kWalkCalibration, 0, walk));
}

// Keyframe files (fuzz_keyframes.cpp): two whole frames of a track with a joint unseen, and one
// correction of a single joint on a named video, as the viewer saves them.
void keyframeSeeds(SeedWriter& out) {
  Eigen::MatrixXd px(60, 30);
  for (Eigen::Index f = 0; f < px.rows(); ++f)
    for (Eigen::Index c = 0; c < px.cols(); ++c) {
      const double frame = static_cast<double>(f), column = static_cast<double>(c);
      px(f, c) = c % 2 == 0 ? 120.5 + 4.0 * frame + column : 40.25 + 11.0 * column;
    }
  px.block(0, 2 * ew::index(ew::Joint::LWrist), px.rows(), 2).setConstant(std::nan(""));
  out.write("keyframes", "two_frames.json", ew::formatKeyframes(ew::keyframesFromTrack(px, {0, 45}, "walk.mp4")));
  ew::Keyframes correction;
  correction.video = "demo.mp4";
  ew::Keyframe knee;
  knee.frame = 12;
  knee.jointsPx = Eigen::RowVectorXd::Constant(30, std::nan(""));
  knee.jointsPx.segment(2 * ew::index(ew::Joint::RKnee), 2) << 412.0, 655.5;
  correction.keyframes.push_back(knee);
  out.write("keyframes", "one_correction.json", ew::formatKeyframes(correction));
}

// Calibration files (fuzz_calibration.cpp): one camera, and two with a metadata table.
void calibrationSeeds(SeedWriter& out) {
  out.write("calibration", "clip_camera.toml", kClipCalibration);
  out.write("calibration", "one_camera.toml",
            "[demo]\nname = \"demo\"\nsize = [ 1768, 994]\n"
            "matrix = [ [ 2520.0, 0.0, 884.0], [ 0.0, 2520.0, 497.0], [ 0.0, 0.0, 1.0]]\n"
            "distortions = [ 0.0, 0.0, 0.0, 0.0]\nrotation = [ 1.2, 1.2, -1.2]\ntranslation = [ -3.5, 1.7, 10.0]\n"
            "fisheye = false\n\n[metadata]\nadjusted = false\nerror = 0.0\n");
  out.write("calibration", "two_cameras.toml",
            "[cam_01] # left\nmatrix = [[1000, 0, 500], [0, 1000, 400], [0, 0, 1]]\n"
            "[cam_02]\nname = \"right\"\nmatrix = [[1500, 0, 500], [0, 1500, 400], [0, 0, 1]]\n");
}

fs::path sharedData(int argc, char** argv) {
  for (int i = 1; i + 1 < argc; ++i) {
    if (std::string(argv[i]) == "--data") return argv[i + 1];
  }
  if (const char* env = std::getenv("EIGENWALKER_DATA"); env && *env) return env;
  return EW_SHARED_DATA_DIR;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2 || std::string(argv[1]).rfind("--", 0) == 0) {
    std::fprintf(stderr, "usage: fuzz_seeds OUT_DIR [--data SHARED_DATA_DIR]\n");
    return 2;
  }
  try {
    const fs::path root = argv[1];
    SeedWriter out(root);
    for (const char* h :
         {"c3d", "bvh", "asf_amc", "trc", "qtm_tsv", "joint_csv", "model_file", "mapping_file", "pipeline",
          "keypoints", "calibration", "calibrated_clip", "keyframes"})
      out.reset(h);
    const fs::path tmp = root / ".tmp";
    fs::create_directories(tmp);
    syntheticSeeds(out, tmp);
    gaitEdgeSeeds(out, tmp);
    handMadeSeeds(out);
    modelSeeds(out, tmp);
    keypointSeeds(out, tmp);
    calibrationSeeds(out);
    keyframeSeeds(out);
    const fs::path data = sharedData(argc, argv);
    if (!data.empty() && fs::is_directory(data)) {
      sharedDataSeeds(out, data);
    } else if (const char* required = std::getenv("EIGENWALKER_REQUIRE_DATA");
               required && std::string(required) == "1") {
      std::fprintf(stderr, "fuzz_seeds: no shared data at '%s' and EIGENWALKER_REQUIRE_DATA=1\n",
                   data.string().c_str());
      return 1;
    } else {
      std::printf("fuzz_seeds: no shared data at '%s': synthetic and hand-made seeds only\n",
                  data.string().c_str());
    }
    fs::remove_all(tmp);
    std::printf("fuzz_seeds: wrote %d seeds under %s\n", out.written(), root.string().c_str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fuzz_seeds: %s\n", e.what());
    return 1;
  }
  return 0;
}
