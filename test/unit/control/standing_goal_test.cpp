// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/control/standing_goal.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "radio_follow/common/angles.hpp"
#include "radio_follow/control/homing.hpp"

namespace radio_follow {
namespace control {
namespace {

double bearingTo(const Eigen::Vector2d& from, const Eigen::Vector2d& to) {
  const Eigen::Vector2d d = to - from;
  return std::atan2(d.y(), d.x());
}

/// Seed 000's configuration 5 noise (Table 2): bearing +-20 deg, distance +-1 m and
/// +-20 %, uniform; a distance the noise takes below zero reads zero.
struct Config5Noise {
  std::mt19937 rng;
  std::uniform_real_distribution<double> unit{-1.0, 1.0};

  explicit Config5Noise(unsigned seed) : rng(seed) {}
  double bearing(double truth) { return truth + deg2rad(20.0) * unit(rng); }
  double distance(double truth) {
    return std::max(0.0, truth * (1.0 + 0.2 * unit(rng)) + unit(rng));
  }
};

/// The robot drives straight from the origin to 0.3 m short of `target`, one reading
/// per 0.1 m (a homing run's last approach, where the bearings say nothing along it).
template <typename Estimator>
void straightApproach(const Eigen::Vector2d& target, Config5Noise& noise, Estimator&& feed) {
  const Eigen::Vector2d direction = target.normalized();
  for (double s = 0.0; s < target.norm() - 0.3; s += 0.1) {
    const Eigen::Vector2d robot = s * direction;
    feed(robot, noise.bearing(bearingTo(robot, target)), noise.distance((target - robot).norm()));
  }
}

TEST(StandingGoal, EveryReadingBeatsTheHybridRuleOnAStraightApproach) {
  // Seed 000's configuration 5: the hybrid rule's goal error is over its 0.11 m.
  double fit_error = 0.0, hybrid_error = 0.0, along_error = 0.0;
  const int trials = 200;
  for (int trial = 0; trial < trials; ++trial) {
    const Eigen::Vector2d target(6.0 + 0.01 * trial, 2.0);
    Config5Noise noise(static_cast<unsigned>(trial) + 1);
    StandingGoalEstimator fit;
    HomingParams params;
    params.goal_estimator = "seed000";
    HybridHoming hybrid(params);
    straightApproach(target, noise, [&](const Eigen::Vector2d& robot, double b, double d) {
      fit.add(robot, b, d);
      hybrid.update(robot, b, d);
    });
    ASSERT_TRUE(hybrid.goal());
    const auto goal = fit.solve(*hybrid.goal());
    ASSERT_TRUE(goal);
    fit_error += (*goal - target).norm() / trials;
    hybrid_error += (*hybrid.goal() - target).norm() / trials;
    along_error += (*goal - target).dot(target.normalized()) / trials;
  }
  EXPECT_LT(fit_error, 0.11);
  EXPECT_LT(fit_error, 0.8 * hybrid_error);
  // The zeros near the target are censored, not zero: no pull towards the robot.
  EXPECT_LT(std::abs(along_error), 0.03);
}

TEST(StandingGoal, ExactReadingsGiveTheTarget) {
  const Eigen::Vector2d target(3.0, -4.0);
  StandingGoalEstimator fit;
  for (int i = 0; i < 20; ++i) {
    const Eigen::Vector2d robot(0.1 * i, 0.02 * i * i);
    ASSERT_TRUE(fit.add(robot, bearingTo(robot, target), (target - robot).norm()));
  }
  const auto goal = fit.solve(Eigen::Vector2d(1.0, -1.0));
  ASSERT_TRUE(goal);
  EXPECT_LT((*goal - target).norm(), 1e-3);
}

TEST(StandingGoal, BearingsAlongOneLineWithoutDistancesFixNoGoal) {
  const Eigen::Vector2d target(5.0, 0.0);
  StandingGoalEstimator fit;
  const double none = std::numeric_limits<double>::quiet_NaN();
  for (int i = 0; i < 20; ++i) {
    const Eigen::Vector2d robot(0.1 * i, 0.0);
    fit.add(robot, bearingTo(robot, target), none);
  }
  EXPECT_FALSE(fit.solve(Eigen::Vector2d(4.0, 0.0)));
  // A sideways baseline fixes it.
  for (int i = 0; i < 20; ++i) {
    const Eigen::Vector2d robot(2.0, 0.1 * i);
    fit.add(robot, bearingTo(robot, target), none);
  }
  const auto goal = fit.solve(Eigen::Vector2d(4.0, 0.0));
  ASSERT_TRUE(goal);
  EXPECT_LT((*goal - target).norm(), 1e-3);
}

TEST(StandingGoal, AReflectionDoesNotPullTheGoal) {
  const Eigen::Vector2d target(4.0, 2.0);
  StandingGoalEstimator fit;
  std::mt19937 rng(3);
  std::normal_distribution<double> angle(0.0, deg2rad(5.0));
  std::normal_distribution<double> range(0.0, 0.1);
  for (int i = 0; i < 60; ++i) {
    const Eigen::Vector2d robot(0.05 * i, 0.02 * i);
    fit.add(robot, bearingTo(robot, target) + angle(rng), (target - robot).norm() + range(rng));
  }
  const auto before = fit.solve(target);
  ASSERT_TRUE(before);
  // One reading off a wall: 90 deg and 6 m wrong.
  fit.add(Eigen::Vector2d(3.0, 1.2), bearingTo(Eigen::Vector2d(3.0, 1.2), target) + kPi / 2.0,
          7.0);
  const auto after = fit.solve(*before);
  ASSERT_TRUE(after);
  EXPECT_LT((*after - *before).norm(), 0.02);
}

TEST(StandingGoal, RefusesReadingsThatAreNoReadingsAndKeepsTheNewest) {
  StandingGoalEstimator fit;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_FALSE(fit.add(Eigen::Vector2d(nan, 0.0), 0.0, 1.0));
  EXPECT_FALSE(fit.add(Eigen::Vector2d(0.0, 0.0), inf, 1.0));
  EXPECT_FALSE(fit.add(Eigen::Vector2d(0.0, 0.0), 0.0, -1.0));
  EXPECT_FALSE(fit.add(Eigen::Vector2d(0.0, 0.0), 0.0, inf));
  EXPECT_EQ(fit.size(), 0u);
  EXPECT_TRUE(fit.add(Eigen::Vector2d(0.0, 0.0), 0.0, nan));  // a bearing without distance
  for (std::size_t i = 0; i < StandingGoalEstimator::kMaxReadings + 10; ++i) {
    fit.add(Eigen::Vector2d(0.0, 0.0), 0.0, 1.0);
  }
  EXPECT_EQ(fit.size(), StandingGoalEstimator::kMaxReadings);
  EXPECT_FALSE(fit.solve(Eigen::Vector2d(nan, 0.0)));
}

TEST(HybridHoming, TheFitOfAllReadingsTakesOverOnceTheHybridRuleHasAGoal) {
  const Eigen::Vector2d target(4.0, 1.0);
  HybridHoming homing{HomingParams()};  // the node's default: all_readings
  for (int i = 0; i < 10; ++i) {
    const Eigen::Vector2d robot(0.1 * i, 0.05 * i);
    homing.update(robot, bearingTo(robot, target), (target - robot).norm());
  }
  EXPECT_EQ(homing.source(), HomingSource::kAllReadings);
  EXPECT_LT((*homing.goal() - target).norm(), 1e-3);
  // The arrival rule is seed 000's: near the goal, the goal agreeing with the vector goal.
  EXPECT_TRUE(homing.arrived(target + Eigen::Vector2d(0.2, 0.0)));
  EXPECT_FALSE(homing.arrived(target + Eigen::Vector2d(0.4, 0.0)));
}

}  // namespace
}  // namespace control
}  // namespace radio_follow
