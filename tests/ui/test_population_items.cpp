// The viewer's multi-item load (ui/app/population.cpp): an .asf dropped together with one of
// its .amc files is that one trial, not the trial twice plus every other motion beside it.

#include <gtest/gtest.h>

#include "tests/common/test_support.h"
#include "ui/app/population.h"

namespace ew::ui {
namespace {

TEST(PopulationItems, AsfDroppedWithItsAmcIsOneTrial) {
  EW_REQUIRE_SHARED_DATA();
  const auto folder = test::sharedDataDir() / "cmu-mocap-asfamc" / "35";
  // minWalkers 1: the items are inspected, not a leave-one-out population.
  const Population both =
      loadPopulation({folder / "35.asf", folder / "35_01.amc"}, {}, {}, /*minWalkers=*/1);
  EXPECT_EQ(both.walkerCount(), 1) << both.label;
  const Population reversed =
      loadPopulation({folder / "35_01.amc", folder / "35.asf"}, {}, {}, /*minWalkers=*/1);
  EXPECT_EQ(reversed.walkerCount(), 1) << reversed.label;
}

}  // namespace
}  // namespace ew::ui
