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

}  // namespace
}  // namespace estimation
}  // namespace radio_follow
