// The synthetic population against the real walkers of ../shared/data/walkers.csv, on the
// quantities of docs/SYNTHETIC.md ("Synthetic vs real"): harmonic variance shares, stride
// frequency, speed, segment lengths, eigenvalue spectrum, and leave-one-subject-out
// known-view reconstruction errors at 0°, 45° and 90°. Prints the table the document
// quotes (run: build/bin/test_synth_vs_real) and checks the two populations agree where
// they should. Skips without the shared data.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numeric>

#include "core/eigenwalker/metrics.h"
#include "core/eigenwalker/projection.h"
#include "core/eigenwalker/reconstruction.h"
#include "core/eigenwalker/walker_set.h"
#include "core/synth/population.h"
#include "tests/common/test_support.h"

namespace ew {
namespace {

// [SECTION] Statistics of one population

struct MeanSd {
  double mean = 0.0, sd = 0.0;
};

MeanSd meanSd(const std::vector<double>& v) {
  MeanSd m;
  if (v.empty()) return m;
  m.mean = std::accumulate(v.begin(), v.end(), 0.0) / static_cast<double>(v.size());
  double ss = 0.0;
  for (double x : v) ss += (x - m.mean) * (x - m.mean);
  m.sd = v.size() > 1 ? std::sqrt(ss / static_cast<double>(v.size() - 1)) : 0.0;
  return m;
}

struct Segment {
  const char* name;
  Joint a, b;
};
constexpr Segment kSegments[] = {
    {"thigh", Joint::RHip, Joint::RKnee},
    {"shank", Joint::RKnee, Joint::RAnkle},
    {"upper arm", Joint::RShoulder, Joint::RElbow},
    {"forearm", Joint::RElbow, Joint::RWrist},
    {"hip width", Joint::RHip, Joint::LHip},
    {"shoulder width", Joint::RShoulder, Joint::LShoulder},
    {"pelvis-sternum", Joint::Pelvis, Joint::Sternum},
    {"sternum-head", Joint::Sternum, Joint::Head},
};
constexpr double kAngles[] = {0.0, 45.0, 90.0};
constexpr double kSigma2Mm2 = 70.0;  // METHOD §6 default (the paper's optimum)

struct PopulationStats {
  int walkers = 0;
  MeanSd h1, h2, residual, strideHz, speed;
  std::vector<MeanSd> segments;
  int components95 = 0;
  double firstThree = 0.0;                        // variance share of the first 3 eigenwalkers
  double totalVarianceMm2 = 0.0;                  // Σλ: spread of the walkers in gait space
  double meanPostureShare = 0.0;                  // … of it in the p0 block (the mean posture)
  std::vector<MeanSd> looLsq, looMap, looMapRel;  // E_a (mm²) per angle; E_r for MAP
};

double segmentLength(const Eigen::MatrixXd& m, Joint a, Joint b) {
  return (m.middleCols<3>(3 * index(a)) - m.middleCols<3>(3 * index(b))).rowwise().norm().mean();
}

void describeWalkers(const std::vector<Walker>& walkers, PopulationStats& s) {
  std::vector<double> h1, h2, res, f;
  for (const auto& w : walkers) {
    h1.push_back(w.fit.h1Share);
    h2.push_back(w.fit.h2Share);
    res.push_back(w.fit.residualShare);
    f.push_back(w.fit.omegaRadS / (2.0 * M_PI));
  }
  s.walkers = static_cast<int>(walkers.size());
  s.h1 = meanSd(h1), s.h2 = meanSd(h2), s.residual = meanSd(res), s.strideHz = meanSd(f);
}

void describeTrials(const Dataset& d, PopulationStats& s) {
  std::vector<double> speed;
  std::vector<std::vector<double>> seg(std::size(kSegments));
  for (const auto& t : d.trials) {
    speed.push_back(t.trial.speedMps);
    for (size_t k = 0; k < std::size(kSegments); ++k) {
      seg[k].push_back(segmentLength(t.trial.joints.positionsMm, kSegments[k].a, kSegments[k].b));
    }
  }
  s.speed = meanSd(speed);
  for (const auto& v : seg) s.segments.push_back(meanSd(v));
}

void describeModel(const std::vector<Walker>& walkers, PopulationStats& s) {
  const EigenwalkerModel model = buildModel(walkers);
  s.components95 = model.componentCount();
  const double total = model.spectrum.sum();
  s.firstThree =
      model.spectrum.head(std::min<Eigen::Index>(3, model.spectrum.size())).sum() / total;
  s.totalVarianceMm2 = total;
  const Eigen::MatrixXd w = walkerMatrix(walkers);
  const Eigen::MatrixXd centred = w.colwise() - w.rowwise().mean();
  const double p0 = centred.topRows(45).squaredNorm(), all = centred.squaredNorm();
  s.meanPostureShare = p0 / all;
}

// Leave-one-subject-out known-view reconstruction (METHOD §8.3), E_a and E_r per angle.
void describeLoo(const std::vector<Walker>& walkers, PopulationStats& s) {
  std::vector<std::vector<double>> lsq(std::size(kAngles)), map(std::size(kAngles)),
      mapRel(std::size(kAngles));
  for (const auto& held : walkers) {
    const EigenwalkerModel model = buildModelWithoutSubject(walkers, held.subject);
    const ModelGram gram = precomputeModelGram(model);
    for (size_t a = 0; a < std::size(kAngles); ++a) {
      const Eigen::VectorXd observed = projectToView(held.fit.w, kAngles[a]);
      const Reconstruction l = reconstructLsq(gram, observed, kAngles[a]);
      const Reconstruction m = reconstructMap(gram, observed, kAngles[a], kSigma2Mm2);
      lsq[a].push_back(depthErrors(held.fit.w, l.w, kAngles[a]).absMean);
      const DepthErrors e = depthErrors(held.fit.w, m.w, kAngles[a]);
      map[a].push_back(e.absMean);
      mapRel[a].push_back(e.relMean);
    }
  }
  for (size_t a = 0; a < std::size(kAngles); ++a) {
    s.looLsq.push_back(meanSd(lsq[a]));
    s.looMap.push_back(meanSd(map[a]));
    s.looMapRel.push_back(meanSd(mapRel[a]));
  }
}

PopulationStats describe(const Dataset& d) {
  PopulationStats s;
  std::vector<std::string> warnings;
  const std::vector<Walker> walkers = makeWalkers(d, &warnings);
  describeWalkers(walkers, s);
  describeTrials(d, s);
  describeModel(walkers, s);
  describeLoo(walkers, s);
  return s;
}

// [SECTION] Printing

std::string cell(const MeanSd& m, const char* format) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, format, m.mean, m.sd);
  return buffer;
}

