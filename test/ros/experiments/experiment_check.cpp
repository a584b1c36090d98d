// SPDX-License-Identifier: BSD-3-Clause
// The checker of the ROS closed-loop runs (test/ros/experiments/*.test): waits for the
// follow evaluator's final report of a simulated run through the real nodes and
//  - with ~experiment, asserts that experiment's thresholds from test/experiments.yaml on
//    the lockstep closed loop of the same experiment and seed (evaluation::checkRun; on
//    simulated time, so no load can move it), and that the ROS run agrees with that
//    lockstep run within the load-robust tolerances below (doc/experiments.md). The ROS
//    run itself is a smoke test of the wiring: a loaded machine slows its nodes on wall
//    time, and a threshold asserted on it failed CI runs that nothing was wrong with
//    (issue 34: exp3_spot_path held the gap 0.855 of the walk against 0.90). Only the
//    safety thresholds (gap and clearance while moving, the stop window, driving again
//    after a fault) are asserted on the ROS run itself;
//  - asserts the ROS-only checks its private parameters set: a topic that must publish
//    again after a fault (a replugged driver), nodes still alive, a homing goal.
// Every check is optional (absent: not checked), so each run states exactly what it claims.
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
#include "radio_follow/evaluation/experiment.hpp"

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

/// How far a ROS run may be from the lockstep run of the same experiment and seed. The
/// ROS loop adds transport latency, the drivers' parsing and reconnect backoff, and
/// timer jitter; the lockstep loop has none of them. The bounds hold on a machine whose
/// two cores are busy with other work: there the nodes run late on wall time, the robot
/// lags, and the share of the walk with the gap held fell by 0.145 in one CI run
/// (exp3_spot_path: 0.855 against the lockstep run's 1.00). They still catch a broken
/// wiring: a robot that does not move, an estimate that never arrives or is wrong by
/// metres, a stop that does not hold.
constexpr double kGapShareTolerance = 0.35;     ///< share of the walk (~gap_share_tolerance)
constexpr double kMinGapTolerance = 0.30;       ///< m
constexpr double kErrorMedianTolerance = 0.15;  ///< m
constexpr double kDistanceTolerance = 0.25;     ///< fraction of the lockstep distance

/// The report fields the experiment checks read, from the evaluator's JSON.
radio_follow::control::FollowReport fromJson(const YAML::Node& report) {
  radio_follow::control::FollowReport r;
  r.min_gap_while_moving = metric(report, "min_gap_while_moving_m");
  r.gap_within_tolerance = metric(report, "gap_within_tolerance");
  r.estimate_error_median = metric(report, "estimate_error_median_m");
  r.path_deviation_max = metric(report, "path_deviation_max_m");
  r.robot_distance = metric(report, "robot_distance_m");
  return r;
}

struct CommandLog {
  struct Entry {
    double t;
    double linear;
  };
  std::vector<Entry> entries;
  /// Stamped when roscpp received it, not when this callback ran: a stalled checker must
  /// not move a command from before a stop into the stop's window.
  void onCommand(const ros::MessageEvent<geometry_msgs::Twist const>& event) {
    entries.push_back({event.getReceiptTime().toSec(), event.getMessage()->linear.x});
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

  std::string experiment_name;
  ros::param::get("~experiment", experiment_name);
  if (!experiment_name.empty()) {
    std::string file, config_dir;
    int seed = 1;
    ASSERT_TRUE(ros::param::get("~experiments_file", file) &&
                ros::param::get("~config_dir", config_dir) && ros::param::get("~seed", seed))
        << "~experiment needs ~experiments_file, ~config_dir and ~seed";
    const auto experiments = radio_follow::evaluation::loadExperiments(file);
    const auto e = std::find_if(experiments.begin(), experiments.end(),
                                [&](const auto& x) { return x.name == experiment_name; });
    ASSERT_NE(e, experiments.end()) << experiment_name << " is not in " << file;
    const radio_follow::control::FollowReport ros_run = fromJson(report);
    // On the ROS run, only the thresholds no load may move: safety (the gap and the
    // clearance while moving, no motion in the stop window) and driving again after a
    // fault. How well it follows is asserted on the lockstep run below.
    radio_follow::evaluation::ExperimentCheck safety = e->check;
    safety.min_gap_within_tolerance.reset();
    safety.max_estimate_error_median.reset();
    safety.max_path_deviation.reset();
    safety.max_path_deviation_beyond_estimate.reset();
    std::vector<radio_follow::evaluation::CommandAt> sent;
    for (const auto& c : commands.entries) {
      sent.push_back({c.t, c.linear});
    }
    for (const std::string& v : radio_follow::evaluation::checkRun(safety, ros_run, sent)) {
      ADD_FAILURE() << "ROS run: " << v;
    }
    const auto lockstep = radio_follow::evaluation::runExperiment(*e, config_dir, seed);
    std::cout << "lockstep report (seed " << seed << "): " << lockstep.report.toJson() << std::endl;
    // The thresholds, on the run no load can move (runExperiment applies checkRun).
    for (const std::string& v : lockstep.violations) {
      ADD_FAILURE() << "lockstep run: " << v;
    }
    const radio_follow::control::FollowReport& l = lockstep.report;
    double gap_share_tolerance = kGapShareTolerance;
    ros::param::get("~gap_share_tolerance", gap_share_tolerance);
    EXPECT_NEAR(ros_run.gap_within_tolerance, l.gap_within_tolerance, gap_share_tolerance)
        << "gap held: ROS run vs lockstep";
    EXPECT_NEAR(ros_run.min_gap_while_moving, l.min_gap_while_moving, kMinGapTolerance)
        << "min gap while moving: ROS run vs lockstep";
    EXPECT_NEAR(ros_run.estimate_error_median, l.estimate_error_median, kErrorMedianTolerance)
        << "median estimate error: ROS run vs lockstep";
    EXPECT_NEAR(ros_run.robot_distance, l.robot_distance, kDistanceTolerance * l.robot_distance)
        << "distance driven: ROS run vs lockstep";
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
