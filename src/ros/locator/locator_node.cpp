// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/ros/locator/locator_node.hpp"

#include <geometry_msgs/PoseWithCovarianceStamped.h>
#include <geometry_msgs/TransformStamped.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>

#include "radio_follow/common/geometry.hpp"
#include "radio_follow/ros/common/wiring_debug.hpp"
#include "radio_follow/ros/locator/odometry_lookup.hpp"

namespace radio_follow {
namespace {

// At most one warning per silent input in this period, s.
constexpr double kSilentWarnPeriod = 10.0;

// Tuning advice that changes nothing is worse than none (issue 33): say so at start and
// on every live change.
void warnIgnoredSettings(const estimation::LocatorConfig& config) {
  for (const std::string& line : config.ignoredSettings()) {
    ROS_WARN("locator: %s; doc/nodes/locator.md says which settings each estimator reads",
             line.c_str());
  }
}

}  // namespace

TargetEstimate toMessage(const estimation::LocatorEstimate& estimate, const std::string& frame,
                         const ros::Time& stamp) {
  TargetEstimate msg;
  msg.header.frame_id = frame;
  msg.header.stamp = stamp;
  msg.position.x = estimate.position.x();
  msg.position.y = estimate.position.y();
  msg.position.z = estimate.position.z();
  msg.velocity.x = estimate.velocity.x();
  msg.velocity.y = estimate.velocity.y();
  msg.velocity.z = estimate.velocity.z();
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) {
      msg.position_covariance[static_cast<std::size_t>(3 * r + c)] = estimate.covariance(r, c);
    }
  }
  msg.range = estimate.position.head<2>().norm();
  msg.bearing = std::atan2(estimate.position.y(), estimate.position.x());
  msg.sources = estimate.sources;
  msg.status = static_cast<std::uint8_t>(estimate.status);
  msg.solver_cost = estimate.solver_cost;
  msg.hypotheses = static_cast<std::uint8_t>(estimate.hypotheses);
  msg.hypothesis_weight = estimate.hypothesis_weight;
  msg.alternative.x = estimate.alternative.x();
  msg.alternative.y = estimate.alternative.y();
  msg.alternative.z = estimate.alternative.z();
  return msg;
}

void setOdometry(TargetEstimate& msg, const estimation::OdometryEstimate& odom,
                 const std::string& odom_frame) {
  msg.odom_frame = odom_frame;
  msg.odom_position.x = odom.position.x();
  msg.odom_position.y = odom.position.y();
  msg.odom_position.z = odom.position.z();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  msg.odom_velocity.x = odom.velocity ? odom.velocity->x() : nan;
  msg.odom_velocity.y = odom.velocity ? odom.velocity->y() : nan;
  msg.odom_velocity.z = odom.velocity ? odom.velocity->z() : nan;
  msg.odom_robot.x = odom.robot.x();
  msg.odom_robot.y = odom.robot.y();
}

