// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/control/homing.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "radio_follow/common/angles.hpp"
#include "radio_follow/common/param_error.hpp"

namespace radio_follow {
namespace control {
namespace {

double bearingTo(const Eigen::Vector2d& from, const Eigen::Vector2d& to) {
  const Eigen::Vector2d d = to - from;
  return std::atan2(d.y(), d.x());
}

TEST(VectorEstimator, RawGoalIsEqs1And2) {
  const Eigen::Vector2d g = VectorEstimator::rawGoal({1.0, 2.0}, kPi / 2.0, 3.0);
  EXPECT_NEAR(g.x(), 1.0, 1e-12);
  EXPECT_NEAR(g.y(), 5.0, 1e-12);
}

TEST(VectorEstimator, ExponentialWeightsFavourNewest) {
  VectorEstimator estimator(1.0, 20);
  estimator.add({0.0, 0.0});
  estimator.add({1.0, 0.0});  // newest, weight 1; older weight e^-1
  const double expected = 1.0 / (1.0 + std::exp(-1.0));
  EXPECT_NEAR(estimator.estimate()->x(), expected, 1e-12);
}

TEST(VectorEstimator, KeepsOnlyWindow) {
  VectorEstimator estimator(1e9, 20);  // near-uniform weights
  for (int i = 0; i < 25; ++i) {
    estimator.add({static_cast<double>(i), 0.0});
  }
  EXPECT_EQ(estimator.size(), 20u);
  EXPECT_NEAR(estimator.estimate()->x(), 14.5, 1e-6);  // mean of 5..24
}

TEST(VectorEstimator, ZTestFlagsFarPointOnly) {
  VectorEstimator estimator(5.0, 20);
  std::mt19937 rng(3);
  std::normal_distribution<double> noise(0.0, 0.1);
  for (int i = 0; i < 20; ++i) {
    estimator.add({5.0 + noise(rng), 2.0 + noise(rng)});
  }
  EXPECT_FALSE(estimator.isOutlier({5.05, 2.0}, 1.645));
  EXPECT_TRUE(estimator.isOutlier({6.0, 2.0}, 1.645));
  EXPECT_TRUE(estimator.isOutlier({5.0, 1.0}, 1.645));
}

TEST(ParallaxEstimator, IntersectionOfTwoRaysRecoversTarget) {
  const Eigen::Vector2d target(4.0, 3.0);
  const Eigen::Vector2d r1(0.0, 0.0), r2(1.0, -0.5);
  const auto goal =
      ParallaxEstimator::intersect(r1, bearingTo(r1, target), r2, bearingTo(r2, target), 0.01);
  ASSERT_TRUE(goal);
  EXPECT_NEAR(goal->x(), 4.0, 1e-9);
  EXPECT_NEAR(goal->y(), 3.0, 1e-9);
}

TEST(ParallaxEstimator, ParallelRaysGiveNothing) {
  EXPECT_FALSE(ParallaxEstimator::intersect({0.0, 0.0}, 0.3, {1.0, 0.0}, 0.3, 0.01));
}

TEST(ParallaxEstimator, KohonenStepWithKOneProjectsOntoBearingLine) {
  // Bearing line along +x from the origin; old goal 1 m off the line.
  const Eigen::Vector2d g = ParallaxEstimator::kohonenStep({3.0, 1.0}, {0.0, 0.0}, 0.0, 1.0);
  EXPECT_NEAR(g.x(), 3.0, 1e-12);
  EXPECT_NEAR(g.y(), 0.0, 1e-12);
  const Eigen::Vector2d h = ParallaxEstimator::kohonenStep({3.0, 1.0}, {0.0, 0.0}, 0.0, 0.8);
  EXPECT_NEAR(h.y(), 0.2, 1e-12);
  const Eigen::Vector2d below = ParallaxEstimator::kohonenStep({3.0, -1.0}, {0.0, 0.0}, 0.0, 0.8);
  EXPECT_NEAR(below.y(), -0.2, 1e-12);
}

TEST(ParallaxEstimator, WaitsForBaselineThenConverges) {
  const Eigen::Vector2d target(5.0, 2.0);
  ParallaxEstimator estimator(0.8, 0.2, 0.01);
  EXPECT_FALSE(estimator.update({0.0, 0.0}, bearingTo({0.0, 0.0}, target)));
  EXPECT_FALSE(estimator.update({0.1, 0.0}, bearingTo({0.1, 0.0}, target)));  // too short
  const auto goal = estimator.update({0.5, 0.0}, bearingTo({0.5, 0.0}, target));
  ASSERT_TRUE(goal);
  EXPECT_NEAR((*goal - target).norm(), 0.0, 1e-9);
}

TEST(HomingErrorMetric, IsEq14) {
  // Goals 1 m apart, at 4 m and 5 m from the robot: 1 / 4.5.
  EXPECT_NEAR(homingErrorMetric({4.0, 0.0}, {5.0, 0.0}, {0.0, 0.0}), 1.0 / 4.5, 1e-12);
}

/// The hybrid rule of seed 000 Section 5.3 as the goal (not the fit of all readings,
/// standing_goal_test.cpp), with the node's range step.
HomingParams hybridParams() {
  HomingParams params;
  params.goal_estimator = "seed000";
  return params;
}

TEST(HybridHoming, AgreeingEstimatesReportParallax) {
  const Eigen::Vector2d target(4.0, 1.0);
  HybridHoming homing{hybridParams()};
  for (int i = 0; i < 10; ++i) {
    const Eigen::Vector2d robot(0.1 * i, 0.05 * i);
    homing.update(robot, bearingTo(robot, target), (target - robot).norm());
  }
  EXPECT_EQ(homing.source(), HomingSource::kParallax);
  EXPECT_NEAR((*homing.goal() - target).norm(), 0.0, 1e-6);
}

/// Seed 000's law as published: no step along the line of sight (HomingParams::range_step).
HomingParams paperParams() {
  HomingParams params = hybridParams();
  params.range_step = 0.0;
  return params;
}

TEST(HybridHoming, DisagreementWithConsistentVectorAverages) {
  // Distances are consistently 2 m short, so the vector goal sits 2 m before the true
  // target while parallax finds it: err > 0.3 and the vector goal is no outlier (the
  // robot sways sideways, its raw goals alternate) -> the average is reported and the
  // parallax goal is pulled to it.
  const Eigen::Vector2d target(6.0, 0.0);
  HybridHoming homing{paperParams()};
  bool saw_average = false;
  for (int i = 0; i < 8 && !saw_average; ++i) {
    const Eigen::Vector2d robot(0.0, i % 2 == 0 ? -0.5 : 0.5);
    homing.update(robot, bearingTo(robot, target), (target - robot).norm() - 2.0);
    if (homing.source() == HomingSource::kAverage) {
      saw_average = true;
      EXPECT_EQ(*homing.goal(), *homing.parallaxGoal());
      EXPECT_GT(homing.goal()->x(), 4.2);
      EXPECT_LT(homing.goal()->x(), 5.8);
    }
  }
  EXPECT_TRUE(saw_average);
}

TEST(HybridHoming, OutlyingVectorKeepsParallax) {
  const Eigen::Vector2d target(6.0, 0.0);
  HybridHoming homing{paperParams()};
  std::mt19937 rng(7);
  std::normal_distribution<double> noise(0.0, 0.05);
  Eigen::Vector2d robot(0.0, 0.0);
  for (int i = 0; i < 20; ++i) {
    robot = Eigen::Vector2d(0.0, 0.1 * i);
    homing.update(robot, bearingTo(robot, target), (target - robot).norm() + noise(rng));
  }
  const Eigen::Vector2d before = *homing.goal();
  robot.y() += 0.05;
  homing.update(robot, bearingTo(robot, target), 20.0);  // wild RSSI distance
  EXPECT_EQ(homing.source(), HomingSource::kParallax);
  EXPECT_LT((*homing.goal() - before).norm(), 0.05);
}

TEST(HybridHoming, ConvergesWithNoisyReadingsAndArrives) {
  const Eigen::Vector2d target(5.0, 3.0);
  HomingParams params;
  HybridHoming homing(params);
  std::mt19937 rng(11);
  std::normal_distribution<double> angle_noise(0.0, deg2rad(3.0));
  std::normal_distribution<double> range_noise(0.0, 0.3);
  Pose2 robot;
  for (int i = 0; i < 400; ++i) {
    const double distance = (target - robot.position()).norm();
    homing.update(robot.position(), bearingTo(robot.position(), target) + angle_noise(rng),
                  distance + range_noise(rng));
    ASSERT_TRUE(homing.goal());
    if (homing.arrived(robot.position())) {
      break;
    }
    const VelocityCommand cmd = homingVelocity(robot, *homing.goal(), params);
    const double dt = 0.1;
    robot.yaw += cmd.angular * dt;
    robot.x += cmd.linear * std::cos(robot.yaw) * dt;
    robot.y += cmd.linear * std::sin(robot.yaw) * dt;
  }
  EXPECT_TRUE(homing.arrived(robot.position()));
  EXPECT_LT((robot.position() - target).norm(), 0.6);
}

TEST(HybridHoming, ArrivalNeedsAgreementWhenBothEstimatesExist) {
  const Eigen::Vector2d target(3.0, 0.0);
  HomingParams params = paperParams();
  // With a lower threshold the averaging step pulls the parallax goal onto the (wrong)
  // vector goal and the two agree: this test is about the arrival rule, not eq 14.
  params.error_threshold = 0.3;
  HybridHoming homing{params};
  // Vector goals 1 m short of the parallax goal: the robot at the reported goal has
  // not arrived while the two disagree.
  for (int i = 0; i < 6; ++i) {
    const Eigen::Vector2d robot(0.0, i % 2 == 0 ? -0.5 : 0.5);
    homing.update(robot, bearingTo(robot, target), (target - robot).norm() - 1.0);
  }
  ASSERT_TRUE(homing.goal());
  EXPECT_FALSE(homing.arrived(*homing.goal()));
}

/// A parallax goal 0.15 m short of the beacon, then the robot drives straight at it with
/// exact readings: the bearing lines run along the path, so no Kohonen step can move the
/// goal along it; only eq 14's averaging step can.
Eigen::Vector2d goalAfterStraightApproach(double error_threshold, double range_step = 0.0) {
  const Eigen::Vector2d target(3.0, 0.0);
  const Eigen::Vector2d short_goal(2.85, 0.0);
  HomingParams params = hybridParams();
  params.error_threshold = error_threshold;
  params.range_step = range_step;
  HybridHoming homing{params};
  for (const Eigen::Vector2d& robot : {Eigen::Vector2d(0.0, -0.5), Eigen::Vector2d(0.0, 0.5)}) {
    homing.update(robot, bearingTo(robot, short_goal), (target - robot).norm());
  }
  for (double x = 0.2; x < 2.35; x += 0.1) {
    const Eigen::Vector2d robot(x, 0.0);
    homing.update(robot, bearingTo(robot, target), (target - robot).norm());
  }
  return *homing.goal();
}

TEST(HybridHoming, LowThresholdCorrectsTheParallaxErrorAlongTheLineOfSight) {
  const Eigen::Vector2d target(3.0, 0.0);
  // 0.3 (seed 000): 0.7 m from the beacon the short goal still stands.
  EXPECT_GT((goalAfterStraightApproach(0.3) - target).norm(), 0.1);
  // 0.1: averaged towards the vector goal until the two agree to 0.1 of the distance
  // (0.07 m here).
  EXPECT_LT((goalAfterStraightApproach(0.1) - target).norm(), 0.05);
}

TEST(HybridHoming, RangeStepCorrectsTheParallaxErrorAlongTheLineOfSightAtTheNodesThreshold) {
  const Eigen::Vector2d target(3.0, 0.0);
  // With eq 14 at the paper's 0.3 the range step alone pulls the short goal in.
  EXPECT_LT((goalAfterStraightApproach(0.3, 0.5) - target).norm(), 0.01);
  EXPECT_LT((goalAfterStraightApproach(0.3, HomingParams().range_step) - target).norm(), 0.01);
}

TEST(RangeStep, MovesTheGoalAlongTheLineOfSightOnly) {
  const Eigen::Vector2d robot(1.0, 1.0);
  const Eigen::Vector2d goal(4.0, 5.0);  // 5 m away
  const Eigen::Vector2d moved = rangeStep(goal, robot, 6.0, 0.5);
  EXPECT_NEAR((moved - robot).norm(), 5.5, 1e-12);
  // Still on the robot-goal line.
  const Eigen::Vector2d a = goal - robot;
  const Eigen::Vector2d b = moved - robot;
  EXPECT_NEAR(a.x() * b.y() - a.y() * b.x(), 0.0, 1e-12);
  EXPECT_EQ(rangeStep(goal, robot, 6.0, 0.0), goal);
  EXPECT_NEAR((rangeStep(goal, robot, 6.0, 1.0) - robot).norm(), 6.0, 1e-12);
  // A goal on the robot, or no distance: nothing to step along.
  EXPECT_EQ(rangeStep(robot, robot, 2.0, 0.5), robot);
  EXPECT_EQ(rangeStep(goal, robot, std::numeric_limits<double>::quiet_NaN(), 0.5), goal);
}

TEST(DistanceAlongBearing, PlacesASlantRangeFromAnotherAntennaOnTheBearingRay) {
  // Board 0.065 m ahead of the module, target 3 m ahead of the board and 0.15 m above the
  // module: the module's range is the 3-D distance from the module, not from the board.
  const Eigen::Vector2d board(0.065, 0.0);
  const Eigen::Vector2d module(0.0, 0.0);
  const Eigen::Vector2d target(3.065, 0.0);
  const double range = std::hypot((target - module).norm(), 0.15);
  EXPECT_NEAR(distanceAlongBearing(board, 0.0, module, 0.15, range), 3.0, 1e-9);
  // Sideways: the target 2 m to the board's left, the module 0.3 m behind it.
  const Eigen::Vector2d side_target(0.065, 2.0);
  const Eigen::Vector2d behind(-0.235, 0.0);
  const double side_range = std::hypot((side_target - behind).norm(), -0.4);
  EXPECT_NEAR(distanceAlongBearing(board, kPi / 2.0, behind, -0.4, side_range), 2.0, 1e-9);
  // The same antenna, on the plane: the range itself.
  EXPECT_NEAR(distanceAlongBearing(board, 1.0, board, 0.0, 2.5), 2.5, 1e-12);
}

TEST(DistanceAlongBearing, ShortOrBadRanges) {
  const Eigen::Vector2d board(0.2, 0.0);
  const Eigen::Vector2d module(0.0, 0.0);
  // Shorter than the height difference: the horizontal distance is 0, the ray's closest
  // point to the module is the board itself (the module is behind it).
  EXPECT_NEAR(distanceAlongBearing(board, 0.0, module, 0.5, 0.3), 0.0, 1e-12);
  // A module ahead of the board that the range circle around it does not let the ray
  // reach: the ray's closest point to the module.
  EXPECT_NEAR(distanceAlongBearing(board, kPi / 2.0, Eigen::Vector2d(0.5, 1.0), 0.0, 0.1), 1.0,
              1e-12);
  EXPECT_TRUE(std::isnan(distanceAlongBearing(board, 0.0, module, 0.0, -1.0)));
  EXPECT_TRUE(std::isnan(
      distanceAlongBearing(board, 0.0, module, 0.0, std::numeric_limits<double>::infinity())));
}

TEST(HybridHoming, BearingsOnlyArriveOnDistance) {
  const Eigen::Vector2d target(3.0, 0.0);
  HybridHoming homing{HomingParams()};
  const double no_distance = std::nan("");
  homing.update({0.0, -0.5}, bearingTo({0.0, -0.5}, target), no_distance);
  homing.update({0.0, 0.5}, bearingTo({0.0, 0.5}, target), no_distance);
  ASSERT_TRUE(homing.goal());
  EXPECT_FALSE(homing.vectorGoal());
  EXPECT_EQ(homing.source(), HomingSource::kParallax);
  EXPECT_TRUE(homing.arrived({2.9, 0.0}));
  EXPECT_FALSE(homing.arrived({2.0, 0.0}));
}

TEST(HomingVelocity, IsEq15) {
  HomingParams params;
  params.max_linear = 0.5;
  params.linear_gain = 100.0;
  const VelocityCommand ahead = homingVelocity(Pose2{}, {3.0, 0.0}, params);
  EXPECT_NEAR(ahead.linear, 0.5, 1e-12);
  EXPECT_NEAR(ahead.angular, 0.0, 1e-12);
  const VelocityCommand diagonal = homingVelocity(Pose2{}, {3.0, 3.0}, params);
  EXPECT_NEAR(diagonal.linear, 0.25, 1e-12);  // (2/pi) 0.5 (pi/2 - pi/4)
  EXPECT_GT(diagonal.angular, 0.0);
  EXPECT_EQ(homingVelocity(Pose2{}, {-3.0, 1.0}, params).linear, 0.0);
}

TEST(HomingParams, ValidateRejectsBadK) {
  HomingParams params;
  params.k = 1.5;
  EXPECT_THROW(params.validate(), ParamError);
  EXPECT_NO_THROW(HomingParams().validate());
}

}  // namespace
}  // namespace control
}  // namespace radio_follow

