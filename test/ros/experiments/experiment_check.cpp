// SPDX-License-Identifier: BSD-3-Clause
// The checker of the closed-loop experiments (test/ros/experiments/*.test): waits for the
// follow evaluator's final report of a simulated run and asserts the thresholds its
// private parameters set; optionally watches cmd_vel for a stop-and-resume window and a
// topic that must publish again after a fault. Every threshold is optional (absent: not
// checked), so each experiment states exactly what it claims.
#include <geometry_msgs/PointStamped.h>
#include <geometry_msgs/PoseStamped.h>
#include <geometry_msgs/Twist.h>
#include <gtest/gtest.h>
#include <radio_follow/UwbRanges.h>
#include <ros/ros.h>
#include <std_msgs/String.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "../../support/spin_until.hpp"

namespace {

/// A metric of the JSON report (JSON is YAML); NaN for null or absent.
double metric(const YAML::Node& report, const std::string& key) {
  const YAML::Node value = report[key];
  if (!value || value.IsNull()) {
    return std::numeric_limits<double>::quiet_NaN();
  }
  return value.as<double>();
}

/// Reads an optional threshold; absent -> nullopt-like NaN.
double threshold(const std::string& name) {
  double value = std::numeric_limits<double>::quiet_NaN();
  ros::param::get("~" + name, value);
  return value;
}

struct CommandLog {
  struct Entry {
    double t;
    double linear;
  };
  std::vector<Entry> entries;
  void onCommand(const geometry_msgs::TwistConstPtr& msg) {
    entries.push_back({ros::Time::now().toSec(), msg->linear.x});
  }
};

TEST(Experiment, MeetsItsThresholds) {
  ros::NodeHandle nh;
  const double timeout = [] {
    double t = 300.0;
    ros::param::get("~timeout", t);
    return t;
  }();

  std::string report_text;
  ros::Subscriber report_sub = nh.subscribe<std_msgs::String>(
      "evaluation/report", 1,
      [&](const std_msgs::StringConstPtr& msg) { report_text = msg->data; });
  CommandLog commands;
  ros::Subscriber cmd_sub = nh.subscribe("cmd_vel", 100, &CommandLog::onCommand, &commands);

  // A UWB ranges topic that must publish again after a fault (a replugged module's driver).
  std::string expect_topic;
  ros::param::get("~expect_ranges_topic", expect_topic);
  const double expect_after = threshold("expect_after");
  double last_on_topic = -1.0;
  ros::Subscriber expect_sub;
  if (!expect_topic.empty()) {
    expect_sub = nh.subscribe<radio_follow::UwbRanges>(
        expect_topic, 10,
        [&](const radio_follow::UwbRangesConstPtr&) { last_on_topic = ros::Time::now().toSec(); });
  }

  // A homing goal (PoseStamped in the odometry frame) compared with the true target.
  std::string goal_topic;
  ros::param::get("~goal_topic", goal_topic);
  geometry_msgs::PoseStampedConstPtr goal;
  geometry_msgs::PointStampedConstPtr truth;
  ros::Subscriber goal_sub, truth_sub;
  if (!goal_topic.empty()) {
    goal_sub = nh.subscribe<geometry_msgs::PoseStamped>(
        goal_topic, 10, [&](const geometry_msgs::PoseStampedConstPtr& msg) { goal = msg; });
    truth_sub = nh.subscribe<geometry_msgs::PointStamped>(
        "ground_truth/target", 10,
        [&](const geometry_msgs::PointStampedConstPtr& msg) { truth = msg; });
  }

  ASSERT_TRUE(radio_follow::test::spinUntil([&] { return !report_text.empty(); }, timeout))
      << "no evaluation/report within " << timeout << " s of wall time";
  std::cout << "experiment report: " << report_text << std::endl;
  const YAML::Node report = YAML::Load(report_text);

  const double min_gap_while_moving = threshold("min_gap_while_moving");
  if (std::isfinite(min_gap_while_moving)) {
    EXPECT_GE(metric(report, "min_gap_while_moving_m"), min_gap_while_moving)
        << "the robot was commanded to move closer than this to the person";
  }
  const double min_within = threshold("min_gap_within_tolerance");
  if (std::isfinite(min_within)) {
    EXPECT_GE(metric(report, "gap_within_tolerance"), min_within);
  }
  const double max_error = threshold("max_estimate_error_median");
  if (std::isfinite(max_error)) {
    EXPECT_LE(metric(report, "estimate_error_median_m"), max_error);
  }
  const double max_final_gap = threshold("max_final_gap");
  if (std::isfinite(max_final_gap)) {
    EXPECT_LE(metric(report, "final_gap_m"), max_final_gap) << "the robot ended this far away";
  }
  const double max_goal_error = threshold("max_goal_error");
  if (!goal_topic.empty()) {
    ASSERT_TRUE(goal && truth) << "no goal on " << goal_topic << " or no ground truth";
    const double error =
        std::hypot(goal->pose.position.x - truth->point.x, goal->pose.position.y - truth->point.y);
    std::cout << "goal error: " << error << " m" << std::endl;
    if (std::isfinite(max_goal_error)) {
      EXPECT_LE(error, max_goal_error) << "last goal on " << goal_topic;
    }
  }
  const double max_deviation = threshold("max_path_deviation");
  if (std::isfinite(max_deviation)) {
    EXPECT_LE(metric(report, "path_deviation_max_m"), max_deviation);
  }

  // Stop and resume: no forward command inside [stop_from, stop_until] (sim time, s), and
  // a forward command again after resume_after.
  const double stop_from = threshold("stop_from");
  const double stop_until = threshold("stop_until");
  if (std::isfinite(stop_from) && std::isfinite(stop_until)) {
    int in_window = 0;
    double worst = 0.0;
    for (const auto& e : commands.entries) {
      if (e.t >= stop_from && e.t <= stop_until) {
        ++in_window;
        worst = std::max(worst, std::abs(e.linear));
      }
    }
    EXPECT_GT(in_window, 0) << "no cmd_vel inside the stop window: the controller went silent";
    EXPECT_EQ(worst, 0.0) << "the robot was told to move during the fault";
  }
  const double resume_after = threshold("resume_after");
  if (std::isfinite(resume_after)) {
    const bool resumed =
        std::any_of(commands.entries.begin(), commands.entries.end(),
                    [&](const auto& e) { return e.t > resume_after && e.linear > 0.1; });
    EXPECT_TRUE(resumed) << "the robot never drove again after " << resume_after << " s";
  }
  if (!expect_topic.empty()) {
    EXPECT_GT(last_on_topic, expect_after) << expect_topic << " did not publish after the fault";
  }
  // Nothing crashed: every node the experiment names is still registered at the end.
  std::vector<std::string> expected_nodes;
  ros::param::get("~expect_nodes", expected_nodes);
  std::vector<std::string> nodes;
  ros::master::getNodes(nodes);
  for (const std::string& name : expected_nodes) {
    EXPECT_NE(std::find(nodes.begin(), nodes.end(), name), nodes.end()) << name << " is gone";
  }
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "experiment_check");
  ros::NodeHandle nh;  // starts the node before the test body
  return RUN_ALL_TESTS();
}
