// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/ros/locator/odometry_lookup.hpp"

#include <geometry_msgs/TransformStamped.h>
#include <tf2/exceptions.h>

#include <cmath>

namespace radio_follow {

std::optional<Pose2> odometryPoseAt(const tf2::BufferCore& tf, const std::string& odom_frame,
                                    const std::string& robot_frame, const ros::Time& stamp,
                                    double tolerance) {
  geometry_msgs::TransformStamped t;
  try {
    t = tf.lookupTransform(odom_frame, robot_frame, stamp);
  } catch (const tf2::ExtrapolationException&) {
    // Newer than the newest odometry (TF lags the drivers by a few ms): that one, when close.
    try {
      t = tf.lookupTransform(odom_frame, robot_frame, ros::Time(0));
    } catch (const tf2::TransformException&) {
      return std::nullopt;
    }
    // Seconds as double: stamps 2^32 s apart overflow ros::Duration (issue 34).
    if (!(std::abs(stamp.toSec() - t.header.stamp.toSec()) <= tolerance)) {
      return std::nullopt;
    }
  } catch (const tf2::TransformException&) {
    return std::nullopt;
  }
  const auto& q = t.transform.rotation;
  Pose2 pose;
  pose.x = t.transform.translation.x;
  pose.y = t.transform.translation.y;
  pose.yaw = std::atan2(2.0 * (q.w * q.z + q.x * q.y), 1.0 - 2.0 * (q.y * q.y + q.z * q.z));
  return pose;
}

}  // namespace radio_follow
