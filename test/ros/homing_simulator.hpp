// SPDX-License-Identifier: BSD-3-Clause
// A minimal closed loop for the homing rostests: integrates cmd_vel into odometry and
// publishes the AoA bearing and RSSI of a static tag at (kTargetX, kTargetY).
#pragma once

#include <geometry_msgs/Twist.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>

#include <algorithm>
#include <cmath>
#include <mutex>

#include "radio_follow/AoaBearing.h"

namespace radio_follow_test {

inline constexpr double kTargetX = 3.0;
inline constexpr double kTargetY = 1.5;

class HomingSimulator {
 public:
  explicit HomingSimulator(ros::NodeHandle& nh)
      : odom_pub_(nh.advertise<nav_msgs::Odometry>("odom", 10)),
        bearing_pub_(nh.advertise<radio_follow::AoaBearing>("aoa_bearing", 10)),
        cmd_sub_(nh.subscribe("cmd_vel", 10, &HomingSimulator::onCmd, this)),
        timer_(nh.createTimer(ros::Duration(0.05), &HomingSimulator::tick, this)) {}

  /// The next `count` odometry messages carry a NaN pose (a driver glitch).
  void corruptOdometry(int count) {
    std::lock_guard<std::mutex> lock(mutex_);
    nan_odometry_ = count;
  }

  double distanceToTarget() {
    std::lock_guard<std::mutex> lock(mutex_);
    return std::hypot(kTargetX - x_, kTargetY - y_);
  }

 private:
  void onCmd(const geometry_msgs::Twist::ConstPtr& msg) {
    std::lock_guard<std::mutex> lock(mutex_);
    v_ = msg->linear.x;
    w_ = msg->angular.z;
  }

  void tick(const ros::TimerEvent&) {
    std::lock_guard<std::mutex> lock(mutex_);
    const double dt = 0.05;
    yaw_ += w_ * dt;
    x_ += v_ * std::cos(yaw_) * dt;
    y_ += v_ * std::sin(yaw_) * dt;
    const ros::Time now = ros::Time::now();
    nav_msgs::Odometry odom;
    odom.header.stamp = now;
    odom.header.frame_id = "odom";
    odom.child_frame_id = "base_link";
    odom.pose.pose.position.x = x_;
    odom.pose.pose.position.y = y_;
    odom.pose.pose.orientation.z = std::sin(0.5 * yaw_);
    odom.pose.pose.orientation.w = std::cos(0.5 * yaw_);
    if (nan_odometry_ > 0) {
      --nan_odometry_;
      odom.pose.pose.position.x = std::nan("");
    }
    odom_pub_.publish(odom);

    radio_follow::AoaBearing b;
    b.header.stamp = now;
    b.header.frame_id = "aoa_front";
    b.tag_id = "ccf9578e0d8a";  // case must not matter
    b.azimuth = std::atan2(std::sin(std::atan2(kTargetY - y_, kTargetX - x_) - yaw_),
                           std::cos(std::atan2(kTargetY - y_, kTargetX - x_) - yaw_));
    const double d = std::max(0.05, std::hypot(kTargetX - x_, kTargetY - y_));
    b.rssi = -50.0 - 20.0 * std::log10(d);
    b.rssi_second = std::nan("");
    bearing_pub_.publish(b);
  }

  std::mutex mutex_;
  double x_ = 0.0, y_ = 0.0, yaw_ = 0.0, v_ = 0.0, w_ = 0.0;
  int nan_odometry_ = 0;
  ros::Publisher odom_pub_;
  ros::Publisher bearing_pub_;
  ros::Subscriber cmd_sub_;
  ros::Timer timer_;
};

}  // namespace radio_follow_test
