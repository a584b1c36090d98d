// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/ros/locator_node.hpp"

#include <geometry_msgs/PoseWithCovarianceStamped.h>
#include <geometry_msgs/TransformStamped.h>

#include <algorithm>
#include <cmath>

namespace radio_follow {

TargetEstimate toMessage(const LocatorEstimate& estimate, const std::string& frame,
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
  return msg;
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
  layout_ = loadLayoutFile(params_.layout_file);  // validated: target anchor set with TWR
  locator_ = std::make_unique<Locator>(layout_, params_.locator);
  inputs_ = std::make_unique<LocatorInputs>(*locator_);
  if (params_.uwb_topics.empty() && params_.aoa_topics.empty() && params_.tdoa_topics.empty()) {
    const SensorTopics topics = conventionalTopics(layout_);
    params_.uwb_topics = topics.uwb;
    params_.aoa_topics = topics.aoa;
    params_.tdoa_topics = topics.tdoa;
  }

  target_pub_ = nh.advertise<TargetEstimate>("target", 10);
  pose_pub_ = nh.advertise<geometry_msgs::PoseWithCovarianceStamped>("target_pose", 10);
  markers_pub_ = nh.advertise<visualization_msgs::MarkerArray>("markers", 1);
  for (const auto& topic : params_.uwb_topics) {
    subscribers_.push_back(nh.subscribe(topic, 50, &LocatorNode::onRanges, this));
  }
  for (const auto& topic : params_.aoa_topics) {
    subscribers_.push_back(nh.subscribe(topic, 50, &LocatorNode::onBearing, this));
  }
  for (const auto& topic : params_.tdoa_topics) {
    subscribers_.push_back(nh.subscribe(topic, 50, &LocatorNode::onTdoa, this));
  }
  reconfigure_ =
      makeLocatorReconfigure(private_nh, params_.locator, [this](const LocatorConfig& config) {
        if (!locator_->setConfig(config)) {
          ROS_INFO("locator: motion model changed, the filter restarts from the next solve");
        }
        params_.locator = config;
      });
  diagnostics_.setHardwareID("locator");
  diagnostics_.add("locator", this, &LocatorNode::diagnose);
  timer_ = nh.createTimer(ros::Duration(1.0 / params_.rate), &LocatorNode::onTimer, this);
  ROS_INFO("locator: %s mode, %zu TWR modules, %zu AoA boards, %zu TDoA anchors, %.1f Hz",
           params_.locator.planar ? "2D" : "3D", layout_.twr_modules.size(),
           layout_.aoa_boards.size(), layout_.tdoa_anchors.size(), params_.rate);
}

void LocatorNode::onRanges(const UwbRanges::ConstPtr& msg) {
  if (const std::size_t refused = inputs_->add(*msg)) {
    ignored_messages_ += refused;
    ROS_WARN_THROTTLE(5.0, "locator: ignoring range from unknown module '%s' or invalid value",
                      (msg->tag_id.empty() ? msg->header.frame_id : msg->tag_id).c_str());
  }
  if (inputs_->targetRanges() == 0 && !inputs_->otherAnchors().empty()) {
    // Ranges arrive, none to the target: a wrong target.uwb_anchor_id leaves the
    // estimate LOST for good, so say which anchors are heard.
    std::string heard;
    for (const auto& [anchor, count] : inputs_->otherAnchors()) {
      heard += (heard.empty() ? "" : ", ") + anchor;
    }
    ROS_WARN_THROTTLE(5.0,
                      "locator: ranges to anchor(s) %s but none to the layout's target "
                      "'%s' (target.uwb_anchor_id in %s)",
                      heard.c_str(), layout_.target_anchor_id.c_str(), params_.layout_file.c_str());
  }
}

void LocatorNode::onBearing(const AoaBearing::ConstPtr& msg) {
  if (inputs_->add(*msg) != 0) {
    ++ignored_messages_;
    ROS_WARN_THROTTLE(5.0, "locator: ignoring bearing from unknown board frame '%s'",
                      msg->header.frame_id.c_str());
  }
}

void LocatorNode::onTdoa(const TdoaMeasurements::ConstPtr& msg) {
  if (const std::size_t refused = inputs_->add(*msg)) {
    ignored_messages_ += refused;
    ROS_WARN_THROTTLE(5.0, "locator: ignoring %zu TDoA difference(s) (unknown anchor?)", refused);
  }
}

void LocatorNode::onTimer(const ros::TimerEvent& /*event*/) {
  const ros::Time now = ros::Time::now();
  const std::size_t solves_before = locator_->stats().solves;
  const LocatorEstimate estimate = locator_->update(now.toSec());
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
  publish(estimate, now);
  diagnostics_.update();
}

void LocatorNode::publish(const LocatorEstimate& estimate, const ros::Time& now) {
  // The estimate is stamped with its newest measurement; LOST with the current time.
  const ros::Time stamp =
      estimate.status == TargetStatus::kLost ? now : ros::Time(std::max(0.0, estimate.stamp));
  // Always published, LOST included: a controller must hear that the target is gone.
  target_pub_.publish(toMessage(estimate, layout_.fixed_frame, stamp));

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

void LocatorNode::diagnose(diagnostic_updater::DiagnosticStatusWrapper& status) {
  const LocatorStats& s = locator_->stats();
  const KalmanFilter& f = locator_->filter();
  if (last_status_ == TargetStatus::kOk) {
    status.summary(diagnostic_msgs::DiagnosticStatus::OK, "tracking");
  } else if (last_status_ == TargetStatus::kLost) {
    status.summary(diagnostic_msgs::DiagnosticStatus::WARN, "target lost");
  } else {
    status.summary(diagnostic_msgs::DiagnosticStatus::WARN, toString(last_status_));
  }
  status.add("status", toString(last_status_));
  status.add("updates", s.updates);
  status.add("solves", s.solves);
  status.add("solver failures", s.solver_failures);
  status.add("stale measurements dropped", s.stale_dropped);
  status.add("future-stamped measurements dropped", s.future_dropped);
  status.add("non-finite epochs", s.non_finite);
  status.add("ambiguous epochs (mirror test)", s.ambiguous);
  status.add("invalid measurements", s.invalid_measurements);
  status.add("bearings not selected", s.bearings_rejected_fov);
  status.add("filter gated", f.gatedCount());
  status.add("filter invalid", f.invalidCount());
  status.add("filter resets", f.resetCount());
  status.add("lost epochs", s.lost);
  status.add("ignored messages", ignored_messages_);
  std::size_t other = 0;
  for (const auto& entry : inputs_->otherAnchors()) {
    other += entry.second;
  }
  status.add("ranges to the target anchor", inputs_->targetRanges());
  status.add("ranges to other anchors", other);
  status.add("solve time mean (us)",
             solves_seen_ > 0 ? 1e6 * solve_seconds_sum_ / static_cast<double>(solves_seen_) : 0.0);
  status.add("solve time max (us)", 1e6 * solve_seconds_max_);
}

}  // namespace radio_follow