LocatorNode::LocatorNode(ros::NodeHandle& nh, ros::NodeHandle& private_nh)
    : diagnostics_(nh, private_nh) {
  {
    const ParamReader params(private_nh);
    allowTuning<LocatorTuningConfig>(params);  // the live-tuning server's own copies
    params_.load(params);
    params.requireAllKnown();
    params_.validate();
  }
  warnIgnoredSettings(params_.locator);
  layout_ = loadLayoutFile(params_.layout_file);  // validated: target anchor set with TWR
  locator_ = std::make_unique<estimation::Locator>(layout_, params_.locator);
  if (params_.odom_frame.empty()) {
    inputs_ = std::make_unique<LocatorInputs>(*locator_);
  } else {
    tf_buffer_ = std::make_unique<tf2_ros::Buffer>();
    tf_listener_ = std::make_unique<tf2_ros::TransformListener>(*tf_buffer_);
    inputs_ = std::make_unique<LocatorInputs>(
        *locator_, [this](const ros::Time& stamp) { return odometryPose(stamp); });
  }
  target_pub_ = nh.advertise<TargetEstimate>("target", 10);
  pose_pub_ = nh.advertise<geometry_msgs::PoseWithCovarianceStamped>("target_pose", 10);
  markers_pub_ = nh.advertise<visualization_msgs::MarkerArray>("markers", 1);
  debugAdvertised(markers_pub_);
  if (params_.path_length > 0) {
    path_pub_ = nh.advertise<nav_msgs::Path>("target_path", 1);
    debugAdvertised(path_pub_);
    path_.header.frame_id = layout_.fixed_frame;
  }
  subscribeInputs(nh);
  std::vector<std::string> resolved;
  for (const ros::Subscriber& s : subscribers_) {
    resolved.push_back(s.getTopic());
  }
  inputs_watch_.emplace(resolved, params_.input_timeout, kSilentWarnPeriod, 0.0);
  reconfigure_ = makeLocatorReconfigure(
      private_nh, params_.locator, [this](const estimation::LocatorConfig& config) {
        warnIgnoredSettings(config);
        if (!locator_->setConfig(config)) {
          ROS_INFO("locator: motion model changed, the filter restarts from the next solve");
        }
        params_.locator = config;
      });
  // The layout names the robot; its fixed frame is where the estimate lives.
  diagnostics_.setHardwareID("layout " +
                             std::filesystem::path(params_.layout_file).stem().string() +
                             ", frame " + layout_.fixed_frame);
  diagnostics_.add("locator", this, &LocatorNode::diagnose);
  // One estimate per solve; it carries its newest measurement's stamp, at most max_age
  // old when it is used, LOST ones the current time. target_pose only has a position.
  OutputDiagnostic::Bounds bounds;
  bounds.min_hz = params_.rate;
  bounds.max_hz = params_.rate;
  bounds.max_age = params_.locator.max_age + 2.0 / params_.rate;
  target_diagnostic_.emplace(diagnostics_, "locator output", target_pub_, bounds, true);
  bounds.min_hz = 0.0;
  pose_diagnostic_.emplace(diagnostics_, "locator output", pose_pub_, bounds, true);
  timer_ = barrier_.timer(nh, ros::Duration(1.0 / params_.rate), "locator update",
                          &LocatorNode::onTimer, this);
  ROS_INFO("locator: %s mode, %zu TWR modules, %zu AoA boards, %zu TDoA anchors, %.1f Hz",
           params_.locator.planar ? "2D" : "3D", layout_.twr_modules.size(),
           layout_.aoa_boards.size(), layout_.tdoa_anchors.size(), params_.rate);
}

std::optional<Pose2> LocatorNode::odometryPose(const ros::Time& stamp) const {
  return odometryPoseAt(*tf_buffer_, params_.odom_frame, layout_.fixed_frame, stamp,
                        params_.tf_tolerance);
}

void LocatorNode::subscribeInputs(ros::NodeHandle& nh) {
  bool none_given = true;
  for (const auto& [param, topics] : params_.topics) {
    none_given = none_given && topics.empty();
  }
  for (const auto& input : inputs_->inputs()) {
    const std::vector<std::string> topics =
        none_given ? input->defaultTopics(layout_) : params_.topics[input->topicsParam()];
    for (const std::string& topic : topics) {
      const std::size_t index = subscribers_.size();
      subscribers_.push_back(input->subscribe(
          nh, topic, [this, index, topic](const std::function<std::size_t()>& handle) {
            barrier_.run(topic, [&] {
              noteInput(index);
              ignored_messages_ += handle();
            });
          }));
      debugSubscribed(subscribers_.back());
    }
  }
}

void LocatorNode::noteInput(std::size_t index) {
  if (inputs_watch_->onMessage(index, ros::Time::now().toSec())) {
    ROS_DEBUG_NAMED("wiring", "locator: first message on %s",
                    inputs_watch_->inputs()[index].name.c_str());
  }
}

void LocatorNode::watchInputs(const ros::Time& now) {
  if (last_tick_.isZero()) {
    inputs_watch_->startAt(now.toSec());  // on simulated time the clock may only start now
  } else if (now < last_tick_) {
    inputs_watch_->restart(now.toSec());  // the clock jumped back: every input is new
  }
  last_tick_ = now;
  for (const std::size_t i : inputs_watch_->dueWarnings(now.toSec())) {
    const InputWatch::Input& input = inputs_watch_->inputs()[i];
    if (input.messages == 0) {
      ROS_WARN(
          "locator: no message on %s since the start (%.1f s); is its driver running and "
          "publishing there? (rostopic info %s)",
          input.name.c_str(), inputs_watch_->silenceSeconds(i, now.toSec()), input.name.c_str());
    } else {
      ROS_WARN("locator: no message on %s for %.1f s (%zu before)", input.name.c_str(),
               inputs_watch_->silenceSeconds(i, now.toSec()), input.messages);
    }
  }
  const estimation::LocatorStats& s = locator_->stats();
  if (s.stale_dropped != last_stats_.stale_dropped) {
    ROS_DEBUG_THROTTLE_NAMED(2.0, "wiring",
                             "locator: %zu measurement(s) dropped, older than max_age %.2f s "
                             "(clocks of driver and locator apart, or a slow link)",
                             s.stale_dropped - last_stats_.stale_dropped, params_.locator.max_age);
  }
  if (s.future_dropped != last_stats_.future_dropped) {
    ROS_DEBUG_THROTTLE_NAMED(2.0, "wiring",
                             "locator: %zu measurement(s) dropped, stamped ahead of this clock",
                             s.future_dropped - last_stats_.future_dropped);
  }
  if (s.invalid_measurements != last_stats_.invalid_measurements) {
    ROS_DEBUG_THROTTLE_NAMED(2.0, "wiring", "locator: %zu invalid measurement(s) dropped",
                             s.invalid_measurements - last_stats_.invalid_measurements);
  }
  if (s.bearings_rejected_fov != last_stats_.bearings_rejected_fov) {
    ROS_DEBUG_THROTTLE_NAMED(2.0, "wiring",
                             "locator: %zu bearing(s) not used: board's field of view does not "
                             "contain the estimate",
                             s.bearings_rejected_fov - last_stats_.bearings_rejected_fov);
  }
  last_stats_ = s;
}

