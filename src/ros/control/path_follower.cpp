// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/ros/control/path_follower.hpp"

#include <tf2/utils.h>
#include <tf2_geometry_msgs/tf2_geometry_msgs.h>

#include <algorithm>
#include <cmath>

#include "radio_follow/common/param_error.hpp"
#include "radio_follow/ros/common/params.hpp"
#include "radio_follow/ros/common/target_estimate.hpp"
#include "radio_follow/ros/control/controller_reconfigure.hpp"
#include "radio_follow/ros/control/velocity_controller.hpp"

namespace radio_follow {

void PathFollowerNode::Params::load(const ParamReader& pnh) {
  pnh.param("odom_frame", odom_frame, odom_frame);
  pnh.param("base_frame", base_frame, base_frame);
  pnh.param("tf_timeout", tf_timeout, tf_timeout);
  path.load(pnh);
}

void PathFollowerNode::Params::validate() const {
  require(!odom_frame.empty(), "~odom_frame", odom_frame, "a frame id");
  require(!base_frame.empty(), "~base_frame", base_frame, "a frame id");
  path.validate();
  require(tf_timeout >= 0.0 && tf_timeout < 1.0, "~tf_timeout", tf_timeout,
          "a timeout in [0, 1) seconds");
}

PathFollowerNode::PathFollowerNode(ros::NodeHandle& nh, ros::NodeHandle& private_nh)
    : ControllerBase(nh, private_nh, true),
      params_(loadValidated<Params>(params())),
      law_(params_.path, loadVelocityLawParams(params(), common())),
      tf_listener_(tf_buffer_),
      motion_(tf_buffer_, params_.odom_frame, params_.tf_timeout) {
  requireKnownParams();
  path_pub_ = private_nh_.advertise<nav_msgs::Path>("path", 1, true);
  estimate_sub_ = barrier_.subscribe(nh_, "target", 5, &PathFollowerNode::onEstimate, this);
  debugSubscribed(estimate_sub_);
  debugAdvertised(path_pub_);
  law_reconfigure_ = makeFollowLawReconfigure(
      private_nh, law_.lawParams(), [this](const control::VelocityLawParams& p) {
        law_.setLawParams(lawWithCommon(p, common()));  // against the safety layer as it is now
      });
  start();
}

PathFollowerNode::~PathFollowerNode() = default;

void PathFollowerNode::onCommonChange(const ControllerCommonParams& next) {
  law_.setLawParams(lawWithCommon(law_.lawParams(), next));  // throws to refuse the change
}

void PathFollowerNode::onStopped() {
  law_.reset();
}

void PathFollowerNode::onEstimate(const TargetEstimate::ConstPtr& msg) {
  if (!noteEstimate(msg->header.stamp, estimateQuality(*msg))) {
    return;  // from the future: the robot stops, and nothing of it reaches the law or TF
  }
  estimate_ = msg;
  // Only full positions extend the path: a HEADING_ONLY position is a guess.
  if (!hasPosition(*msg)) {
    return;
  }
  const std::optional<Eigen::Vector2d> point = motion_.add(*msg);
  if (!point && motion_.lastError().empty()) {
    return;  // a young track's wide position (control::TrackGate): not a path point
  }
  path_mode_ = point.has_value();
  if (!point) {
    ROS_WARN_THROTTLE(5.0, "%s: no transform %s <- %s at the estimate's stamp (%s)",
                      ros::this_node::getName().c_str(), params_.odom_frame.c_str(),
                      msg->header.frame_id.c_str(), motion_.lastError().c_str());
    return;
  }
  if (law_.addTarget(*point)) {
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
  for (const auto& p : law_.path().points()) {
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
  const std::optional<control::Pose2> robot = path_mode_ ? robotPose() : std::nullopt;
  const std::size_t before = law_.path().points().size();
  Output out = law_.step(targetPolar(*estimate_, std::nullopt, moduleGap(now)), robot,
                         motion_.speed(now), dt);
  if (law_.path().points().size() != before) {
    publishPath(now);  // the robot passed some points
  }
  return out;
}

}  // namespace radio_follow
