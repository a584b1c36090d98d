// SPDX-License-Identifier: BSD-3-Clause
// replay.launch on the shipped bag: estimates near the bag's ground truth, commands on
// replay/cmd_vel, none on cmd_vel.
#include <geometry_msgs/PointStamped.h>
#include <geometry_msgs/Twist.h>
#include <gtest/gtest.h>
#include <ros/ros.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <deque>
#include <vector>

#include "../support/spin_until.hpp"
#include "radio_follow/TargetEstimate.h"

namespace {

TEST(Replay, EstimatesFollowTheGroundTruthAndNothingDrives) {
  ros::NodeHandle nh;
  std::deque<geometry_msgs::PointStamped> truth;
  std::vector<double> errors;
  int cmd_vel = 0;
  int replay_cmd_vel = 0;
  auto on_truth = [&](const geometry_msgs::PointStampedConstPtr& m) {
    truth.push_back(*m);
    if (truth.size() > 400) {
      truth.pop_front();
    }
  };
  auto on_target = [&](const radio_follow::TargetEstimateConstPtr& m) {
    if (m->status != radio_follow::TargetEstimate::STATUS_OK) {
      return;
    }
    // The truth sample nearest to the estimate's stamp (the simulator publishes at 50 Hz).
    const auto nearest =
        std::min_element(truth.begin(), truth.end(), [&](const auto& a, const auto& b) {
          return std::abs((a.header.stamp - m->header.stamp).toSec()) <
                 std::abs((b.header.stamp - m->header.stamp).toSec());
        });
    if (nearest != truth.end() &&
        std::abs((nearest->header.stamp - m->header.stamp).toSec()) < 0.05) {
      errors.push_back(
          std::hypot(m->position.x - nearest->point.x, m->position.y - nearest->point.y));
    }
  };
  ros::Subscriber s1 =
      nh.subscribe<geometry_msgs::PointStamped>("ground_truth/target_relative", 100, on_truth);
  ros::Subscriber s2 = nh.subscribe<radio_follow::TargetEstimate>("target", 100, on_target);
  ros::Subscriber s3 = nh.subscribe<geometry_msgs::Twist>(
      "cmd_vel", 10, [&](const geometry_msgs::TwistConstPtr&) { ++cmd_vel; });
  ros::Subscriber s4 = nh.subscribe<geometry_msgs::Twist>(
      "replay/cmd_vel", 10, [&](const geometry_msgs::TwistConstPtr&) { ++replay_cmd_vel; });

  ASSERT_TRUE(radio_follow::test::spinUntil([&] { return errors.size() >= 200; }, 90.0))
      << "only " << errors.size() << " estimates compared with the ground truth";
  std::nth_element(errors.begin(), errors.begin() + errors.size() / 2, errors.end());
  // Issue 14's goal for Spot on realistic sensors was a median of 0.15 m, on the thesis
  // tables' white bearing errors; real boards' (issue 35) slowly varying 6 deg is
  // 0.2-0.26 m sideways at the walk's 2-2.5 m, which the node at real time, ranged by
  // Spot's nearly collinear modules, carries: 0.25 m.
  std::printf("median error %.3f m over %zu estimates\n", errors[errors.size() / 2], errors.size());
  EXPECT_LT(errors[errors.size() / 2], 0.25);
  EXPECT_GT(replay_cmd_vel, 0) << "the controller did not run";
  EXPECT_EQ(cmd_vel, 0) << "something was sent on cmd_vel during a replay";
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "replay_rostest");
  return RUN_ALL_TESTS();
}
