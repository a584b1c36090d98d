// SPDX-License-Identifier: BSD-3-Clause
// Helpers shared by the controller rostests: record cmd_vel and status, and wait for a
// condition (waits are bounded, they do not measure speed).
#pragma once

#include <geometry_msgs/Twist.h>
#include <ros/ros.h>

#include <functional>
#include <mutex>
#include <string>
#include <vector>

#include "radio_follow/FollowerStatus.h"
#include "radio_follow/TargetEstimate.h"
#include "radio_follow/UwbRanges.h"

namespace radio_follow_test {

class ControllerRecorder {
 public:
  ControllerRecorder(ros::NodeHandle& nh, const std::string& status_topic) {
    cmd_sub_ = nh.subscribe("cmd_vel", 50, &ControllerRecorder::onCmd, this);
    status_sub_ = nh.subscribe(status_topic, 50, &ControllerRecorder::onStatus, this);
  }

  geometry_msgs::Twist lastCmd() {
    std::lock_guard<std::mutex> lock(mutex_);
    return last_cmd_;
  }
  int cmdCount() {
    std::lock_guard<std::mutex> lock(mutex_);
    return cmd_count_;
  }
  /// Commands received since the index `from` (an earlier cmdCount()).
  std::vector<geometry_msgs::Twist> cmdsSince(int from) {
    std::lock_guard<std::mutex> lock(mutex_);
    return std::vector<geometry_msgs::Twist>(cmds_.begin() + from, cmds_.end());
  }
  bool hasStatus() {
    std::lock_guard<std::mutex> lock(mutex_);
    return has_status_;
  }
  radio_follow::FollowerStatus lastStatus() {
    std::lock_guard<std::mutex> lock(mutex_);
    return last_status_;
  }

 private:
  void onCmd(const geometry_msgs::Twist::ConstPtr& msg) {
    std::lock_guard<std::mutex> lock(mutex_);
    last_cmd_ = *msg;
    cmds_.push_back(*msg);
    ++cmd_count_;
  }
  void onStatus(const radio_follow::FollowerStatus::ConstPtr& msg) {
    std::lock_guard<std::mutex> lock(mutex_);
    last_status_ = *msg;
    has_status_ = true;
  }

  std::mutex mutex_;
  geometry_msgs::Twist last_cmd_;
  std::vector<geometry_msgs::Twist> cmds_;
  int cmd_count_ = 0;
  radio_follow::FollowerStatus last_status_;
  bool has_status_ = false;
  ros::Subscriber cmd_sub_;
  ros::Subscriber status_sub_;
};

/// Polls `condition` every 20 ms until it holds or `timeout` seconds passed.
inline bool waitFor(const std::function<bool()>& condition, double timeout) {
  const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(timeout);
  while (ros::ok() && ros::WallTime::now() < end) {
    if (condition()) {
      return true;
    }
    ros::WallDuration(0.02).sleep();
  }
  return condition();
}

/// An OK estimate of a target `distance` m straight ahead in base_link, stamped `stamp`.
inline radio_follow::TargetEstimate aheadEstimate(const ros::Time& stamp, double distance = 4.0) {
  radio_follow::TargetEstimate e;
  e.header.stamp = stamp;
  e.header.frame_id = "base_link";
  e.position.x = distance;
  e.range = distance;
  e.status = radio_follow::TargetEstimate::STATUS_OK;
  return e;
}

/// A raw range of module 5722 to the tests' target anchor ABCD.
inline radio_follow::UwbRanges anchorRange(const ros::Time& stamp, double range = 4.0) {
  radio_follow::UwbRanges r;
  r.header.stamp = stamp;
  r.tag_id = "5722";
  r.ranges.resize(1);
  r.ranges[0].anchor_id = "ABCD";
  r.ranges[0].range = range;
  return r;
}

inline bool isZero(const geometry_msgs::Twist& t) {
  return t.linear.x == 0.0 && t.linear.y == 0.0 && t.angular.z == 0.0;
}

}  // namespace radio_follow_test
