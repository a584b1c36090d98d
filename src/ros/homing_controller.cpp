// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/ros/homing_controller.hpp"

#include <geometry_msgs/PoseStamped.h>
#include <tf2/utils.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>

#include "radio_follow/common/angles.hpp"
#include "radio_follow/common/param_error.hpp"
#include "radio_follow/common/param_keys.hpp"

namespace radio_follow {

void HomingControllerNode::Params::load(const ParamReader& pnh) {
  pnh.param("tag_id", tag_id, tag_id);
  tag_id = normalizeId(tag_id);
  pnh.param("board_x", board_x, board_x);
  pnh.param("board_y", board_y, board_y);
  pnh.param("board_yaw", board_yaw, board_yaw);
  pnh.param("distance_source", distance_source, distance_source);
  pnh.param("distance_range_topic", distance_range_topic, distance_range_topic);
  pnh.param("distance_max_age", distance_max_age, distance_max_age);
  pnh.param("odom_timeout", odom_timeout, odom_timeout);
  pnh.param("search_speed", search_speed, search_speed);
  pnh.param("rssi_at_1m", rssi.rssi_at_1m, rssi.rssi_at_1m);
  pnh.param("rssi_exponent", rssi.exponent, rssi.exponent);
  pnh.param("tau", homing.tau, homing.tau);
  pnh.param("window", homing.window, homing.window);
  pnh.param("kohonen_k", homing.k, homing.k);
  pnh.param("min_baseline", homing.min_baseline, homing.min_baseline);
  pnh.param("min_parallax_angle", homing.min_parallax_angle, homing.min_parallax_angle);
  pnh.param("error_threshold", homing.error_threshold, homing.error_threshold);
  pnh.param("z_threshold", homing.z_threshold, homing.z_threshold);
  pnh.param("arrival_distance", homing.arrival_distance, homing.arrival_distance);
  pnh.param("agreement_distance", homing.agreement_distance, homing.agreement_distance);
  pnh.param("linear_gain", homing.linear_gain, homing.linear_gain);
  pnh.param("angular_gain", homing.angular_gain, homing.angular_gain);
}

void HomingControllerNode::Params::validate() const {
  require(std::isfinite(board_x) && std::isfinite(board_y), "~board_x/~board_y", board_x,
          "finite metres");
  require(std::isfinite(board_yaw), "~board_yaw", board_yaw, "a finite angle in rad");
  require(distance_source == "rssi" || distance_source == "uwb", "~distance_source",
          distance_source, "'rssi' or 'uwb'");
  requireGraphName("~distance_range_topic", distance_range_topic);
  require(distance_max_age > 0.0, "~distance_max_age", distance_max_age, "seconds > 0");
  require(odom_timeout > 0.0, "~odom_timeout", odom_timeout, "seconds > 0");
  require(search_speed >= 0.0, "~search_speed", search_speed, "a speed >= 0 in m/s");
  rssi.validate();
  homing.validate();
}

HomingControllerNode::HomingControllerNode(ros::NodeHandle& nh, ros::NodeHandle& private_nh)
    : ControllerBase(nh, private_nh, false),
      params_([&] {
        Params p;
        p.load(params());
        p.homing.max_linear = common().limits.max_linear;
        p.homing.max_angular = common().limits.max_angular;
        p.validate();
        return p;
      }()),
      homing_(params_.homing) {
  requireKnownParams();
  goal_pub_ = private_nh_.advertise<geometry_msgs::PoseStamped>("goal", 1, true);
  odom_sub_ = nh_.subscribe("odom", 10, &HomingControllerNode::onOdom, this);
  bearing_sub_ = nh_.subscribe("aoa_bearing", 20, &HomingControllerNode::onBearing, this);
  debugSubscribed(odom_sub_);
  debugSubscribed(bearing_sub_);
  if (params_.distance_source == "uwb") {
    distance_sub_ = nh_.subscribe(params_.distance_range_topic, 10,
                                  &HomingControllerNode::onDistanceRanges, this);
  }
  start();
}

void HomingControllerNode::onOdom(const nav_msgs::Odometry::ConstPtr& msg) {
  const ros::Time now = ros::Time::now();
  const ros::Time stamp = msg->header.stamp.isZero() ? now : msg->header.stamp;
  control::Pose2 pose;
  pose.x = msg->pose.pose.position.x;
  pose.y = msg->pose.pose.position.y;
  pose.yaw = tf2::getYaw(msg->pose.pose.orientation);
  if (time_.jumpedBack(now.toSec())) {
    resetTrack("the clock jumped back");
  }
  // One NaN pose would otherwise enter every later goal through the parallax estimate.
  if (!std::isfinite(pose.x) || !std::isfinite(pose.y) || !std::isfinite(pose.yaw) ||
      time_.check(stamp.toSec(), now.toSec()) == TimePolicy::Verdict::kFuture) {
    ++odom_refused_;
    ROS_WARN_THROTTLE(5.0, "%s: odometry refused (non-finite pose or stamp from the future)",
                      ros::this_node::getName().c_str());
    return;
  }
  robot_ = pose;
  odom_stamp_ = stamp;
  odom_frame_ = msg->header.frame_id;
}

void HomingControllerNode::resetTrack(const char* why) {
  ROS_WARN("%s: %s, homing starts over", ros::this_node::getName().c_str(), why);
  robot_.reset();
  last_bearing_.reset();
  uwb_stamp_ = ros::Time();
  homing_ = control::HybridHoming(params_.homing);
}

void HomingControllerNode::onDistanceRanges(const UwbRanges::ConstPtr& msg) {
  for (const auto& r : msg->ranges) {
    if ((common().target_anchor_id.empty() ||
         normalizeId(r.anchor_id) == common().target_anchor_id) &&
        std::isfinite(r.range) && r.range >= 0.0) {
      uwb_distance_ = r.range;
      uwb_stamp_ = msg->header.stamp.isZero() ? ros::Time::now() : msg->header.stamp;
    }
  }
}

void HomingControllerNode::onBearing(const AoaBearing::ConstPtr& msg) {
  if (!params_.tag_id.empty() && normalizeId(msg->tag_id) != params_.tag_id) {
    return;
  }
  const ros::Time stamp = msg->header.stamp.isZero() ? ros::Time::now() : msg->header.stamp;
  if (!robot_ || std::abs((stamp - odom_stamp_).toSec()) > params_.odom_timeout) {
    ROS_WARN_THROTTLE(5.0, "%s: bearing without odometry within %.2f s, ignored",
                      ros::this_node::getName().c_str(), params_.odom_timeout);
    return;
  }
  if (!std::isfinite(msg->azimuth)) {
    return;
  }
  // The board's position and boresight in the odometry frame.
  const double c = std::cos(robot_->yaw);
  const double s = std::sin(robot_->yaw);
  const Eigen::Vector2d sensor(robot_->x + c * params_.board_x - s * params_.board_y,
                               robot_->y + s * params_.board_x + c * params_.board_y);
  const double bearing = wrapAngle(robot_->yaw + params_.board_yaw + msg->azimuth);

  double distance = std::numeric_limits<double>::quiet_NaN();
  if (params_.distance_source == "rssi") {
    distance = std::isfinite(msg->rssi) ? params_.rssi.distance(msg->rssi) : distance;
  } else if (!uwb_stamp_.isZero() &&
             std::abs((stamp - uwb_stamp_).toSec()) <= params_.distance_max_age) {
    distance = uwb_distance_;
  }
  homing_.update(sensor, bearing, distance);
  last_bearing_ = bearing;
  // A fresh bearing is a usable observation even before a goal exists: compute() then
  // searches along it, which is how the parallax estimate gets its baseline.
  noteEstimate(stamp, control::EstimateQuality::kUsable);

  if (homing_.goal()) {
    geometry_msgs::PoseStamped goal;
    goal.header.stamp = stamp;
    goal.header.frame_id = odom_frame_;
    goal.pose.position.x = homing_.goal()->x();
    goal.pose.position.y = homing_.goal()->y();
    // Facing the target from where the robot is now: what a planner should aim for.
    const double heading =
        std::atan2(homing_.goal()->y() - robot_->y, homing_.goal()->x() - robot_->x);
    goal.pose.orientation.z = std::sin(0.5 * heading);
    goal.pose.orientation.w = std::cos(0.5 * heading);
    goal_pub_.publish(goal);
  }
}

ControllerBase::Output HomingControllerNode::compute(const ros::Time& now, double /*dt*/) {
  Output out;
  if (!robot_ || (now - odom_stamp_).toSec() > params_.odom_timeout) {
    out.state = control::FollowerState::kWaitingForTarget;
    out.text = "No odometry, waiting.";
    return out;
  }
  if (!homing_.goal()) {
    // No distance and no parallax yet: creep along the bearing so the parallax estimate
    // gets its baseline (seed 000 needs two readings taken at different places).
    out.state = control::FollowerState::kWaitingForTarget;
    out.text = "Searching for the target.";
    if (last_bearing_) {
      control::HomingParams search = params_.homing;
      search.max_linear = std::min(search.max_linear, params_.search_speed);
      const Eigen::Vector2d ahead =
          robot_->position() + Eigen::Vector2d(std::cos(*last_bearing_), std::sin(*last_bearing_));
      out.command = control::homingVelocity(*robot_, ahead, search);
    }
    return out;
  }
  if (homing_.arrived(robot_->position())) {
    out.state = control::FollowerState::kArrived;
    out.text = "Arrived at the target.";
    return out;
  }
  out.command = control::homingVelocity(*robot_, *homing_.goal(), params_.homing);
  out.text = "Homing to the target.";
  return out;
}

}  // namespace radio_follow
