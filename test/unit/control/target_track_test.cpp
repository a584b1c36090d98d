// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/control/target_track.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace radio_follow {
namespace control {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

TrackPoint point(const Eigen::Vector2d& robot, const Eigen::Vector2d& target,
                 const Eigen::Vector2d& velocity) {
  const std::optional<TrackPoint> p = trackPoint(robot, target, velocity);
  EXPECT_TRUE(p.has_value());
  return p.value_or(TrackPoint{});
}

TEST(TargetTrack, TakesTheLocatorsGroundVelocityAveragedOverTheWindow) {
  TargetTrack track;
  EXPECT_FALSE(track.speed(0.0).has_value());
  // The robot at (1, 1), the person 3 m to its left walking at 1.2 m/s, 0.6 of it away.
  ASSERT_TRUE(track.add(2.0, point({1.0, 1.0}, {1.0, 4.0}, {0.96, 0.72})));
  ASSERT_TRUE(track.speed(2.05).has_value());
  EXPECT_NEAR(*track.speed(2.05), 1.2, 1e-12);
  EXPECT_NEAR(*track.recedingSpeed(2.05), 0.72, 1e-12);
  // The filter's velocities jitter: the mean of the window's, no fit, no difference of
  // positions (the positions here say nothing about the speed).
  ASSERT_TRUE(track.add(2.1, point({1.0, 1.0}, {5.0, 1.0}, {1.04, 0.88})));
  EXPECT_NEAR(*track.speed(2.1), std::hypot(1.0, 0.8), 1e-12);
  // Along the newest line of sight, +x.
  EXPECT_NEAR(*track.recedingSpeed(2.1), 1.0, 1e-12);
  // Walking towards the robot: negative.
  TargetTrack towards;
  ASSERT_TRUE(towards.add(1.0, point({1.0, 1.0}, {1.0, 4.0}, {0.0, -0.5})));
  EXPECT_NEAR(*towards.recedingSpeed(1.0), -0.5, 1e-12);
}

TEST(TargetTrack, NoSpeedWithoutAVelocityOrFromOldPoints) {
  TargetTrack track;
  // No ground velocity yet (the solver estimator's first positions): NaN in the message.
  ASSERT_TRUE(track.add(1.0, point({0.0, 0.0}, {3.0, 0.0}, {kNaN, kNaN})));
  EXPECT_FALSE(track.speed(1.0).has_value());
  EXPECT_FALSE(track.recedingSpeed(1.0).has_value());
  ASSERT_TRUE(track.add(1.1, point({0.0, 0.0}, {3.0, 0.0}, {1.0, 0.0})));
  EXPECT_NEAR(*track.speed(1.1), 1.0, 1e-12) << "points without a velocity do not count";
  EXPECT_TRUE(track.speed(1.1 + TargetTrack::kWindow).has_value());
  // No newer point for longer than the window: the person may have stopped.
  EXPECT_FALSE(track.speed(1.2 + TargetTrack::kWindow).has_value());
  EXPECT_FALSE(track.recedingSpeed(1.2 + TargetTrack::kWindow).has_value());
  // A new point drops those beyond the window from the mean.
  ASSERT_TRUE(track.add(3.0, point({0.0, 0.0}, {3.0, 0.0}, {0.2, 0.0})));
  EXPECT_NEAR(*track.speed(3.0), 0.2, 1e-12);
  track.reset();
  EXPECT_FALSE(track.speed(3.0).has_value());
}

TEST(TargetTrack, OlderPointsAndNonFiniteStampsAreIgnored) {
  TargetTrack track;
  ASSERT_TRUE(track.add(1.0, point({0.0, 0.0}, {3.0, 0.0}, {1.0, 0.0})));
  EXPECT_FALSE(track.add(0.9, point({0.0, 0.0}, {3.0, 0.0}, {5.0, 0.0})));
  EXPECT_FALSE(track.add(kNaN, point({0.0, 0.0}, {3.0, 0.0}, {5.0, 0.0})));
  EXPECT_NEAR(*track.speed(1.0), 1.0, 1e-12);
}

TEST(TrackPoint, RefusesImplausiblePositionsAndForgetsImplausibleVelocities) {
  const Eigen::Vector2d walking(1.0, 0.0);
  EXPECT_FALSE(trackPoint({kNaN, 0.0}, {3.0, 0.0}, walking).has_value());
  EXPECT_FALSE(
      trackPoint({0.0, 0.0}, {3.0, std::numeric_limits<double>::infinity()}, walking).has_value());
  EXPECT_FALSE(trackPoint({0.0, 0.0}, {1e300, 0.0}, walking).has_value());
  EXPECT_FALSE(trackPoint({0.0, 0.0}, {3.0, 0.0}, std::nullopt)->velocity.has_value());
  // A velocity no person walks at, or a non-finite one, is no velocity: no feed-forward.
  for (const Eigen::Vector2d& v :
       {Eigen::Vector2d(1e300, 0.0), Eigen::Vector2d(kNaN, 1.0),
        Eigen::Vector2d(0.0, -std::numeric_limits<double>::infinity())}) {
    const std::optional<TrackPoint> p = trackPoint({0.0, 0.0}, {3.0, 0.0}, v);
    ASSERT_TRUE(p.has_value());
    EXPECT_FALSE(p->velocity.has_value()) << v.transpose();
  }
  const std::optional<TrackPoint> p = trackPoint({0.0, 0.0}, {3.0, 0.0}, Eigen::Vector2d(1.5, 0.0));
  ASSERT_TRUE(p.has_value() && p->velocity.has_value());
  EXPECT_EQ(*p->velocity, Eigen::Vector2d(1.5, 0.0));
}

// The one verdict the nodes (estimateQuality) and the lockstep loop use: an odometry part
// no robot can act on makes the estimate LOST; an unknown velocity does not.
TEST(TrackPoint, OdometryPartNoRobotCanActOnIsRefused) {
  const Eigen::Vector3d robot(10.0, 0.0, 0.0);
  const Eigen::Vector3d target(13.0, 0.0, 0.0);
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_TRUE(plausibleOdometryPart(robot, target, {1.0, 0.0, 0.0}));
  EXPECT_TRUE(plausibleOdometryPart(robot, target, {kNaN, kNaN, kNaN}));
  EXPECT_TRUE(plausibleOdometryPart(robot, target, {kNaN, 0.0, 0.0})) << "unknown on one axis";
  EXPECT_FALSE(plausibleOdometryPart(robot, target, {13.0, 0.0, 0.0})) << "faster than a sprinter";
  EXPECT_FALSE(plausibleOdometryPart(robot, target, {0.0, inf, 0.0}));
  EXPECT_FALSE(plausibleOdometryPart(robot, {1e300, 0.0, 0.0}, {1.0, 0.0, 0.0}));
  EXPECT_FALSE(plausibleOdometryPart({kNaN, 0.0, 0.0}, target, {1.0, 0.0, 0.0}));
  EXPECT_FALSE(plausibleOdometryPart(robot, {13.0, 0.0, inf}, {1.0, 0.0, 0.0}));
}

}  // namespace
}  // namespace control
}  // namespace radio_follow
