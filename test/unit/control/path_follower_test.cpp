// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/control/path_follower.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "radio_follow/common/angles.hpp"

namespace radio_follow {
namespace control {
namespace {

TEST(PathBuffer, KeepsPointsAtLeastMinSpacingApart) {
  PathBuffer path(0.1, 100);
  EXPECT_TRUE(path.add({0.0, 0.0}));
  EXPECT_FALSE(path.add({0.05, 0.0}));
  EXPECT_TRUE(path.add({0.1, 0.0}));
  EXPECT_FALSE(path.add({std::nan(""), 0.0}));
  EXPECT_EQ(path.points().size(), 2u);
}

TEST(PathBuffer, DropsOldestBeyondCapacity) {
  PathBuffer path(0.1, 3);
  for (int i = 0; i < 5; ++i) {
    path.add({static_cast<double>(i), 0.0});
  }
  ASSERT_EQ(path.points().size(), 3u);
  EXPECT_DOUBLE_EQ(path.points().front().x(), 2.0);
}

TEST(PathBuffer, PrunesPassedPointsButKeepsNewest) {
  PathBuffer path(0.1, 100);
  for (int i = 0; i <= 10; ++i) {
    path.add({0.5 * i, 0.0});
  }
  path.prune({2.1, 0.05}, 0.2);  // nearest is x = 2.0, reached: drop through it
  EXPECT_DOUBLE_EQ(path.points().front().x(), 2.5);
  path.prune({100.0, 0.0}, 0.2);
  ASSERT_EQ(path.points().size(), 1u);
  EXPECT_DOUBLE_EQ(path.points().front().x(), 5.0);
}

TEST(PathBuffer, LengthAlongPathFromRobot) {
  PathBuffer path(0.1, 100);
  path.add({1.0, 0.0});
  path.add({1.0, 2.0});
  path.add({3.0, 2.0});
  EXPECT_NEAR(path.lengthFrom({0.0, 0.0}), 1.0 + 2.0 + 2.0, 1e-12);
}

TEST(PurePursuit, StraightAheadHasZeroCurvature) {
  const std::deque<Eigen::Vector2d> path = {{0.5, 0.0}, {1.0, 0.0}, {2.0, 0.0}};
  const PursuitTarget t = purePursuit(path, Pose2{}, 0.8);
  ASSERT_TRUE(t.valid);
  EXPECT_DOUBLE_EQ(t.point.x(), 1.0);
  EXPECT_NEAR(t.curvature, 0.0, 1e-12);
}

TEST(PurePursuit, CurvatureOfArcThroughGoal) {
  // Goal 1 m ahead, 1 m left: the circle through robot and goal tangent to x has r = 1.
  const std::deque<Eigen::Vector2d> path = {{1.0, 1.0}};
  const PursuitTarget t = purePursuit(path, Pose2{}, 0.5);
  EXPECT_NEAR(t.curvature, 1.0, 1e-12);
}

TEST(PurePursuit, GoalExpressedInRobotFrame) {
  Pose2 robot;
  robot.x = 1.0;
  robot.y = 1.0;
  robot.yaw = kPi / 2.0;
  const std::deque<Eigen::Vector2d> path = {{1.0, 3.0}};
  const PursuitTarget t = purePursuit(path, robot, 1.0);
  EXPECT_NEAR(t.local.x(), 2.0, 1e-12);
  EXPECT_NEAR(t.local.y(), 0.0, 1e-12);
  EXPECT_NEAR(t.curvature, 0.0, 1e-12);
}

TEST(PurePursuit, EmptyPathIsInvalid) {
  EXPECT_FALSE(purePursuit({}, Pose2{}, 1.0).valid);
}

// The person 4 m ahead: the law drives straight at them until it has a path, and says why.
TEST(PathFollowLaw, DrivesStraightWithoutOdometryOrBeforeTheFirstPathPoint) {
  TargetPolar ahead;
  ahead.range = 4.0;
  PathFollowLaw law{PathFollowParams{}, VelocityLawParams{}};
  LawOutput out = law.step(ahead, std::nullopt, std::nullopt, 0.05);
  EXPECT_EQ(out.text, "No odometry, driving straight to the target.");
  out = law.step(ahead, Pose2{}, std::nullopt, 0.05);
  EXPECT_EQ(out.text, "No path yet, driving straight to the target.");
  EXPECT_GT(out.command.linear, 0.0);
  ASSERT_TRUE(law.addTarget(Eigen::Vector2d(4.0, 0.0)));
  out = law.step(ahead, Pose2{}, std::nullopt, 0.05);
  EXPECT_EQ(out.text.find("driving straight"), std::string::npos) << out.text;
  EXPECT_GT(out.command.linear, 0.0);
}

TEST(PathFollowLaw, SlowsForADegradedEstimateOnlyWhenItCannotSteerByIt) {
  const VelocityLawParams law_params;
  TargetPolar far;
  far.range = 6.0;
  far.degraded = true;
  far.range_sigma = 0.05;
  far.bearing_sigma = 0.12;  // 7 deg: 0.19 m sideways at the follow distance
  const auto speed = [&](const TargetPolar& t, std::string* text) {
    PathFollowLaw law{PathFollowParams{}, law_params};
    EXPECT_TRUE(law.addTarget(Eigen::Vector2d(6.0, 0.0)));
    const LawOutput out = law.step(t, Pose2{}, 1.0, 0.05);
    *text = out.text;
    return out.command.linear;
  };
  std::string text;
  TargetPolar ok = far;
  ok.degraded = false;
  const double full = speed(ok, &text);
  EXPECT_EQ(text, "Following the path.");
  EXPECT_GT(full, 1.0);
  EXPECT_NEAR(speed(far, &text), full, 1e-12);
  EXPECT_EQ(text, "Following the path, the direction is approximate.");
  TargetPolar mirror = far;
  mirror.mirror = true;
  EXPECT_NEAR(speed(mirror, &text), law_params.degraded_speed_factor * full, 1e-12);
  EXPECT_EQ(text, "Following the path slowly, the target may be at its mirror image.");
}

TEST(PathFollowLaw, NeverDrivesIntoTheStopMarginAndWaitsOnceArrived) {
  const VelocityLawParams law_params;
  const auto speed = [&](double range, double module_gap, double walking, bool after_arrival) {
    PathFollowLaw law{PathFollowParams{}, law_params};
    EXPECT_TRUE(law.addTarget(Eigen::Vector2d(range, 0.0)));
    TargetPolar t;
    t.module_gap = module_gap;
    if (after_arrival) {
      t.range = law_params.follow_distance - 0.05;
      law.step(t, Pose2{}, 0.0, 0.05);
      EXPECT_EQ(law.step(t, Pose2{}, 0.0, 0.05).state, FollowerState::kArrived);
    }
    t.range = range;
    return law.step(t, Pose2{}, walking, 0.05).command.linear;
  };
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_GT(speed(3.0, inf, 1.0, false), 0.0);
  EXPECT_EQ(speed(3.0, 0.05, 1.0, false), 0.0);  // the raw range says: at the stop
  const double d = law_params.follow_distance;
  EXPECT_EQ(speed(d + 0.05, inf, 0.15, true), 0.0);  // noise, the person stands
  EXPECT_GT(speed(d + kArrivalHysteresis + 0.05, inf, 0.15, true), 0.0);
}

}  // namespace
}  // namespace control
}  // namespace radio_follow
