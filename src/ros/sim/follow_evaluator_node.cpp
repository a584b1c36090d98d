// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/ros/sim/follow_evaluator_node.hpp"

#include <ros/names.h>
#include <signal.h>
#include <std_msgs/String.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <system_error>

#include "radio_follow/common/param_error.hpp"
#include "radio_follow/common/plausibility.hpp"
#include "radio_follow/common/target_status.hpp"
#include "radio_follow/ros/common/params.hpp"
#include "radio_follow/ros/common/target_estimate.hpp"

namespace radio_follow {
namespace {

/// Seconds of ground truth kept to match estimates by stamp.
constexpr double kTruthHistory = 2.0;

/// Writes through a temporary file and a rename, so a reader never sees half a file.
void writeFile(const std::string& path, const std::string& text) {
  const std::string temporary = path + ".tmp";
  {
    std::ofstream out(temporary);
    out << text;
    if (!out) {
      ROS_ERROR_THROTTLE(10.0, "follow_evaluator: could not write %s", temporary.c_str());
      return;
    }
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    ROS_ERROR_THROTTLE(10.0, "follow_evaluator: could not rename %s", temporary.c_str());
  }
}

/// Ends the roslaunch that started this node, as Ctrl-C does. roslaunch has no API for a
/// node to end a launch cleanly: a `required` node that exits makes it print "REQUIRED
/// process has died" in red after every successful run. SIGINT to the parent is what
/// Ctrl-C sends; only done when the parent really is roslaunch.
void endParentLaunch() {
  const pid_t parent = getppid();
  std::ifstream cmdline("/proc/" + std::to_string(parent) + "/cmdline");
  const std::string command((std::istreambuf_iterator<char>(cmdline)),
                            std::istreambuf_iterator<char>());
  if (command.find("roslaunch") == std::string::npos) {
    ROS_WARN(
        "follow_evaluator: end_launch is set but my parent (pid %d) is not roslaunch; "
        "leaving it running",
        static_cast<int>(parent));
    return;
  }
  ROS_INFO("follow_evaluator: scenario over, ending the launch");
  kill(parent, SIGINT);
}

}  // namespace

FollowEvaluatorNode::FollowEvaluatorNode(ros::NodeHandle& nh, ros::NodeHandle& private_nh)
    : metrics_(control::FollowSettings{}) {
  const ParamReader reader(private_nh);
  const ParamTable<Params>& table = Params::table();
  const auto judged_by_controller = [](const std::string& name) {
    return name == "follow_distance" || name == "safe_distance";
  };
  for (const auto& entry : table.entries()) {
    if (!judged_by_controller(entry.name)) {
      table.load(reader, params_, entry.name);
    }
  }
  if (params_.controller.empty()) {
    table.load(reader, params_, "follow_distance");
    table.load(reader, params_, "safe_distance");
  } else {
    // The distances the controller really runs with, not a second copy of them.
    requireGraphName("~controller", params_.controller);
    const std::string ns = ros::names::resolve(params_.controller);
    require(ros::param::has(ns + "/follow_distance") && ros::param::has(ns + "/safe_distance"),
            "~controller", params_.controller,
            "a controller node whose follow_distance and safe_distance are set");
    const ParamReader controller{ros::NodeHandle(ns), ns + "/"};
    table.load(controller, params_, "follow_distance");
    table.load(controller, params_, "safe_distance");
  }
  reader.requireAllKnown();
  params_.validate();
  if (!params_.report_dir.empty()) {
    std::error_code error;
    std::filesystem::create_directories(params_.report_dir, error);
    require(!error, "~report_dir", params_.report_dir,
            "a directory that exists or can be created (" + error.message() + ")");
  }
  metrics_ = control::FollowMetrics(params_.settings);
  time_.setFutureTolerance(futureStampTolerance(ros::Time::isSimTime()));  // as the controllers

  odom_sub_ = barrier_.subscribe<nav_msgs::Odometry>(
      nh, "odom", 10, [this](const nav_msgs::OdometryConstPtr& m) {
        const auto& p = m->pose.pose;
        if (usable(plausibleOdometryCoordinate(p.position.x) &&
                       plausibleOdometryCoordinate(p.position.y) &&
                       std::isfinite(p.orientation.x) && std::isfinite(p.orientation.y) &&
                       std::isfinite(p.orientation.z) && std::isfinite(p.orientation.w) &&
                       std::isfinite(m->twist.twist.linear.x),
                   "odom")) {
          odom_ = m;
        }
      });
  truth_sub_ = barrier_.subscribe<geometry_msgs::PointStamped>(
      nh, "ground_truth/target", 10, [this](const geometry_msgs::PointStampedConstPtr& m) {
        if (!usable(plausibleOdometryCoordinate(m->point.x) &&
                        plausibleOdometryCoordinate(m->point.y),
                    "ground_truth/target")) {
          return;
        }
        if (truth_) {
          // Seconds as double: stamps 2^32 s apart overflow ros::Duration.
          const double dt = m->header.stamp.toSec() - truth_->header.stamp.toSec();
          if (dt > 0.0) {
            target_speed_ =
                std::hypot(m->point.x - truth_->point.x, m->point.y - truth_->point.y) / dt;
          }
        }
        truth_ = m;
      });
  relative_sub_ = barrier_.subscribe<geometry_msgs::PointStamped>(
      nh, "ground_truth/target_relative", 10, [this](const geometry_msgs::PointStampedConstPtr& m) {
        if (!usable(plausibleCoordinate(m->point.x) && plausibleCoordinate(m->point.y),
                    "ground_truth/target_relative")) {
          return;
        }
        relative_history_.push_back(m);
        while (relative_history_.size() > 1 &&
               m->header.stamp.toSec() - relative_history_.front()->header.stamp.toSec() >
                   kTruthHistory) {
          relative_history_.pop_front();
        }
      });
  estimate_sub_ = barrier_.subscribe<TargetEstimate>(
      nh, "target", 10, [this](const TargetEstimateConstPtr& m) {
        if (usable(plausibleCoordinate(m->position.x) && plausibleCoordinate(m->position.y),
                   "target")) {
          estimate_ = m;
        }
      });
  cmd_sub_ = barrier_.subscribe<geometry_msgs::Twist>(
      nh, "cmd_vel", 10, [this](const geometry_msgs::TwistConstPtr& m) {
        if (usable(std::isfinite(m->linear.x) && std::isfinite(m->angular.z), "cmd_vel")) {
          cmd_ = *m;
        }
      });
  report_pub_ = nh.advertise<std_msgs::String>("evaluation/report", 1, true);
  finished_sub_ =
      barrier_.subscribe(nh, "ground_truth/finished", 1, &FollowEvaluatorNode::onFinished, this);
  timer_ = barrier_.timer(nh, ros::Duration(1.0 / params_.rate), "evaluation tick",
                          &FollowEvaluatorNode::onTick, this);
  if (!params_.report_dir.empty()) {
    write_timer_ = barrier_.timer(nh, ros::Duration(params_.write_period), "report files",
                                  [this](const ros::TimerEvent&) { writeFiles(); });
  }
}

FollowEvaluatorNode::~FollowEvaluatorNode() {
  writeReport();
}

bool FollowEvaluatorNode::usable(bool ok, const char* topic) {
  if (!ok) {
    ++implausible_;
    ROS_WARN_THROTTLE(5.0, "follow_evaluator: dropped a %s message with a non-finite or "
                           "implausible value (%zu dropped so far)", topic, implausible_);
  }
  return ok;
}

void FollowEvaluatorNode::onFinished(const std_msgs::BoolConstPtr& msg) {
  if (!msg->data || finished_) {
    return;
  }
  finished_ = true;
  timer_.stop();
  write_timer_.stop();
  writeFiles();
  const control::FollowReport result = metrics_.report();
  std_msgs::String report;
  report.data = result.toJson();
  report_pub_.publish(report);
  logVerdict(result);
  if (params_.end_launch) {
    endParentLaunch();
  }
}

void FollowEvaluatorNode::logVerdict(const control::FollowReport& report) const {
  if (report.failures.empty()) {
    ROS_INFO(
        "follow_evaluator: closed loop OK: the robot drove %.1f m, the estimate was usable "
        "%.0f %% of the time, the gap held %.0f %% of the walk",
        report.robot_distance, 100.0 * report.estimate_availability,
        100.0 * report.gap_within_tolerance);
    return;
  }
  std::string reasons;
  for (const std::string& failure : report.failures) {
    reasons += (reasons.empty() ? "" : "; ") + failure;
  }
  const std::string last_status =
      estimate_ ? toString(static_cast<TargetStatus>(estimate_->status)) : "none heard";
  ROS_ERROR(
      "follow_evaluator: CLOSED LOOP FAILED: %s. Last estimate status: %s. Check the "
      "locator's inputs (its diagnostics name silent topics) and doc/deployment.md.",
      reasons.c_str(), last_status.c_str());
}

void FollowEvaluatorNode::onTick(const ros::TimerEvent& event) {
  if (time_.jumpedBack(event.current_real.toSec())) {
    // A restarted simulator or a looped bag: the samples so far belong to another run.
    ROS_WARN("follow_evaluator: the clock jumped back, metrics start over");
    metrics_ = control::FollowMetrics(params_.settings);
    relative_history_.clear();
    estimate_.reset();
  }
  if (finished_ || !odom_ || !truth_ || relative_history_.empty()) {
    return;
  }
  const auto& relative = relative_history_.back();
  control::FollowSample s;
  s.t = event.current_real.toSec();
  s.robot_x = odom_->pose.pose.position.x;
  s.robot_y = odom_->pose.pose.position.y;
  const auto& q = odom_->pose.pose.orientation;
  s.robot_yaw = std::atan2(2.0 * (q.w * q.z + q.x * q.y), 1.0 - 2.0 * (q.y * q.y + q.z * q.z));
  s.robot_speed = odom_->twist.twist.linear.x;
  s.cmd_linear = cmd_.linear.x;
  s.cmd_angular = cmd_.angular.z;
  s.target_x = truth_->point.x;
  s.target_y = truth_->point.y;
  s.target_speed = target_speed_;
  s.truth_x = relative->point.x;
  s.truth_y = relative->point.y;
  if (estimate_) {
    s.estimate_status = toString(static_cast<TargetStatus>(estimate_->status));
  }
  const bool usable = estimate_ && hasPosition(*estimate_);
  // An estimate from the future is not available, whatever it claims (TimePolicy).
  const bool trusted =
      usable && time_.check(estimate_->header.stamp.toSec(), event.current_real.toSec()) ==
                    TimePolicy::Verdict::kFresh;
  if (trusted && event.current_real.toSec() - estimate_->header.stamp.toSec() <=
                     control::kSampleEstimateMaxAge) {
    // Compare with the truth closest to the estimate's stamp.
    const ros::Time stamp = estimate_->header.stamp;
    const auto closest = std::min_element(
        relative_history_.begin(), relative_history_.end(), [&stamp](const auto& a, const auto& b) {
          return std::abs(a->header.stamp.toSec() - stamp.toSec()) <
                 std::abs(b->header.stamp.toSec() - stamp.toSec());
        });
    s.truth_x = (*closest)->point.x;
    s.truth_y = (*closest)->point.y;
    s.estimate_x = estimate_->position.x;
    s.estimate_y = estimate_->position.y;
    const auto& c = estimate_->position_covariance;
    if (std::isfinite(c[0]) && std::isfinite(c[1]) && std::isfinite(c[4])) {
      s.estimate_covariance = std::array<double, 3>{c[0], c[1], c[4]};
    }
  }
  metrics_.add(s);
}

void FollowEvaluatorNode::writeFiles() const {
  if (params_.report_dir.empty()) {
    return;
  }
  writeFile(params_.report_dir + "/trajectory.csv", metrics_.toCsv());
  writeFile(params_.report_dir + "/metrics.json", metrics_.report().toJson());
}

void FollowEvaluatorNode::writeReport() const {
  ROS_INFO("follow_evaluator: %zu samples\n%s", metrics_.samples().size(),
           metrics_.report().toJson().c_str());
  writeFiles();
}

}  // namespace radio_follow
