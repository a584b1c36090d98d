// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <ros/ros.h>
#include <tf2_ros/buffer.h>

#include <Eigen/Core>
#include <optional>
#include <string>

#include "radio_follow/TargetEstimate.h"
#include "radio_follow/control/follow_inputs.hpp"
#include "radio_follow/control/target_motion.hpp"

namespace radio_follow {

/// Follows the target's estimates in the odometry frame: the path follower stores them as
/// the person's path, and both followers take the person's ground velocity from them as
/// a speed feed-forward (control::TargetMotion says why a world frame).
class TargetMotionTracker {
 public:
  TargetMotionTracker(const tf2_ros::Buffer& buffer, std::string odom_frame, double tf_timeout);

  /// Transforms a track point (control::TrackGate: OK, or DEGRADED in a confirmed
  /// track) into the odometry frame at its stamp (or with the newest transform when that
  /// is within `tf_timeout` of the stamp; it never waits for TF) and records it. Returns
  /// the target's odometry-frame position, or nullopt (not a track point, lastError()
  /// empty; or no transform, lastError() says why).
  std::optional<Eigen::Vector2d> add(const TargetEstimate& estimate);

  /// The target's ground speed, m/s, or nullopt without enough recent positions.
  std::optional<double> speed(const ros::Time& now) const;
  /// Its component along the line of sight from the robot (at the last recorded estimate)
  /// to the target: positive when the target walks away, m/s.
  std::optional<double> recedingSpeed(const ros::Time& now) const;

  void reset() { track_.reset(); }
  const std::string& lastError() const { return last_error_; }
  const std::string& odomFrame() const { return odom_frame_; }

 private:
  const tf2_ros::Buffer& buffer_;
  std::string odom_frame_;
  ros::Duration tf_timeout_;
  control::TargetTrack track_;
  control::TrackGate gate_;
  std::string last_error_;
};

}  // namespace radio_follow
