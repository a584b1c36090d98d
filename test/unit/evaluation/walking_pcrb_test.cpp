// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/evaluation/walking_pcrb.hpp"

#include <gtest/gtest.h>

#include "../../support/shipped_loop.hpp"
#include "radio_follow/common/param_error.hpp"
#include "radio_follow/evaluation/closed_loop.hpp"

namespace radio_follow {
namespace evaluation {
namespace {

// Every measurement sigma, the process noise's and the prior's standard deviations twice as
// large: the information is a quarter at every step, so the bound exactly doubles. Fails
// when the bound does not count the simulator's sigmas or the locator's process noise.
TEST(WalkingPcrb, TheBoundScalesWithTheNoiseItCounts) {
  const ClosedLoopConfig c = test::shippedLoop("tracked", sim::SensorProfile::kIdeal);
  estimation::LocatorConfig locator = c.locator;
  locator.estimator = estimation::Estimator::kSolver;  // the faster one; the bound is the same
  WalkingPcrbParams params;
  params.runs = 2;
  const WalkingPcrbResult base = runWalkingPcrb(c.layout, c.world, locator, c.locator_rate, params);

  sim::WorldConfig world = c.world;
  world.twr.sigma_scale *= 2.0;
  world.aoa.sigma_scale *= 2.0;
  locator.process_noise *= 4.0;
  params.prior_position_sigma *= 2.0;
  params.prior_velocity_sigma *= 2.0;
  const WalkingPcrbResult scaled = runWalkingPcrb(c.layout, world, locator, c.locator_rate, params);

  ASSERT_GT(base.samples, 50u);
  ASSERT_EQ(scaled.samples, base.samples);
  EXPECT_NEAR(scaled.pcrb / base.pcrb, 2.0, 1e-9);
  // tracked has no boards: both bounds count the same ranges.
  EXPECT_DOUBLE_EQ(base.pcrb_in_fov, base.pcrb);
  EXPECT_GT(base.rmse, 0.0);
}

// Bearings of boards that do not face the person are information too: the bound that counts
// them is the tighter one.
TEST(WalkingPcrb, EveryBearingCountedTightensTheBound) {
  const ClosedLoopConfig c = test::shippedLoop("spot", sim::SensorProfile::kIdeal);
  estimation::LocatorConfig locator = c.locator;
  locator.estimator = estimation::Estimator::kSolver;
  WalkingPcrbParams params;
  params.runs = 2;
  params.shape = WalkShape::kArc;
  const WalkingPcrbResult r = runWalkingPcrb(c.layout, c.world, locator, c.locator_rate, params);
  ASSERT_GT(r.samples, 50u);
  EXPECT_LT(r.pcrb, r.pcrb_in_fov);
}

TEST(WalkingPcrb, ParsesItsShapes) {
  for (const WalkShape shape : {WalkShape::kStraight, WalkShape::kArc, WalkShape::kModel}) {
    EXPECT_EQ(parseWalkShape(toString(shape), "--paths"), shape);
  }
  EXPECT_THROW(parseWalkShape("zigzag", "--paths"), ParamError);
}

}  // namespace
}  // namespace evaluation
}  // namespace radio_follow
