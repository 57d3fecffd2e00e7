// The guided tour says what its own views show (issue 18): step 5's J(α), for the default
// population's first walker at the step's angle, has its second dip at the depth-reversed view
// −α and far above the best fit, as the step's text says.

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "core/eigenwalker/projection.h"
#include "core/eigenwalker/reconstruction.h"
#include "core/eigenwalker/walker_set.h"
#include "core/synth/population.h"
#include "ui/app/tour.h"

namespace ew::ui {
namespace {

double stepAngle(const TourStep& step) {
  for (const auto& action : nlohmann::json::parse(step.actionsJson))
    if (action.contains("set_angle")) return action["set_angle"].get<double>();
  ADD_FAILURE() << step.title << " sets no angle";
  return 0.0;
}

TEST(Tour, TheMirrorStepsProfileShowsTheDepthReversedDipItDescribes) {
  const TourStep& step = tourSteps()[4];
  ASSERT_NE(std::string(step.title).find("mirror"), std::string::npos) << step.title;
  EXPECT_NE(std::string(step.text).find("−α"), std::string::npos);
  const double alpha = stepAngle(step);
  const std::vector<Walker> walkers = makeWalkers(syntheticDataset());
  const EigenwalkerModel model = buildModelWithoutSubject(walkers, walkers.front().subject);
  const ViewSearch search = searchViewAngle(precomputeModelGram(model), projectToView(walkers.front().fit.w, alpha),
                                            {Estimator::Map, kPaperSigma2Mm2});
  ASSERT_GE(search.minima.size(), 2u);
  EXPECT_NEAR(search.minima[0].alphaDeg, alpha, 5.0);
  EXPECT_TRUE(search.minima[1].depthReversedOfBest) << search.minima[1].alphaDeg;
  // "far above the best fit": measured 81 times on this walker at 45°.
  EXPECT_GT(search.minima[1].objective, 10.0 * search.minima[0].objective);
}

}  // namespace
}  // namespace ew::ui
