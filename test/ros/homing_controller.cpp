// SPDX-License-Identifier: BSD-3-Clause
// Closes a simple loop around the running homing_controller: the test integrates the
// commanded twist into odometry and produces the AoA bearing and RSSI of a static tag
// at (3, 1.5). Checks the published goal, the homing command and status, and arrival.
#include <geometry_msgs/PoseStamped.h>
#include <gtest/gtest.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <std_srvs/SetBool.h>

#include <cmath>
#include <mutex>

#include "controller_test_utils.hpp"
#include "radio_follow/AoaBearing.h"

namespace {

using radio_follow::FollowerStatus;
using radio_follow_test::isZero;
using radio_follow_test::waitFor;

constexpr double kTargetX = 3.0;
constexpr double kTargetY = 1.5;

class Simulator {
 public:
  explicit Simulator(ros::NodeHandle& nh)
      : odom_pub_(nh.advertise<nav_msgs::Odometry>("odom", 10)),
        bearing_pub_(nh.advertise<radio_follow::AoaBearing>("aoa_bearing", 10)),
        cmd_sub_(nh.subscribe("cmd_vel", 10, &Simulator::onCmd, this)),
        timer_(nh.createTimer(ros::Duration(0.05), &Simulator::tick, this)) {}

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
  ros::Publisher odom_pub_;
  ros::Publisher bearing_pub_;
  ros::Subscriber cmd_sub_;
  ros::Timer timer_;
};

TEST(HomingController, PublishesGoalHomesAndArrives) {
  ros::NodeHandle nh;
  radio_follow_test::ControllerRecorder rec(nh, "homing_controller/status");
  std::mutex goal_mutex;
  geometry_msgs::PoseStamped goal;
  bool has_goal = false;
  ros::Subscriber goal_sub = nh.subscribe<geometry_msgs::PoseStamped>(
      "homing_controller/goal", 10, [&](const geometry_msgs::PoseStamped::ConstPtr& msg) {
        std::lock_guard<std::mutex> lock(goal_mutex);
        goal = *msg;
        has_goal = true;
      });
  Simulator sim(nh);

  ASSERT_TRUE(waitFor([&] { return rec.lastStatus().text == "Homing to the target."; }, 20.0))
      << "last status: " << rec.lastStatus().text;
  ASSERT_TRUE(waitFor([&] { return rec.lastCmd().linear.x > 0.05; }, 10.0));
  {
    std::lock_guard<std::mutex> lock(goal_mutex);
    ASSERT_TRUE(has_goal);
    EXPECT_EQ(goal.header.frame_id, "odom");
    EXPECT_NEAR(goal.pose.position.x, kTargetX, 0.3);
    EXPECT_NEAR(goal.pose.position.y, kTargetY, 0.3);
  }

  ASSERT_TRUE(
      waitFor([&] { return rec.lastStatus().state == FollowerStatus::STATE_ARRIVED; }, 40.0))
      << "last status: " << rec.lastStatus().text << ", distance " << sim.distanceToTarget();
  EXPECT_LT(sim.distanceToTarget(), 0.4);
  ros::WallDuration(0.3).sleep();
  EXPECT_TRUE(isZero(rec.lastCmd()));

  ros::ServiceClient enable = nh.serviceClient<std_srvs::SetBool>("homing_controller/set_enabled");
  std_srvs::SetBool srv;
  srv.request.data = false;
  ASSERT_TRUE(enable.call(srv));
  ASSERT_TRUE(
      waitFor([&] { return rec.lastStatus().state == FollowerStatus::STATE_DISABLED; }, 5.0));
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "homing_controller_rostest");
  ros::AsyncSpinner spinner(2);
  spinner.start();
  return RUN_ALL_TESTS();
}
