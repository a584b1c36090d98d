// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/ros/path_follower.hpp"

#include <tf2/utils.h>
#include <tf2_geometry_msgs/tf2_geometry_msgs.h>

#include <algorithm>
#include <cmath>

#include "radio_follow/common/param_error.hpp"
#include "radio_follow/ros/controller_reconfigure.hpp"
#include "radio_follow/ros/params.hpp"
#include "radio_follow/ros/target_estimate.hpp"
#include "radio_follow/ros/velocity_controller.hpp"

namespace radio_follow {

void PathFollowerNode::Params::load(const ParamReader& pnh) {
  pnh.param("odom_frame", odom_frame, odom_frame);
  pnh.param("base_frame", base_frame, base_frame);
  pnh.param("path_spacing", path_spacing, path_spacing);
  pnh.param("max_path_points", max_path_points, max_path_points);
  pnh.param("lookahead", lookahead, lookahead);
  pnh.param("reached_radius", reached_radius, reached_radius);
  pnh.param("turn_gain", turn_gain, turn_gain);
  pnh.param("tf_timeout", tf_timeout, tf_timeout);
}

void PathFollowerNode::Params::validate() const {
  require(!odom_frame.empty(), "~odom_frame", odom_frame, "a frame id");
  require(!base_frame.empty(), "~base_frame", base_frame, "a frame id");
  require(path_spacing > 0.0, "~path_spacing", path_spacing, "a spacing > 0 in metres");
  require(max_path_points >= 2, "~max_path_points", max_path_points, "a count >= 2");
  require(lookahead > 0.0, "~lookahead", lookahead, "a distance > 0 in metres");
  require(reached_radius > 0.0, "~reached_radius", reached_radius, "a distance > 0 in metres");
  require(turn_gain > 0.0, "~turn_gain", turn_gain, "a gain > 0 in 1/s");
  require(tf_timeout >= 0.0 && tf_timeout < 1.0, "~tf_timeout", tf_timeout,
          "a timeout in [0, 1) seconds");
}

PathFollowerNode::PathFollowerNode(ros::NodeHandle& nh, ros::NodeHandle& private_nh)
    : ControllerBase(nh, private_nh, true),
      params_(loadValidated<Params>(params())),
      law_params_(loadVelocityLawParams(params(), common())),
      fallback_law_(law_params_),
      speed_pid_(law_params_.linear),
      path_(params_.path_spacing, static_cast<std::size_t>(params_.max_path_points)),
      tf_listener_(tf_buffer_),
      motion_(tf_buffer_, params_.odom_frame, params_.tf_timeout) {
  requireKnownParams();
  path_pub_ = private_nh_.advertise<nav_msgs::Path>("path", 1, true);
  estimate_sub_ = nh_.subscribe("target", 5, &PathFollowerNode::onEstimate, this);
  debugSubscribed(estimate_sub_);
  debugAdvertised(path_pub_);
  law_reconfigure_ = makeFollowLawReconfigure(
      private_nh, law_params_, [this](const control::VelocityLawParams& p) {
        applyLaw(lawWithCommon(p, common()));  // against the safety layer as it is now
      });
  start();
}

PathFollowerNode::~PathFollowerNode() = default;

void PathFollowerNode::onCommonChange(const ControllerCommonParams& next) {
  applyLaw(lawWithCommon(law_params_, next));  // throws to refuse the change
}

void PathFollowerNode::applyLaw(const control::VelocityLawParams& p) {
  law_params_ = p;
  fallback_law_.setParams(p);
  speed_pid_.setGains(p.linear);
}

void PathFollowerNode::onStopped() {
  fallback_law_.reset();
  speed_pid_.reset();
  arrived_ = false;
}

void PathFollowerNode::onEstimate(const TargetEstimate::ConstPtr& msg) {
  estimate_ = msg;
  noteEstimate(msg->header.stamp, estimateQuality(*msg));
  // Only full positions extend the path: a HEADING_ONLY position is a guess.
  if (!hasPosition(*msg)) {
    return;
  }
  const std::optional<Eigen::Vector2d> point = motion_.add(*msg);
  path_mode_ = point.has_value();
  if (!point) {
    ROS_WARN_THROTTLE(5.0, "%s: no transform %s <- %s at the estimate's stamp (%s)",
                      ros::this_node::getName().c_str(), params_.odom_frame.c_str(),
                      msg->header.frame_id.c_str(), motion_.lastError().c_str());
    return;
  }
  if (path_.add(*point)) {
    publishPath(msg->header.stamp);
  }
}

std::optional<control::Pose2> PathFollowerNode::robotPose() {
  try {
    const auto t = tf_buffer_.lookupTransform(params_.odom_frame, params_.base_frame, ros::Time(0));
    control::Pose2 pose;
    pose.x = t.transform.translation.x;
    pose.y = t.transform.translation.y;
    pose.yaw = tf2::getYaw(t.transform.rotation);
    return pose;
  } catch (const tf2::TransformException& e) {
    ROS_WARN_THROTTLE(5.0, "%s: no robot pose %s <- %s (%s)", ros::this_node::getName().c_str(),
                      params_.odom_frame.c_str(), params_.base_frame.c_str(), e.what());
    return std::nullopt;
  }
}

void PathFollowerNode::publishPath(const ros::Time& stamp) {
  nav_msgs::Path msg;
  msg.header.stamp = stamp;
  msg.header.frame_id = params_.odom_frame;
  for (const auto& p : path_.points()) {
    geometry_msgs::PoseStamped pose;
    pose.header = msg.header;
    pose.pose.position.x = p.x();
    pose.pose.position.y = p.y();
    pose.pose.orientation.w = 1.0;
    msg.poses.push_back(pose);
  }
  path_pub_.publish(msg);
}

ControllerBase::Output PathFollowerNode::compute(const ros::Time& now, double dt) {
  Output out;
  const bool heading_only = estimate_->status == TargetEstimate::STATUS_HEADING_ONLY;
  const std::optional<control::Pose2> robot = path_mode_ ? robotPose() : std::nullopt;
  if (!robot || path_.empty() || heading_only) {
    // Without self-localisation no path can be stored: drive straight at the target.
    out.command = fallback_law_.update(targetPolar(*estimate_, std::nullopt, moduleGap(now)), dt);
    if (heading_only) {
      out.text = "Direction only, turning to the target.";
    } else if (fallback_law_.arrived()) {
      out.state = control::FollowerState::kArrived;
      out.text = "At follow distance, waiting.";
    } else {
      out.text = "No odometry, driving straight to the target.";
    }
    return out;
  }

  const std::size_t before = path_.points().size();
  path_.prune(robot->position(), params_.reached_radius);
  if (path_.points().size() != before) {
    publishPath(now);
  }
  const control::PursuitTarget goal =
      control::purePursuit(path_.points(), *robot, params_.lookahead);
  // A path built from noisy estimates zig-zags and is longer than the walk; the straight
  // range is never longer than the walk. The smaller of the two keeps the robot from
  // closing in on a person who has stopped because their path looked long.
  const double along = path_.lengthFrom(robot->position());
  const double gap = control::governingGap(
      std::min(along, estimate_->range) - law_params_.follow_distance, moduleGap(now), law_params_);
  const double alpha = std::atan2(goal.local.y(), goal.local.x());
  // The person walks the path ahead: the feed-forward is their whole ground speed.
  const double walking_speed = motion_.speed(now).value_or(0.0);
  double speed = control::gapSpeed(gap, walking_speed, dt, speed_pid_, law_params_);
  speed *= std::max(0.0, std::cos(alpha));
  if (estimate_->status == TargetEstimate::STATUS_DEGRADED) {
    speed *= law_params_.degraded_speed_factor;
  }
  out.command.linear = speed;
  // Pure pursuit steers along the arc; a goal behind the robot (after it stopped and the
  // person walked around it) needs turning in place first.
  out.command.angular =
      std::abs(alpha) > 0.5 * M_PI ? params_.turn_gain * alpha : speed * goal.curvature;
  arrived_ = control::updateArrived(arrived_, gap, walking_speed);
  if (arrived_) {
    out.state = control::FollowerState::kArrived;
    out.text = "At follow distance, waiting.";
  } else if (estimate_->status == TargetEstimate::STATUS_DEGRADED) {
    out.text = "Following the path slowly, the position is uncertain.";
  } else {
    out.text = "Following the path.";
  }
  return out;
}

}  // namespace radio_follow
