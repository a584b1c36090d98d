// SPDX-License-Identifier: BSD-3-Clause
// homing_controller with bearings only: it must search, find the tag by parallax and
// arrive (see homing_controller_parallax.test).
#include <geometry_msgs/PoseStamped.h>
#include <gtest/gtest.h>
#include <ros/ros.h>

#include "controller_test_utils.hpp"
#include "homing_simulator.hpp"

namespace {

using radio_follow::FollowerStatus;
using radio_follow_test::HomingSimulator;
using radio_follow_test::waitFor;

TEST(HomingControllerParallax, SearchesThenHomesOnParallaxAlone) {
  ros::NodeHandle nh;
  radio_follow_test::ControllerRecorder rec(nh, "homing_controller/status");
  HomingSimulator sim(nh);

  ASSERT_TRUE(waitFor([&] { return rec.lastStatus().text == "Searching for the target."; }, 20.0))
      << "last status: " << rec.lastStatus().text;
  ASSERT_TRUE(waitFor([&] { return rec.lastCmd().linear.x > 0.05; }, 10.0));
  // Bearings only: arrival is decided by the distance to the parallax goal alone.
  ASSERT_TRUE(
      waitFor([&] { return rec.lastStatus().state == FollowerStatus::STATE_ARRIVED; }, 40.0))
      << "last status: " << rec.lastStatus().text << ", distance " << sim.distanceToTarget();
  EXPECT_LT(sim.distanceToTarget(), 0.5);
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "homing_controller_parallax_rostest");
  ros::AsyncSpinner spinner(2);
  spinner.start();
  return RUN_ALL_TESTS();
}