void printRow(const std::string& name, const std::vector<std::string>& cells) {
  std::string row = "| " + name;
  for (const auto& c : cells) row += " | " + c;
  std::printf("%s |\n", row.c_str());
}

void printTable(const std::vector<std::pair<std::string, PopulationStats>>& pops) {
  std::string header = "| quantity";
  for (const auto& [name, s] : pops)
    header += " | " + name + " (R = " + std::to_string(s.walkers) + ")";
  std::printf("\n%s |\n|---", header.c_str());
  for (size_t k = 0; k < pops.size(); ++k) std::printf("|---");
  std::printf("|\n");
  auto row = [&](const std::string& name, auto get) {
    std::vector<std::string> cells;
    for (const auto& p : pops) cells.push_back(get(p.second));
    printRow(name, cells);
  };
  row("1st harmonic share", [](const PopulationStats& s) { return cell(s.h1, "%.3f ± %.3f"); });
  row("2nd harmonic share", [](const PopulationStats& s) { return cell(s.h2, "%.3f ± %.3f"); });
  row("residual share", [](const PopulationStats& s) { return cell(s.residual, "%.4f ± %.4f"); });
  row("stride frequency (Hz)",
      [](const PopulationStats& s) { return cell(s.strideHz, "%.3f ± %.3f"); });
  row("speed (m/s)", [](const PopulationStats& s) { return cell(s.speed, "%.2f ± %.2f"); });
  for (size_t k = 0; k < std::size(kSegments); ++k) {
    row(std::string(kSegments[k].name) + " (mm)",
        [k](const PopulationStats& s) { return cell(s.segments[k], "%.0f ± %.0f"); });
  }
  row("components for 95 %",
      [](const PopulationStats& s) { return std::to_string(s.components95); });
  row("variance in first 3", [](const PopulationStats& s) {
    char b[32];
    std::snprintf(b, sizeof b, "%.3f", s.firstThree);
    return std::string(b);
  });
  row("total variance Σλ (mm²)", [](const PopulationStats& s) {
    char b[32];
    std::snprintf(b, sizeof b, "%.0f", s.totalVarianceMm2);
    return std::string(b);
  });
  row("… share in mean posture p0", [](const PopulationStats& s) {
    char b[32];
    std::snprintf(b, sizeof b, "%.3f", s.meanPostureShare);
    return std::string(b);
  });
  for (size_t a = 0; a < std::size(kAngles); ++a) {
    const std::string angle = std::to_string(static_cast<int>(kAngles[a])) + "°";
    row("LOO E_a LSQ " + angle + " (mm²)",
        [a](const PopulationStats& s) { return cell(s.looLsq[a], "%.0f ± %.0f"); });
    row("LOO E_a MAP " + angle + " (mm²)",
        [a](const PopulationStats& s) { return cell(s.looMap[a], "%.0f ± %.0f"); });
    row("LOO E_r MAP " + angle,
        [a](const PopulationStats& s) { return cell(s.looMapRel[a], "%.3f ± %.3f"); });
  }
  std::printf("\n");
}

// [SECTION] The comparison

TEST(SynthVsReal, PrintComparisonTable) {
  EW_REQUIRE_SHARED_DATA();
  const PopulationStats real = describe(loadDataset({test::sharedDataDir() / "walkers.csv"}));
  PopulationOptions same;
  same.count = real.walkers;  // same R as the real set: model capacity comparable
  const PopulationStats synthSame = describe(syntheticDataset(same));
  const PopulationStats synthDefault = describe(syntheticDataset());
  printTable({{"real", real}, {"synthetic", synthSame}, {"synthetic default", synthDefault}});

  // Where they should agree (docs/SYNTHETIC.md explains the tolerances).
  EXPECT_NEAR(synthSame.h1.mean, real.h1.mean, 0.06);
  EXPECT_NEAR(synthSame.h2.mean, real.h2.mean, 0.05);
  EXPECT_NEAR(synthSame.strideHz.mean, real.strideHz.mean, 0.2 * real.strideHz.mean);
  EXPECT_NEAR(synthSame.segments[0].mean, real.segments[0].mean, 0.15 * real.segments[0].mean);
  EXPECT_NEAR(synthSame.segments[1].mean, real.segments[1].mean, 0.15 * real.segments[1].mean);
  for (size_t a = 0; a < std::size(kAngles); ++a) {
    // Same order of magnitude of the leave-one-out depth error.
    EXPECT_GT(synthSame.looMap[a].mean, 0.2 * real.looMap[a].mean) << kAngles[a];
    EXPECT_LT(synthSame.looMap[a].mean, 5.0 * real.looMap[a].mean) << kAngles[a];
  }
}

}  // namespace
}  // namespace ew
