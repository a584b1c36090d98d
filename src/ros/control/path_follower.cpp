// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/ros/control/path_follower.hpp"

#include <tf2/utils.h>
#include <tf2_geometry_msgs/tf2_geometry_msgs.h>

#include "radio_follow/common/param_error.hpp"
#include "radio_follow/ros/common/wiring_debug.hpp"
#include "radio_follow/ros/control/controller_reconfigure.hpp"

namespace radio_follow {

const ParamTable<PathFollowerNode::Params>& PathFollowerNode::Params::table() {
  static const ParamTable<Params> t =
      ParamTable<Params>()
          .add("odom_frame", &Params::odom_frame, "",
               "The path's frame: the locator's odom_frame (other estimates are not stored).")
          .add("base_frame", &Params::base_frame, "",
               "The robot's frame (the path's pose lookup).");
  return t;
}

void PathFollowerNode::Params::load(const ParamReader& pnh) {
  table().load(pnh, *this);
  path.load(pnh);
}

void PathFollowerNode::Params::validate() const {
  require(!odom_frame.empty(), "~odom_frame", odom_frame, "a frame id");
  require(!base_frame.empty(), "~base_frame", base_frame, "a frame id");
  path.validate();
}

PathFollowerNode::PathFollowerNode(ros::NodeHandle& nh, ros::NodeHandle& private_nh)
    : EstimateFollowerNode(nh, private_nh),
      params_(loadValidated<Params>(params())),
      law_(params_.path, control::loadVelocityLawParams(params(), common())),
      tf_listener_(tf_buffer_) {
  requireKnownParams();
  path_pub_ = private_nh_.advertise<nav_msgs::Path>("path", 1, true);
  debugAdvertised(path_pub_);
  law_reconfigure_ = makeFollowLawReconfigure(
      private_nh, law_.lawParams(), [this](const control::VelocityLawParams& p) {
        // Against the safety layer as it is now (throws ParamError to refuse).
        law_.setLawParams(control::lawWithCommon(p, common()));
      });
  startFollowing(law_);
}

PathFollowerNode::~PathFollowerNode() = default;

void PathFollowerNode::onTrackPoint(bool placed, bool kept, const ros::Time& stamp) {
  path_mode_ = placed;
  if (kept) {
    publishPath(stamp);
  }
}

bool PathFollowerNode::acceptsOdomFrame(const std::string& frame) {
  if (frame == params_.odom_frame) {
    return true;
  }
  ROS_WARN_THROTTLE(5.0,
                    "%s: the locator tracks in '%s', the path is stored in odom_frame '%s': "
                    "no path point from it",
                    ros::this_node::getName().c_str(), frame.c_str(), params_.odom_frame.c_str());
  return false;
}

std::optional<Pose2> PathFollowerNode::robotPose() {
  if (!path_mode_) {
    return std::nullopt;  // the law drives straight to the target and says why
  }
  try {
    const auto t = tf_buffer_.lookupTransform(params_.odom_frame, params_.base_frame, ros::Time(0));
    Pose2 pose;
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

void PathFollowerNode::afterTick(const ros::Time& now) {
  if (law_.path().points().size() != published_points_) {
    publishPath(now);  // the robot passed some points
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
  published_points_ = law_.path().points().size();
}

}  // namespace radio_follow
