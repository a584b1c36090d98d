// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/estimation/odometry_estimate.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace radio_follow {
namespace estimation {
namespace {

Pose2 pose(double x, double y, double yaw) {
  Pose2 p;
  p.x = x;
  p.y = y;
  p.yaw = yaw;
  return p;
}

TEST(OdometryEstimate, TheParticleEstimatorsOwnStateAsItIs) {
  LocatorEstimate e;
  e.status = TargetStatus::kOk;
  e.stamp = 5.0;
  e.in_odom = true;
  e.robot_pose = pose(1.0, 2.0, 0.5);
  e.tracking_position = Eigen::Vector3d(4.0, 6.0, 0.0);
  e.tracking_velocity = Eigen::Vector3d(0.8, -0.3, 0.0);
  int asked = 0;
  const auto o = inOdometry(e, [&](double) {
    ++asked;
    return std::optional<Pose2>();
  });
  ASSERT_TRUE(o.has_value());
  EXPECT_EQ(asked, 0) << "no lookup: the filter tracks in odometry already";
  EXPECT_EQ(o->robot, Eigen::Vector2d(1.0, 2.0));
  EXPECT_EQ(o->position, e.tracking_position);
  ASSERT_TRUE(o->velocity.has_value());
  EXPECT_EQ(*o->velocity, e.tracking_velocity);
}

TEST(OdometryEstimate, TheSolversPositionPlacedWithThePoseAtItsStampWithoutVelocity) {
  LocatorEstimate e;
  e.status = TargetStatus::kDegraded;
  e.stamp = 7.25;
  e.position = Eigen::Vector3d(2.0, 0.0, 0.3);
  e.velocity = Eigen::Vector3d(1.0, 0.0, 0.0);  // relative to the robot: not a ground velocity
  double asked_at = 0.0;
  const auto o = inOdometry(e, [&](double t) {
    asked_at = t;
    return std::optional<Pose2>(pose(1.0, -1.0, M_PI / 2.0));
  });
  ASSERT_TRUE(o.has_value());
  EXPECT_DOUBLE_EQ(asked_at, 7.25);
  EXPECT_EQ(o->robot, Eigen::Vector2d(1.0, -1.0));
  EXPECT_NEAR(o->position.x(), 1.0, 1e-12);
  EXPECT_NEAR(o->position.y(), 1.0, 1e-12);
  EXPECT_FALSE(o->velocity.has_value());
}

TEST(OdometryEstimate, NothingWhenLostWithoutAPoseOrNotFinite) {
  LocatorEstimate e;
  e.status = TargetStatus::kLost;
  const PoseAt origin = [](double) { return std::optional<Pose2>(Pose2{}); };
  EXPECT_FALSE(inOdometry(e, origin).has_value());
  e.status = TargetStatus::kOk;
  EXPECT_TRUE(inOdometry(e, origin).has_value());
  EXPECT_FALSE(inOdometry(e, [](double) { return std::optional<Pose2>(); }).has_value());
  EXPECT_FALSE(inOdometry(e, nullptr).has_value());
  e.position.x() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(inOdometry(e, origin).has_value());
  // A non-finite velocity is an unknown one, the position still holds.
  e.in_odom = true;
  e.tracking_velocity.y() = std::numeric_limits<double>::infinity();
  const auto o = inOdometry(e, origin);
  ASSERT_TRUE(o.has_value());
  EXPECT_FALSE(o->velocity.has_value());
}

/// A solver estimate (robot frame, no ground velocity) at `t` of a target walking at
/// 1 m/s along odometry x from (3, 1), seen by a robot that drives and turns.
LocatorEstimate walkingTarget(double t, Pose2* robot) {
  *robot = pose(0.5 * t, 0.2 * t, 0.3 * t);
  LocatorEstimate e;
  e.status = TargetStatus::kOk;
  e.stamp = t;
  e.position = robot->fromFixed(Eigen::Vector3d(3.0 + t, 1.0, 0.0));
  e.velocity = Eigen::Vector3d(5.0, 5.0, 0.0);  // relative to the robot: never used
  return e;
}

TEST(OdometryTrack, FitsTheSolversGroundVelocityFromItsOdometryPositions) {
  OdometryTrack track;
  Pose2 robot;
  const PoseAt at = [&robot](double) { return std::optional<Pose2>(robot); };
  std::optional<OdometryEstimate> o;
  for (int k = 0; k < 4; ++k) {
    o = track.update(walkingTarget(0.1 * k, &robot), at);
    ASSERT_TRUE(o.has_value());
    EXPECT_FALSE(o->velocity.has_value()) << "fewer than five positions: no velocity";
  }
  for (int k = 4; k <= 20; ++k) {
    const LocatorEstimate e = walkingTarget(0.1 * k, &robot);
    o = track.update(e, at);
    // The same stamp again (no new measurement) adds nothing.
    o = track.update(e, at);
  }
  ASSERT_TRUE(o.has_value() && o->velocity.has_value());
  EXPECT_NEAR(o->velocity->x(), 1.0, 1e-9);
  EXPECT_NEAR(o->velocity->y(), 0.0, 1e-9);
  EXPECT_NEAR(o->position.x(), 5.0, 1e-9);
}

TEST(OdometryTrack, TheParticleEstimatorsVelocityAsItIsAndAClockJumpStartsAnew) {
  OdometryTrack track;
  Pose2 robot;
  const PoseAt at = [&robot](double) { return std::optional<Pose2>(robot); };
  for (int k = 0; k <= 10; ++k) {
    track.update(walkingTarget(100.0 + 0.1 * k, &robot), at);
  }
  ASSERT_TRUE(track.update(walkingTarget(101.1, &robot), at)->velocity.has_value());
  // The clock went back: the old positions say nothing about the new ones.
  EXPECT_FALSE(track.update(walkingTarget(1.0, &robot), at)->velocity.has_value());

  LocatorEstimate e;
  e.status = TargetStatus::kOk;
  e.stamp = 1.2;
  e.in_odom = true;
  e.tracking_velocity = Eigen::Vector3d(0.4, 0.1, 0.0);
  const auto o = track.update(e, at);
  ASSERT_TRUE(o.has_value() && o->velocity.has_value());
  EXPECT_EQ(*o->velocity, e.tracking_velocity);
}

}  // namespace
}  // namespace estimation
}  // namespace radio_follow