void LocatorNode::onTimer(const ros::TimerEvent& /*event*/) {
  const ros::Time now = ros::Time::now();
  const std::size_t solves_before = locator_->stats().solves;
  const estimation::LocatorEstimate estimate = locator_->update(now.toSec());
  if (locator_->stats().solves != solves_before) {
    const double s = locator_->stats().last_solve_seconds;
    solve_seconds_sum_ += s;
    solve_seconds_max_ = std::max(solve_seconds_max_, s);
    ++solves_seen_;
  }
  if (estimate.status != last_status_) {
    ROS_INFO("locator: target %s -> %s", toString(last_status_), toString(estimate.status));
    last_status_ = estimate.status;
  }
  last_spread_ = polarSpread(estimate.position.head<2>(), estimate.covariance.topLeftCorner<2, 2>());
  publish(estimate, now);
  watchInputs(now);
  diagnostics_.update();
}

void LocatorNode::publish(const estimation::LocatorEstimate& estimate, const ros::Time& now) {
  // The estimate is stamped with its newest measurement; LOST with the current time.
  // A stamp ros::Time cannot hold (NaN, negative, past 2^32 s) would throw: it gets now.
  const bool representable = estimate.stamp >= 0.0 && estimate.stamp < 4294967295.0;
  const ros::Time stamp =
      estimate.status == TargetStatus::kLost || !representable ? now : ros::Time(estimate.stamp);
  TargetEstimate msg = toMessage(estimate, layout_.fixed_frame, stamp);
  if (tf_buffer_) {
    // The controllers track the target in the odometry frame: the particle estimator's
    // own state, else the solver's position placed with the odometry pose at its stamp
    // and a velocity fitted to those positions.
    const std::optional<estimation::OdometryEstimate> odom =
        odometry_track_.update(estimate, [&](double /*t*/) { return odometryPose(stamp); });
    if (odom) {
      setOdometry(msg, *odom, params_.odom_frame);
    }
  }
  // Always published, LOST included: a controller must hear that the target is gone.
  target_pub_.publish(msg);
  target_diagnostic_->tick(stamp);

  if (hasPosition(estimate.status)) {
    geometry_msgs::PoseWithCovarianceStamped pose;
    pose.header.frame_id = layout_.fixed_frame;
    pose.header.stamp = stamp;
    pose.pose.pose.position.x = estimate.position.x();
    pose.pose.pose.position.y = estimate.position.y();
    pose.pose.pose.position.z = estimate.position.z();
    pose.pose.pose.orientation.w = 1.0;
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) {
        pose.pose.covariance[static_cast<std::size_t>(6 * r + c)] = estimate.covariance(r, c);
      }
    }
    // Orientation is not estimated: infinite-like variance says so to consumers.
    for (int i = 3; i < 6; ++i) {
      pose.pose.covariance[static_cast<std::size_t>(6 * i + i)] = 1e6;
    }
    pose_pub_.publish(pose);
    pose_diagnostic_->tick(stamp);
    extendPath(estimate, stamp);
    // The estimate is stamped with its newest measurement; solving faster than the sensors
    // report repeats a stamp, which tf2 rejects (TF_REPEATED_DATA): send each stamp once.
    if (params_.publish_tf && pose.header.stamp > last_tf_stamp_) {
      last_tf_stamp_ = pose.header.stamp;
      geometry_msgs::TransformStamped t;
      t.header = pose.header;
      t.child_frame_id = params_.target_frame;
      t.transform.translation.x = estimate.position.x();
      t.transform.translation.y = estimate.position.y();
      t.transform.translation.z = estimate.position.z();
      t.transform.rotation.w = 1.0;
      tf_.sendTransform(t);
    }
  }
  if (markers_pub_.getNumSubscribers() > 0) {  // drawing is the node's largest cost
    markers_pub_.publish(locatorMarkers(layout_, params_.locator, estimate, now));
  }
}