namespace radio_follow {
namespace control {
namespace {

// One NaN odometry pose used to enter the parallax estimate and make every later goal
// NaN; a non-finite reading is now refused and the estimate recovers with good data.
TEST(HybridHoming, AZeroDistanceIsAReadingANegativeOneIsNot) {
  // A sensor that clamps at zero reports 0 for every reading the noise took below it;
  // refusing those would keep only the long readings near the target.
  const Eigen::Vector2d robot(1.0, 2.0);
  HybridHoming zero{HomingParams()};
  zero.update(robot, 0.3, 0.0);
  ASSERT_TRUE(zero.vectorGoal().has_value());
  EXPECT_NEAR((*zero.vectorGoal() - robot).norm(), 0.0, 1e-12);
  HybridHoming negative{HomingParams()};
  negative.update(robot, 0.3, -0.2);
  EXPECT_FALSE(negative.vectorGoal().has_value());
  EXPECT_EQ(negative.refused(), 0u);  // the bearing still counts
}

TEST(HybridHomingInput, NonFiniteReadingIsRefusedAndTheGoalStaysFinite) {
  HomingParams params;
  HybridHoming homing(params);
  const Eigen::Vector2d target(5.0, 2.0);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (int i = 0; i < 40; ++i) {
    const Eigen::Vector2d robot(0.1 * i, 0.05 * i);
    const Eigen::Vector2d d = target - robot;
    if (i == 10) {
      homing.update(Eigen::Vector2d(nan, 0.0), std::atan2(d.y(), d.x()), d.norm());
      homing.update(robot, nan, d.norm());
    }
    homing.update(robot, std::atan2(d.y(), d.x()), d.norm());
    if (homing.goal()) {
      ASSERT_TRUE(homing.goal()->allFinite()) << "step " << i;
    }
  }
  EXPECT_EQ(homing.refused(), 2u);
  ASSERT_TRUE(homing.goal().has_value());
  EXPECT_LT((*homing.goal() - target).norm(), 0.2);
}

}  // namespace
}  // namespace control
}  // namespace radio_follow
