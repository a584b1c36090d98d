// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/evaluation/homing_trial.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "radio_follow/common/angles.hpp"
#include "radio_follow/control/homing_controller.hpp"
#include "radio_follow/sim/obstacles.hpp"

namespace radio_follow {
namespace evaluation {
namespace {

/// A controller that trusts each reading: turn towards the bearing, drive when facing it,
/// stop within 0.3 m. Enough to exercise the harness and its metrics.
HomingCommand naive(const HomingMeasurement& m) {
  HomingCommand c;
  c.goal_x = m.odom.x + m.distance * std::cos(m.odom.yaw + m.bearing);
  c.goal_y = m.odom.y + m.distance * std::sin(m.odom.yaw + m.bearing);
  c.arrived = m.distance < 0.3;
  c.angular = 2.0 * m.bearing;
  c.linear = std::abs(m.bearing) < 0.3 ? std::min(1.0, m.distance) : 0.0;
  return c;
}

TEST(HomingTrial, NoiseFreeStraightAheadIsEfficient) {
  HomingTrialConfig config;
  const HomingResult r = runHomingTrial(naive, 5.0, 0.0, HomingNoise{}, config, 1);
  EXPECT_TRUE(r.success);
  EXPECT_LT(r.final_error, 0.31);
  EXPECT_NEAR(r.goal_error, 0.0, 1e-9);
  EXPECT_GT(r.path_efficiency, 0.999);
  EXPECT_GT(r.net_velocity, 0.3);
  EXPECT_LT(r.time, 30.0);
}

TEST(HomingTrial, TheFinalPositionIsWhereTheRobotComesToRest) {
  // Full speed until "arrived" at 1 m short of the target: the base then brakes at its
  // limit and stops v^2 / (2 a) further on, where the final error is measured.
  HomingTrialConfig config;
  config.robot.max_linear = 1.0;
  config.robot.max_linear_decel = 2.0;
  const HomingStep rush = [](const HomingMeasurement& m) {
    HomingCommand c;
    c.linear = 1.0;
    c.arrived = m.distance < 1.0;
    return c;
  };
  const HomingResult r = runHomingTrial(rush, 6.0, 0.0, HomingNoise{}, config, 1);
  EXPECT_TRUE(r.success);
  // Arrived between 0.9 and 1.0 m short (0.1 m per 10 Hz cycle), then 0.25 m of braking.
  EXPECT_GT(r.final_error, 0.9 - 0.25 - 0.01);
  EXPECT_LT(r.final_error, 1.0 - 0.25 + 0.01);
}

TEST(HomingTrial, TargetBehindNeedsATurnAndCostsEfficiencyNothingElse) {
  const HomingResult r = runHomingTrial(naive, -4.0, 1.0, HomingNoise{}, HomingTrialConfig{}, 1);
  EXPECT_TRUE(r.success);
  EXPECT_GT(r.path_efficiency, 0.9);
}

TEST(HomingTrial, ControllerThatNeverArrivesFailsAtTheTimeLimit) {
  HomingTrialConfig config;
  config.time_limit = 5.0;
  const HomingResult r = runHomingTrial([](const HomingMeasurement&) { return HomingCommand{}; },
                                        3.0, 3.0, HomingNoise{}, config, 1);
  EXPECT_FALSE(r.success);
  EXPECT_NEAR(r.time, 5.0, 1e-9);
  EXPECT_TRUE(std::isnan(r.goal_error));
}

TEST(HomingTrial, NoiseIsUniformWithinTheConfiguredBounds) {
  const HomingNoise noise = seed000NoiseConfigurations()[4];  // +-20 deg, +-1 m +-20 %
  double max_angle = 0.0, max_distance = 0.0;
  HomingTrialConfig config;
  config.time_limit = 20.0;
  runHomingTrial(
      [&](const HomingMeasurement& m) {
        const double true_bearing = std::atan2(0.0 - m.odom.y, 8.0 - m.odom.x) - m.odom.yaw;
        max_angle = std::max(max_angle, std::abs(wrapAngleFast(m.bearing - true_bearing)));
        max_distance = std::max(max_distance, std::abs(m.distance - 8.0));
        return HomingCommand{};
      },
      8.0, 0.0, noise, config, 3);
  EXPECT_LE(max_angle, deg2rad(20.0) + 1e-12);
  EXPECT_GT(max_angle, deg2rad(17.0));  // 200 draws reach close to the bound
  EXPECT_LE(max_distance, 1.0 + 0.2 * 8.0 + 1e-12);
  EXPECT_GT(max_distance, 2.2);
}

TEST(HomingTrial, TargetsFillEachQuadrant) {
  const auto targets = homingTargets(10, 10.0, 1.0, 7);
  ASSERT_EQ(targets.size(), 40u);
  int q[4] = {0, 0, 0, 0};
  for (const auto& [x, y] : targets) {
    EXPECT_GE(std::hypot(x, y), 1.0);
    EXPECT_LE(std::abs(x), 10.0);
    q[(x >= 0 ? (y >= 0 ? 0 : 3) : (y >= 0 ? 1 : 2))]++;
  }
  for (int n : q)
    EXPECT_EQ(n, 10);
  EXPECT_EQ(homingTargets(10, 10.0, 1.0, 7), targets);
}

TEST(HomingTrial, SummaryAveragesSuccessfulRunsOnly) {
  HomingResult good;
  good.success = true;
  good.time = 10.0;
  good.goal_error = 0.1;
  HomingResult bad;
  bad.time = 120.0;
  const HomingSummary s = summarize({good, bad});
  EXPECT_DOUBLE_EQ(s.success_rate, 0.5);
  EXPECT_DOUBLE_EQ(s.time, 10.0);
  EXPECT_DOUBLE_EQ(s.goal_error, 0.1);
}

TEST(HomingTrial, HomingControllerReachesBeaconsInEveryQuadrantUnderTheWorstNoise) {
  // The homing_controller node's law in the loop, seed 000's noisiest configuration.
  control::HomingControllerParams params;
  params.distance_source = "uwb";
  params.homing.max_linear = 1.0;
  HomingTrialConfig config;
  config.robot.max_linear = 1.0;
  const HomingNoise noise = seed000NoiseConfigurations()[4];
  std::vector<HomingResult> results;
  int seed = 0;
  for (const auto& [x, y] : homingTargets(2, 10.0, 1.0, 11)) {
    results.push_back(runHomingTrial(homingControllerStep(params), x, y, noise, config, ++seed));
  }
  const HomingSummary s = summarize(results);
  EXPECT_DOUBLE_EQ(s.success_rate, 1.0);
  EXPECT_LT(s.goal_error, 0.4);
  EXPECT_LT(s.final_error, 0.6);
}

/// Configuration 5's mean goal error on one target set of 40, as lab homing_experiment runs it
/// (doc/homing_experiment.md): the node's shipped files, a UWB distance, the paper's speed.
double configurationFiveGoalError(const std::string& goal_estimator, std::uint64_t set) {
  HomingNodeParams node = loadHomingNodeParams(RF_CONFIG_DIR);
  node.law.distance_source = "uwb";
  node.law.homing.max_linear = 1.0;
  node.law.homing.goal_estimator = goal_estimator;
  HomingTrialConfig config;
  config.robot.max_linear = 1.0;
  const HomingNoise noise = seed000NoiseConfigurations()[4];
  const auto targets = homingTargets(10, 10.0, 1.0, set);
  std::vector<HomingResult> results;
  for (std::size_t t = 0; t < targets.size(); ++t) {
    results.push_back(runHomingTrial(homingControllerStep(node.law), targets[t].first,
                                     targets[t].second, noise, config, set * 1000 + 400 + t));
  }
  const HomingSummary s = summarize(results);
  EXPECT_DOUBLE_EQ(s.success_rate, 1.0) << goal_estimator << ", target set " << set;
  return s.goal_error;
}

TEST(HomingTrial, TheShippedGoalMeetsThePapersGoalErrorOnConfigurationFive) {
  // Issue 35: seed 000's Table 3 gives 0.11 m; the hybrid rule as the goal gave 0.13-0.16 m.
  for (std::uint64_t set = 1; set <= 5; ++set) {
    const double all_readings = configurationFiveGoalError("all_readings", set);
    EXPECT_LE(all_readings, 0.11) << "target set " << set;
    EXPECT_LT(all_readings, configurationFiveGoalError("seed000", set)) << "target set " << set;
  }
}

TEST(HomingTrial, ShippedParametersLoadStrictly) {
  const HomingNodeParams node = loadHomingNodeParams(RF_CONFIG_DIR);
  EXPECT_EQ(node.law.homing.arrival_distance, 0.3);  // the paper's radius, the node's default
  EXPECT_GT(node.pipeline.avoidance.stop_threshold, 0.0);
}

TEST(HomingTrial, ObstacleCourseBlocksTheDirectPathAndKeepsStartAndTargetClear) {
  const sim::Obstacles a = homingObstacleCourse(0.0, 0.0, 6.0, 2.0, 8, 10.0, 1.0, 5);
  const sim::Obstacles b = homingObstacleCourse(0.0, 0.0, 6.0, 2.0, 8, 10.0, 1.0, 5);
  EXPECT_EQ(a.circles.size() + a.walls.size(), 8u);
  EXPECT_EQ(a.circles.size(), b.circles.size());  // deterministic
  EXPECT_GE(sim::clearance(a, 0.0, 0.0), 1.0);
  EXPECT_GE(sim::clearance(a, 6.0, 2.0), 1.0);
  // Something lies on the straight line: a ray from the start towards the target hits it
  // before the target.
  EXPECT_LT(sim::castRay(a, 0.0, 0.0, std::atan2(2.0, 6.0)), std::hypot(6.0, 2.0));
}

// A wall across the way: blind, the law drives into it; with the scan (seed 000 Appendix
// B's rules, the node's avoidance/* defaults, a robot of the 0.2 m radius they leave room
// for) it goes round and arrives, in each of five noise seeds. The wall reaches 1.3 m to
// one side of the straight line and 0.7 m to the other: a wall centred on it is a trap
// for these reactive rules (no escape behaviour; doc/homing_experiment.md).
TEST(HomingTrial, ScanAvoidanceGoesRoundAWallThatStopsABlindRobot) {
  const HomingNodeParams node = loadHomingNodeParams(RF_CONFIG_DIR);
  control::HomingControllerParams params = node.law;
  params.distance_source = "uwb";
  params.homing.max_linear = 1.0;
  HomingTrialConfig config;
  config.robot.max_linear = 1.0;
  config.avoidance = node.pipeline.avoidance;
  config.obstacles.walls.push_back({3.0, -0.7, 3.0, 1.3});
  const HomingNoise noise = seed000NoiseConfigurations()[0];
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    config.use_scan = false;
    const HomingResult blind =
        runHomingTrial(homingControllerStep(params), 6.0, 0.0, noise, config, seed);
    EXPECT_TRUE(blind.collided) << "seed " << seed;
    EXPECT_FALSE(blind.success) << "seed " << seed;
    config.use_scan = true;
    const HomingResult seeing =
        runHomingTrial(homingControllerStep(params), 6.0, 0.0, noise, config, seed);
    EXPECT_FALSE(seeing.collided) << "seed " << seed;
    EXPECT_TRUE(seeing.success) << "seed " << seed;
    EXPECT_GT(seeing.min_clearance, 0.0) << "seed " << seed;
    EXPECT_LT(seeing.final_error, 0.5) << "seed " << seed;
  }
}

}  // namespace
}  // namespace evaluation
}  // namespace radio_follow
