// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/ros/control/target_motion_tracker.hpp"

#include <tf2/exceptions.h>
#include <tf2_geometry_msgs/tf2_geometry_msgs.h>

#include <cmath>
#include <string>
#include <utility>

#include "radio_follow/ros/common/target_estimate.hpp"

namespace radio_follow {

TargetMotionTracker::TargetMotionTracker(const tf2_ros::Buffer& buffer, std::string odom_frame,
                                         double tf_timeout)
    : buffer_(buffer), odom_frame_(std::move(odom_frame)), tf_timeout_(tf_timeout) {}

std::optional<Eigen::Vector2d> TargetMotionTracker::add(const TargetEstimate& estimate) {
  if (!gate_.accept(static_cast<TargetStatus>(estimate.status))) {
    last_error_.clear();
    return std::nullopt;  // no position, or a young track's wide one (TrackGate)
  }
  try {
    // Never wait (timeout 0): this runs in a callback. The transform at the stamp when
    // TF has it, else the newest one if it is at most tf_timeout away from the stamp
    // (odometry usually lags the estimate by a few ms).
    geometry_msgs::TransformStamped t;
    if (buffer_.canTransform(odom_frame_, estimate.header.frame_id, estimate.header.stamp)) {
      t = buffer_.lookupTransform(odom_frame_, estimate.header.frame_id, estimate.header.stamp);
    } else {
      t = buffer_.lookupTransform(odom_frame_, estimate.header.frame_id, ros::Time(0));
      // Seconds as double: stamps 2^32 s apart overflow ros::Duration (issue 34).
      const double offset = t.header.stamp.toSec() - estimate.header.stamp.toSec();
      if (!(std::abs(offset) <= tf_timeout_.toSec())) {
        last_error_ = "newest transform " + std::to_string(offset) +
                      " s from the estimate, more than tf_timeout";
        return std::nullopt;
      }
    }
    geometry_msgs::Point target;
    tf2::doTransform(estimate.position, target, t);
    const Eigen::Vector2d in_odom(target.x, target.y);
    track_.add(estimate.header.stamp.toSec(),
               Eigen::Vector2d(t.transform.translation.x, t.transform.translation.y), in_odom);
    last_error_.clear();
    return in_odom;
  } catch (const tf2::TransformException& e) {
    last_error_ = e.what();
    return std::nullopt;
  }
}

std::optional<double> TargetMotionTracker::speed(const ros::Time& now) const {
  return track_.speed(now.toSec());
}

std::optional<double> TargetMotionTracker::recedingSpeed(const ros::Time& now) const {
  return track_.recedingSpeed(now.toSec());
}

}  // namespace radio_follow
