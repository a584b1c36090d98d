// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <geometry_msgs/PointStamped.h>
#include <geometry_msgs/Twist.h>
#include <nav_msgs/Odometry.h>
#include <radio_follow/TargetEstimate.h>
#include <ros/ros.h>
#include <std_msgs/Bool.h>

#include <deque>
#include <string>

#include "radio_follow/common/time_policy.hpp"
#include "radio_follow/control/follow_metrics.hpp"
#include "radio_follow/ros/common/callback_barrier.hpp"

namespace radio_follow {

/// Samples a simulated follow run (ground truth, odometry, the locator's estimate and
/// the command) at a fixed rate and, when it shuts down, writes `metrics.json` and
/// `trajectory.csv` into `~report_dir` (scripts/plot_report.py draws them).
class FollowEvaluatorNode {
 public:
  using Params = control::FollowEvaluatorParams;

  FollowEvaluatorNode(ros::NodeHandle& nh, ros::NodeHandle& private_nh);
  ~FollowEvaluatorNode();

  FollowEvaluatorNode(const FollowEvaluatorNode&) = delete;
  FollowEvaluatorNode& operator=(const FollowEvaluatorNode&) = delete;

 private:
  void onTick(const ros::TimerEvent&);
  /// The simulator announced the end: stop sampling, write, publish the report.
  void onFinished(const std_msgs::BoolConstPtr& msg);
  void writeReport() const;
  /// One line saying whether the run worked as a closed loop, naming what failed.
  void logVerdict(const control::FollowReport& report) const;
  void writeFiles() const;
  /// Whether an input is usable (finite, plausible); counts and warns (throttled,
  /// naming `topic`) when it is not, so one bad message cannot make the report NaN.
  bool usable(bool ok, const char* topic);

  Params params_;
  std::size_t implausible_ = 0;  ///< inputs dropped as not finite or implausible
  control::FollowMetrics metrics_;
  TimePolicy time_;
  CallbackBarrier barrier_;  // every subscriber and timer runs inside it
  ros::Subscriber odom_sub_, truth_sub_, relative_sub_, estimate_sub_, cmd_sub_;
  ros::Timer timer_;
  ros::Timer write_timer_;
  ros::Subscriber finished_sub_;
  ros::Publisher report_pub_;
  bool finished_ = false;
  nav_msgs::OdometryConstPtr odom_;
  geometry_msgs::PointStampedConstPtr truth_;
  geometry_msgs::PointStampedConstPtr previous_truth_;
  /// Recent ground truth in the robot frame, so an estimate is compared with the truth
  /// at its own stamp (the locator's error, not the transport's latency).
  std::deque<geometry_msgs::PointStampedConstPtr> relative_history_;
  TargetEstimateConstPtr estimate_;
  geometry_msgs::Twist cmd_;
  double target_speed_ = 0.0;
};

}  // namespace radio_follow