void LocatorNode::extendPath(const estimation::LocatorEstimate& estimate, const ros::Time& stamp) {
  if (params_.path_length == 0 || (!path_.poses.empty() && stamp == path_.header.stamp)) {
    return;  // no path, or the same estimate again (solving faster than the sensors)
  }
  geometry_msgs::PoseStamped pose;
  pose.header.frame_id = layout_.fixed_frame;
  pose.header.stamp = stamp;
  pose.pose.position.x = estimate.position.x();
  pose.pose.position.y = estimate.position.y();
  pose.pose.position.z = estimate.position.z();
  pose.pose.orientation.w = 1.0;
  if (!path_.poses.empty() && stamp < path_.header.stamp) {
    path_.poses.clear();  // the clock jumped back
  }
  path_.poses.push_back(pose);
  if (path_.poses.size() > static_cast<std::size_t>(params_.path_length)) {
    path_.poses.erase(path_.poses.begin());
  }
  path_.header.stamp = stamp;
  if (path_pub_.getNumSubscribers() > 0) {
    path_pub_.publish(path_);
  }
}

void LocatorNode::diagnose(diagnostic_updater::DiagnosticStatusWrapper& status) {
  const estimation::LocatorStats& s = locator_->stats();
  const estimation::KalmanFilter& f = locator_->filter();
  if (last_status_ == TargetStatus::kOk) {
    status.summary(diagnostic_msgs::DiagnosticStatus::OK, "tracking");
  } else if (last_status_ == TargetStatus::kLost) {
    status.summary(diagnostic_msgs::DiagnosticStatus::WARN, "target lost");
  } else {
    status.summary(diagnostic_msgs::DiagnosticStatus::WARN, toString(last_status_));
  }
  status.add("status", toString(last_status_));
  if (hasPosition(last_status_)) {
    // Which way the estimate is uncertain: a DEGRADED range-only track is sure of the
    // distance and not of the direction (the controllers follow it at full speed while
    // the direction is within their max_follow_sigma).
    status.addf("range sigma", "%.3f m", last_spread_.range_sigma);
    status.addf("bearing sigma", "%.1f deg", last_spread_.bearing_sigma * 180.0 / M_PI);
  }
  status.add("updates", s.updates);
  status.add("solves", s.solves);
  status.add("solver failures", s.solver_failures);
  status.add("stale measurements dropped", s.stale_dropped);
  status.add("future-stamped measurements dropped", s.future_dropped);
  status.add("callback faults", barrier_.faults());
  if (barrier_.faults() > 0) {
    status.add("last callback fault", barrier_.lastFault());
  }
  status.add("non-finite epochs", s.non_finite);
  status.add("ambiguous epochs (mirror test)", s.ambiguous);
  status.add("invalid measurements", s.invalid_measurements);
  status.add("bearings not selected", s.bearings_rejected_fov);
  status.add("filter gated", f.gatedCount());
  status.add("filter invalid", f.invalidCount());
  status.add("filter resets", f.resetCount());
  status.add("lost epochs", s.lost);
  status.add("ignored messages", ignored_messages_);
  for (const auto& input : inputs_->inputs()) {
    input->diagnose(status);
  }
  status.add("solve time mean (us)",
             solves_seen_ > 0 ? 1e6 * solve_seconds_sum_ / static_cast<double>(solves_seen_) : 0.0);
  status.add("solve time max (us)", 1e6 * solve_seconds_max_);
  const double now = ros::Time::now().toSec();
  std::string silent;
  for (const std::size_t i : inputs_watch_->silentInputs(now)) {
    silent += (silent.empty() ? "" : ", ") + inputs_watch_->inputs()[i].name;
  }
  status.add("silent inputs", silent.empty() ? "none" : silent);
  for (const InputWatch::Input& input : inputs_watch_->inputs()) {
    status.add("messages on " + input.name, input.messages);
  }
  if (!silent.empty()) {
    status.mergeSummaryf(diagnostic_msgs::DiagnosticStatus::WARN, "silent inputs: %s",
                         silent.c_str());
  }
}

}  // namespace radio_follow
