#pragma once
// Marker trials for the readers' tests (Nexus CSV, QTM TSV): a small trial with a gap, the
// markers a reader gave compared with those written, and the 15 joints two readings map to.

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/common/trial.h"

namespace ew::test {

// Three markers over four frames from `firstFrame`, RASI gone on the third frame.
inline RawTrial threeMarkerTrial(double rateHz, long firstFrame) {
  RawTrial t;
  t.rateHz = rateHz;
  t.firstFrame = firstFrame;
  t.labels = {"LASI", "RASI", "LHEE"};
  t.positionsMm = Eigen::MatrixXd(4, 9);
  for (Eigen::Index r = 0; r < 4; ++r)
    for (Eigen::Index c = 0; c < 9; ++c)
      t.positionsMm(r, c) = 100.0 * static_cast<double>(c + 1) + 0.25 * static_cast<double>(r);
  t.positionsMm.block<1, 3>(2, 3).setConstant(std::nan(""));
  return t;
}

// The same labels (each read one with `labelPrefix` before it, e.g. Nexus's "Subject01:"),
// positions within `toleranceMm` and the same gaps, the same rate.
inline void expectSameMarkers(const RawTrial& read, const RawTrial& written, double toleranceMm,
                              const std::string& labelPrefix = "") {
  ASSERT_EQ(read.labels.size(), written.labels.size());
  for (size_t m = 0; m < read.labels.size(); ++m) EXPECT_EQ(read.labels[m], labelPrefix + written.labels[m]);
  ASSERT_EQ(read.positionsMm.rows(), written.positionsMm.rows());
  ASSERT_EQ(read.positionsMm.cols(), written.positionsMm.cols());
  for (Eigen::Index r = 0; r < read.positionsMm.rows(); ++r)
    for (Eigen::Index c = 0; c < read.positionsMm.cols(); ++c) {
      const double a = read.positionsMm(r, c), b = written.positionsMm(r, c);
      if (std::isnan(b)) {
        EXPECT_TRUE(std::isnan(a)) << r << ", " << c;
      } else {
        EXPECT_NEAR(a, b, toleranceMm) << r << ", " << c;
      }
    }
  EXPECT_DOUBLE_EQ(read.rateHz, written.rateHz);
}

// Two readings of one trial map to the same 15 joints: the same marker set, the same gaps,
// positions within 0.001 mm.
inline void expectSameJoints(const JointTrial& a, const JointTrial& b) {
  EXPECT_EQ(a.source, b.source);
  ASSERT_EQ(a.positionsMm.rows(), b.positionsMm.rows());
  EXPECT_EQ(a.positionsMm.array().isNaN().count(), b.positionsMm.array().isNaN().count());
  const Eigen::ArrayXXd apart = (a.positionsMm - b.positionsMm).array().abs();
  EXPECT_LT(apart.isNaN().select(0.0, apart).maxCoeff(), 1e-3);
}

// `text` with its first `from` made `to` (a test fails where `from` is not in it): one fault
// put into a good export.
inline std::string replacedOnce(std::string text, const std::string& from, const std::string& to) {
  const size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return at == std::string::npos ? text : text.replace(at, from.size(), to);
}

}  // namespace ew::test
