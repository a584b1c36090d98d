// SPDX-License-Identifier: BSD-3-Clause
// The TDoA heading mode through ROS (locator_tdoa_sim.test): the simulator's anchors hear the
// robot's own module, the locator node learns every anchor pair's offset from those blinks
// (its diagnostics say so), holds the person's differences back until then, and afterwards
// finds the person's direction from the anchors alone (the module only ranges).
#include <diagnostic_msgs/DiagnosticArray.h>
#include <gtest/gtest.h>
#include <ros/ros.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <map>
#include <mutex>
#include <string>
#include <vector>

#include "radio_follow/TargetEstimate.h"

namespace {

// test/data/scenario_tdoa_person.yaml: the person stands at (2.5, 1.5); the robot stands.
const double kTrueBearing = std::atan2(1.5, 2.5);

/// The locator's status values, by key, once a status shows every pair's offset learnt.
std::map<std::string, std::string> calibratedDiagnostics(double timeout) {
  ros::NodeHandle nh;
  std::mutex mutex;
  std::map<std::string, std::string> values;
  std::atomic<bool> done{false};
  ros::Subscriber sub = nh.subscribe<diagnostic_msgs::DiagnosticArray>(
      "/diagnostics", 10, [&](const diagnostic_msgs::DiagnosticArray::ConstPtr& msg) {
        for (const auto& s : msg->status) {
          if (s.name != "locator: locator") {
            continue;
          }
          std::map<std::string, std::string> v;
          int learnt = 0;
          for (const auto& kv : s.values) {
            v[kv.key] = kv.value;
            learnt += kv.key.rfind("TDoA offset ", 0) == 0 && kv.value.rfind("learning", 0) != 0;
          }
          if (learnt == 2) {  // anchors 49 and 17 against the reference 05
            const std::lock_guard<std::mutex> lock(mutex);
            values = v;
            done = true;
          }
        }
      });
  const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(timeout);
  while (!done && ros::WallTime::now() < deadline) {
    ros::WallDuration(0.1).sleep();
  }
  const std::lock_guard<std::mutex> lock(mutex);
  return values;
}

TEST(LocatorTdoaSim, LearnsTheAnchorsOffsetsFromTheModulesBlinks) {
  const auto values = calibratedDiagnostics(60.0);
  ASSERT_FALSE(values.empty()) << "no locator status with both pairs' offsets learnt in 60 s";
  EXPECT_EQ(values.count("TDoA offset 49-05 (m)"), 1u);
  EXPECT_EQ(values.count("TDoA offset 17-05 (m)"), 1u);
  EXPECT_GT(std::stoul(values.at("TDoA calibration blinks (robot's modules)")), 50u);
  // Until then the person's differences waited.
  EXPECT_GT(std::stoul(values.at("TDoA differences awaiting calibration")), 0u);
  // The module's blinks are calibration, not strangers'.
  EXPECT_EQ(values.at("TDoA messages of other tags (not fused)"), "0");
}

TEST(LocatorTdoaSim, FindsThePersonsDirectionFromTheAnchors) {
  ros::NodeHandle nh;
  std::mutex mutex;
  std::vector<double> errors;
  std::atomic<int> received{0};
  std::atomic<int> with_tdoa{0};
  ros::Subscriber sub = nh.subscribe<radio_follow::TargetEstimate>(
      "target", 100, [&](const radio_follow::TargetEstimate::ConstPtr& msg) {
        ++received;
        const bool directed = msg->status == radio_follow::TargetEstimate::STATUS_OK ||
                              msg->status == radio_follow::TargetEstimate::STATUS_DEGRADED ||
                              msg->status == radio_follow::TargetEstimate::STATUS_HEADING_ONLY;
        if (!directed) {
          return;
        }
        with_tdoa += (msg->sources & radio_follow::TargetEstimate::SOURCE_TDOA) != 0;
        const double error = std::remainder(msg->bearing - kTrueBearing, 2.0 * M_PI);
        const std::lock_guard<std::mutex> lock(mutex);
        errors.push_back(std::abs(error));
      });
  // 200 estimates: 10 s of the locator's 20 Hz.
  const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(60.0);
  while (received < 200 && ros::WallTime::now() < deadline) {
    ros::WallDuration(0.1).sleep();
  }
  const std::lock_guard<std::mutex> lock(mutex);
  ASSERT_GE(received, 200) << "fewer than 200 estimates in 60 s";
  // The one module cannot give a direction: every directed estimate is the anchors'.
  EXPECT_EQ(with_tdoa, static_cast<int>(errors.size()));
  EXPECT_GE(errors.size(), 100u) << "directed estimates among " << received.load();
  ASSERT_FALSE(errors.empty());
  std::nth_element(errors.begin(), errors.begin() + errors.size() / 2, errors.end());
  // Half a 45 deg sector: the person's side and quarter, not its mirror nor a guess.
  EXPECT_LT(errors[errors.size() / 2] * 180.0 / M_PI, 22.5);
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "locator_tdoa_sim_rostest");
  ros::AsyncSpinner spinner(1);
  spinner.start();
  return RUN_ALL_TESTS();
}
