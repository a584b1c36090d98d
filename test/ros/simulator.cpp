// SPDX-License-Identifier: BSD-3-Clause
// Checks the running simulator (a static target and a post, Spot layout, noise-free ranges):
// ranges agree with ground truth, bearings arrive from every board facing the target, the
// scan sees the post,
// /clock advances, and the base drives under cmd_vel.
#include <geometry_msgs/PointStamped.h>
#include <geometry_msgs/Twist.h>
#include <gtest/gtest.h>
#include <nav_msgs/Odometry.h>
#include <radio_follow/AoaBearing.h>
#include <radio_follow/UwbRanges.h>
#include <ros/ros.h>
#include <sensor_msgs/LaserScan.h>
#include <std_msgs/Float64.h>

#include <cmath>

namespace {

TEST(Simulator, RangesMatchGroundTruth) {
  ros::NodeHandle nh;
  const auto truth = ros::topic::waitForMessage<geometry_msgs::PointStamped>(
      "ground_truth/target_relative", nh, ros::Duration(30.0));
  ASSERT_TRUE(truth);
  const auto ranges = ros::topic::waitForMessage<radio_follow::UwbRanges>("uwb/5A84/ranges", nh,
                                                                          ros::Duration(30.0));
  ASSERT_TRUE(ranges);
  EXPECT_EQ(ranges->tag_id, "5A84");
  EXPECT_EQ(ranges->header.frame_id, "uwb_5A84");
  ASSERT_EQ(ranges->ranges.size(), 1u);
  EXPECT_EQ(ranges->ranges[0].anchor_id, "DA12");
  // Module 5A84 sits at (-0.07, -0.04, 0.093); the robot has not moved.
  const double dx = truth->point.x + 0.07, dy = truth->point.y + 0.04, dz = truth->point.z - 0.093;
  EXPECT_NEAR(ranges->ranges[0].range, std::sqrt(dx * dx + dy * dy + dz * dz), 1e-6);
}

TEST(Simulator, FrontFacingBoardSeesTheTarget) {
  ros::NodeHandle nh;
  // Target at (6, -4): in front (x > 0) of the front board, behind the back one.
  const auto bearing = ros::topic::waitForMessage<radio_follow::AoaBearing>("aoa/front/bearing", nh,
                                                                            ros::Duration(30.0));
  ASSERT_TRUE(bearing);
  EXPECT_EQ(bearing->header.frame_id, "aoa_front");
  EXPECT_NEAR(bearing->azimuth, std::atan2(-4.0, 6.0 - 0.065), 0.35);
  EXPECT_LT(bearing->rssi, -30.0);
}

TEST(Simulator, ScanSeesThePostToTheLeft) {
  ros::NodeHandle nh;
  const auto scan =
      ros::topic::waitForMessage<sensor_msgs::LaserScan>("scan", nh, ros::Duration(30.0));
  ASSERT_TRUE(scan);
  const int left =
      static_cast<int>(std::lround((M_PI / 2.0 - scan->angle_min) / scan->angle_increment));
  ASSERT_LT(left, static_cast<int>(scan->ranges.size()));
  EXPECT_NEAR(scan->ranges[left], 1.7, 0.05);                      // post at 2 m, radius 0.3 m
  EXPECT_TRUE(std::isinf(scan->ranges[scan->ranges.size() / 2]));  // nothing ahead
  const auto clearance = ros::topic::waitForMessage<std_msgs::Float64>(
      "ground_truth/obstacle_clearance", nh, ros::Duration(30.0));
  ASSERT_TRUE(clearance);
  EXPECT_NEAR(clearance->data, 1.7, 1e-6);
}

TEST(Simulator, BaseDrivesUnderCmdVel) {
  ros::NodeHandle nh;
  ros::Publisher cmd = nh.advertise<geometry_msgs::Twist>("cmd_vel", 1);
  const auto before =
      ros::topic::waitForMessage<nav_msgs::Odometry>("odom", nh, ros::Duration(30.0));
  ASSERT_TRUE(before);
  geometry_msgs::Twist twist;
  twist.linear.x = 0.5;
  const ros::Time start = ros::Time::now();
  ros::Rate rate(20.0);  // sim time
  while (ros::ok() && ros::Time::now() - start < ros::Duration(4.0)) {
    cmd.publish(twist);
    rate.sleep();
  }
  const auto after =
      ros::topic::waitForMessage<nav_msgs::Odometry>("odom", nh, ros::Duration(30.0));
  ASSERT_TRUE(after);
  const double moved = after->pose.pose.position.x - before->pose.pose.position.x;
  EXPECT_GT(moved, 1.0);  // 4 s at up to 0.5 m/s after a 0.5 s ramp
  EXPECT_LT(moved, 2.5);
  EXPECT_GT(after->header.stamp.toSec(), before->header.stamp.toSec() + 3.0);
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "simulator_rostest");
  ros::AsyncSpinner spinner(2);
  spinner.start();
  return RUN_ALL_TESTS();
}
