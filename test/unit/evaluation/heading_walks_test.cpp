// SPDX-License-Identifier: BSD-3-Clause
// Issue 35's single-board bench (runHeadingWalks): what it counts and that a seed repeats it.
#include "radio_follow/evaluation/heading_walks.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "../../support/shipped_loop.hpp"
#include "radio_follow/common/error_statistics.hpp"
#include "radio_follow/common/param_error.hpp"
#include "radio_follow/evaluation/closed_loop.hpp"

namespace radio_follow {
namespace evaluation {
namespace {

TEST(HeadingWalks, JudgesEveryUpdateAgainstTheNewestRawReading) {
  const ClosedLoopConfig c = test::shippedLoop("spot", sim::SensorProfile::kIdeal);
  HeadingWalkParams params;
  params.walks = 4;
  params.duration = 20.0;
  const HeadingWalkResult r = runHeadingWalks(c.layout, c.world, c.locator, params);
  EXPECT_EQ(r.walks, 4);
  // 20 Hz after the 2 s settle: 361 updates per walk.
  EXPECT_EQ(r.updates, 4u * 361u);
  EXPECT_EQ(r.locator_deg.size() + r.without_direction, r.updates);
  EXPECT_EQ(r.raw_deg.size(), r.locator_deg.size());
  // The thesis's tables: a few degrees in front of a board, either way.
  EXPECT_LT(quantile(r.raw_deg, 0.5), 5.0);
  EXPECT_LT(quantile(r.locator_deg, 0.5), 5.0);
  EXPECT_GE(*std::min_element(r.raw_deg.begin(), r.raw_deg.end()), 0.0);

  const HeadingWalkResult again = runHeadingWalks(c.layout, c.world, c.locator, params);
  EXPECT_EQ(again.locator_deg, r.locator_deg) << "a seed repeats the walks and the noise";
  params.seed = 2;
  EXPECT_NE(runHeadingWalks(c.layout, c.world, c.locator, params).raw_deg, r.raw_deg);
}

TEST(HeadingWalks, RefusesAPersonBehindTheBoardAndALayoutWithoutOne) {
  const ClosedLoopConfig c = test::shippedLoop("spot", sim::SensorProfile::kIdeal);
  HeadingWalkParams params;
  params.max_direction = 2.0;  // beyond 90 deg: behind the board
  EXPECT_THROW(runHeadingWalks(c.layout, c.world, c.locator, params), ParamError);
  Layout no_board = c.layout;
  no_board.aoa_boards.clear();
  EXPECT_THROW(runHeadingWalks(no_board, c.world, c.locator, HeadingWalkParams{}), ParamError);
}

}  // namespace
}  // namespace evaluation
}  // namespace radio_follow
