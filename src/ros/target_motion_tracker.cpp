// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/ros/target_motion_tracker.hpp"

#include <tf2/exceptions.h>
#include <tf2_geometry_msgs/tf2_geometry_msgs.h>

#include <utility>

namespace radio_follow {

TargetMotionTracker::TargetMotionTracker(const tf2_ros::Buffer& buffer, std::string odom_frame,
                                         double tf_timeout)
    : buffer_(buffer), odom_frame_(std::move(odom_frame)), tf_timeout_(tf_timeout) {}

std::optional<Eigen::Vector2d> TargetMotionTracker::add(const TargetEstimate& estimate) {
  if (estimate.status != TargetEstimate::STATUS_OK &&
      estimate.status != TargetEstimate::STATUS_DEGRADED) {
    last_error_.clear();
    return std::nullopt;  // a HEADING_ONLY position is a guess along the bearing
  }
  try {
    const geometry_msgs::TransformStamped t = buffer_.lookupTransform(
        odom_frame_, estimate.header.frame_id, estimate.header.stamp, tf_timeout_);
    geometry_msgs::Point target;
    tf2::doTransform(estimate.position, target, t);
    robot_ = {t.transform.translation.x, t.transform.translation.y};
    target_ = {target.x, target.y};
    motion_.add(estimate.header.stamp.toSec(), target_);
    last_error_.clear();
    return target_;
  } catch (const tf2::TransformException& e) {
    last_error_ = e.what();
    return std::nullopt;
  }
}

std::optional<double> TargetMotionTracker::speed(const ros::Time& now) const {
  const std::optional<Eigen::Vector2d> v = motion_.velocity(now.toSec());
  if (!v) {
    return std::nullopt;
  }
  return v->norm();
}

std::optional<double> TargetMotionTracker::recedingSpeed(const ros::Time& now) const {
  const std::optional<Eigen::Vector2d> v = motion_.velocity(now.toSec());
  const Eigen::Vector2d line = target_ - robot_;
  if (!v || !(line.norm() > 1e-6)) {
    return std::nullopt;
  }
  return v->dot(line.normalized());
}

}  // namespace radio_follow
