// SPDX-License-Identifier: BSD-3-Clause
// The thesis's Experiments 1-2 (Sections 5.3-5.4) on the shipped configuration, short
// versions of what `lab standing_experiments` prints (doc/standing_experiments.md). The
// thresholds are the thesis's findings and the project's follow requirement, not this
// simulator's output.
#include "radio_follow/evaluation/standing_experiments.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "../../support/shipped_loop.hpp"
#include "radio_follow/common/angles.hpp"
#include "radio_follow/common/error_statistics.hpp"
#include "radio_follow/common/param_error.hpp"
#include "radio_follow/evaluation/closed_loop.hpp"
#include "radio_follow/sim/target_path.hpp"

namespace radio_follow {
namespace evaluation {
namespace {

StaticAccuracyParams shortStatic() {
  StaticAccuracyParams p;
  p.distances = {2.5};
  p.directions = 8;
  p.duration = 12.0;
  return p;
}

TEST(StandingExperiments, SectorZeroIsCentredOnStraightAhead) {
  EXPECT_EQ(sectorOf(0.0, 8), 0u);
  EXPECT_EQ(sectorOf(deg2rad(22.4), 8), 0u);
  EXPECT_EQ(sectorOf(deg2rad(-22.4), 8), 0u);
  EXPECT_EQ(sectorOf(deg2rad(22.6), 8), 1u);
  EXPECT_EQ(sectorOf(deg2rad(90.0), 8), 2u);
  EXPECT_EQ(sectorOf(kPi, 8), 4u);
  EXPECT_EQ(sectorOf(-kPi, 8), 4u);
  EXPECT_EQ(sectorOf(deg2rad(-45.0), 8), 7u);
  EXPECT_EQ(sectorOf(1.0, 1), 0u);
}

TEST(StandingExperiments, StaticParamsAreValidated) {
  StaticAccuracyParams p;
  p.distances = {};
  EXPECT_THROW(p.validate(), ParamError);
  p = StaticAccuracyParams{};
  p.duration = p.settle;
  EXPECT_THROW(p.validate(), ParamError);
  p = StaticAccuracyParams{};
  p.directions = 0;
  EXPECT_THROW(p.validate(), ParamError);
}

// Experiment 1, Spot: with the AoA cube the estimate is good in every direction (the
// thesis: errors similar in all directions, standard deviation within 0.2 m, Figures
// 5.13-5.14); the TWR modules alone, three of them close together, are far worse (its
// Figures 5.10-5.11: errors of metres where a module is blocked, spread up to 1 m).
// Real boards' bearings (issue 35) widen both: a standing person keeps a board's slowly
// varying 6 deg, so the error of the mean is one draw of it (2 sigma at 2.5 m: 0.5 m),
// and their heavy-tailed events (Student-t, scale 5 deg: 0.22 m at 2.5 m) the spread.
TEST(StandingExperiments, Experiment1SpotAoaHoldsInEveryDirectionTwrAloneDoesNot) {
  const ClosedLoopConfig c = test::shippedLoop("spot");
  const auto both = runStaticAccuracy(c.layout, c.world, c.locator, shortStatic());
  ASSERT_EQ(both.size(), 8u);
  double worst_both = 0.0;
  for (const StaticPoint& p : both) {
    EXPECT_GE(p.usable, 0.95) << "direction " << rad2deg(p.direction);
    EXPECT_LT(p.mean_error, 0.5) << "direction " << rad2deg(p.direction);
    EXPECT_LT(p.spread, 0.25) << "direction " << rad2deg(p.direction);
    worst_both = std::max(worst_both, p.mean_error);
  }
  const auto twr = runStaticAccuracy(twrOnly(c.layout), c.world, c.locator, shortStatic());
  double worst_twr = 0.0;
  for (const StaticPoint& p : twr) {
    worst_twr = std::max(worst_twr, std::isfinite(p.mean_error) ? p.mean_error : 1e9);
  }
  EXPECT_GT(worst_twr, 2.0 * worst_both);
}

TEST(StandingExperiments, RunsAreDeterministic) {
  const ClosedLoopConfig c = test::shippedLoop("cube");
  StaticAccuracyParams p = shortStatic();
  p.directions = 2;
  p.duration = 4.0;
  const auto a = runStaticAccuracy(c.layout, c.world, c.locator, p);
  const auto b = runStaticAccuracy(c.layout, c.world, c.locator, p);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].mean_error, b[i].mean_error);
    EXPECT_EQ(a[i].spread, b[i].spread);
  }
}

// Experiment 2: the person walks round the standing robot (config/scenarios/
// walk_around.yaml); the thesis shows the track held in every configuration (Figures
// 5.24-5.27). Held here: an estimate at every update after the start, over the whole
// walk a median error within the 0.3 m the follow experiments require, and in every
// direction within what a board's slowly varying error leaves at the walk's 3 m radius
// (real boards: 6 deg that decorrelates over 1.5 m of the path, so a 45 deg sector's
// median is about one draw of it; 2.5 sigma: 3 m x tan(15 deg) = 0.8 m).
TEST(StandingExperiments, Experiment2TrackHeldAllRoundForTheAoaLayouts) {
  for (const char* layout : {"spot", "cube"}) {
    const ClosedLoopConfig c = test::shippedLoop(layout);
    const sim::Scenario walk =
        sim::loadScenarioFile(std::string(RF_CONFIG_DIR) + "/scenarios/walk_around.yaml", 1);
    const auto samples =
        runWalkAround(c.layout, c.world, c.locator, walk.target, walk.duration, {});
    ASSERT_FALSE(samples.empty());
    std::vector<double> errors;
    for (const WalkSample& sample : samples) {
      if (sample.usable) {
        errors.push_back(sample.error);
      }
    }
    EXPECT_LT(quantile(errors, 0.5), 0.3) << layout;
    for (const DirectionSector& s : bySector(samples, 8)) {
      EXPECT_GE(s.usable, 0.95) << layout << " sector " << s.centre_deg;
      EXPECT_LT(s.median_error, 0.8) << layout << " sector " << s.centre_deg;
    }
  }
}

TEST(StandingExperiments, ByDistanceTakesTheWorstPoint) {
  std::vector<StaticPoint> points(3);
  points[0].distance = 1.0;
  points[0].mean_error = 0.1;
  points[0].spread = 0.05;
  points[1].distance = 1.0;
  points[1].mean_error = 0.3;
  points[1].spread = 0.02;
  points[2].distance = 2.0;
  points[2].mean_error = std::nan("");  // never usable: the worst there is
  points[2].spread = std::nan("");
  const auto rows = byDistance(points, {1.0, 2.0});
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_DOUBLE_EQ(rows[0].max_mean_error, 0.3);
  EXPECT_DOUBLE_EQ(rows[0].max_spread, 0.05);
  EXPECT_TRUE(std::isinf(rows[1].max_mean_error));
}

}  // namespace
}  // namespace evaluation
}  // namespace radio_follow
