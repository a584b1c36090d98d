// SPDX-License-Identifier: BSD-3-Clause
// Closes a simple loop around the running homing_controller: the test integrates the
// commanded twist into odometry and produces the AoA bearing and RSSI of a static tag
// at (3, 1.5). Checks the published goal, the homing command and status, and arrival.
#include <geometry_msgs/PoseStamped.h>
#include <gtest/gtest.h>
#include <ros/ros.h>
#include <std_srvs/SetBool.h>

#include <cmath>
#include <mutex>

#include "controller_test_utils.hpp"
#include "homing_simulator.hpp"

namespace {

using radio_follow::FollowerStatus;
using radio_follow_test::HomingSimulator;
using radio_follow_test::isZero;
using radio_follow_test::kTargetX;
using radio_follow_test::kTargetY;
using radio_follow_test::waitFor;

TEST(HomingController, PublishesGoalHomesAndArrives) {
  ros::NodeHandle nh;
  radio_follow_test::ControllerRecorder rec(nh, "homing_controller/status");
  std::mutex goal_mutex;
  geometry_msgs::PoseStamped goal;
  bool has_goal = false;
  int non_finite_goals = 0;
  ros::Subscriber goal_sub = nh.subscribe<geometry_msgs::PoseStamped>(
      "homing_controller/goal", 10, [&](const geometry_msgs::PoseStamped::ConstPtr& msg) {
        std::lock_guard<std::mutex> lock(goal_mutex);
        goal = *msg;
        has_goal = true;
        non_finite_goals +=
            !std::isfinite(msg->pose.position.x) || !std::isfinite(msg->pose.position.y);
      });
  HomingSimulator sim(nh);

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
  // One NaN odometry message used to make every later goal NaN: refused, homing goes on.
  sim.corruptOdometry(1);

  ASSERT_TRUE(
      waitFor([&] { return rec.lastStatus().state == FollowerStatus::STATE_ARRIVED; }, 40.0))
      << "last status: " << rec.lastStatus().text << ", distance " << sim.distanceToTarget();
  EXPECT_LT(sim.distanceToTarget(), 0.4);
  {
    std::lock_guard<std::mutex> lock(goal_mutex);
    EXPECT_EQ(non_finite_goals, 0);
  }
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
