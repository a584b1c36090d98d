// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/ros/control/estimate_follower.hpp"

#include <tf2/exceptions.h>
#include <tf2_geometry_msgs/tf2_geometry_msgs.h>

#include <cmath>
#include <string>

#include "radio_follow/common/geometry.hpp"
#include "radio_follow/common/param_error.hpp"
#include "radio_follow/ros/common/wiring_debug.hpp"

namespace radio_follow {

EstimateFollowerNode::EstimateFollowerNode(ros::NodeHandle& nh, ros::NodeHandle& private_nh)
    : ControllerBase(nh, private_nh, true),
      follow_params_(loadValidated<Params>(params())),
      tf_listener_(tf_buffer_) {}

void EstimateFollowerNode::startFollowing(control::FollowLaw& law) {
  estimate_sub_ = barrier_.subscribe(nh_, "target", 5, &EstimateFollowerNode::onEstimate, this);
  debugSubscribed(estimate_sub_);
  start(law);
}

void EstimateFollowerNode::onEstimate(const TargetEstimate::ConstPtr& msg) {
  const auto& c = msg->position_covariance;  // row-major 3x3
  Eigen::Matrix2d covariance;
  covariance << c[0], c[1], c[3], c[4];
  const control::EstimateUse use = noteEstimate(
      msg->header.stamp, static_cast<TargetStatus>(msg->status), msg->range, msg->bearing,
      polarSpread(Eigen::Vector2d(msg->position.x, msg->position.y), covariance), msg->hypotheses);
  // A refused estimate (from the future) stops the robot; nothing of it reaches TF.
  if (use != control::EstimateUse::kTrackPoint || follow_params_.odom_frame.empty()) {
    return;
  }
  const auto placed = place(*msg);
  const bool kept = placed && addTrackPoint(msg->header.stamp, placed->first, placed->second);
  onTrackPoint(placed.has_value(), kept, msg->header.stamp);
}

std::optional<std::pair<Eigen::Vector2d, Eigen::Vector2d>> EstimateFollowerNode::place(
    const TargetEstimate& msg) {
  const std::string& odom = follow_params_.odom_frame;
  try {
    // Never wait (timeout 0): this runs in a callback. The transform at the stamp when
    // TF has it, else the newest one if it is at most tf_timeout away from the stamp
    // (odometry usually lags the estimate by a few ms).
    geometry_msgs::TransformStamped t;
    if (tf_buffer_.canTransform(odom, msg.header.frame_id, msg.header.stamp)) {
      t = tf_buffer_.lookupTransform(odom, msg.header.frame_id, msg.header.stamp);
    } else {
      t = tf_buffer_.lookupTransform(odom, msg.header.frame_id, ros::Time(0));
      // Seconds as double: stamps 2^32 s apart overflow ros::Duration (issue 34).
      const double offset = t.header.stamp.toSec() - msg.header.stamp.toSec();
      if (!(std::abs(offset) <= follow_params_.tf_timeout)) {
        throw tf2::TransformException("newest transform " + std::to_string(offset) +
                                      " s from the estimate, more than tf_timeout");
      }
    }
    geometry_msgs::Point target;
    tf2::doTransform(msg.position, target, t);
    return std::make_pair(Eigen::Vector2d(t.transform.translation.x, t.transform.translation.y),
                          Eigen::Vector2d(target.x, target.y));
  } catch (const tf2::TransformException& e) {
    ROS_WARN_THROTTLE(5.0,
                      "%s: no transform %s <- %s at the estimate's stamp (%s): no speed "
                      "feed-forward and no path point from it",
                      ros::this_node::getName().c_str(), odom.c_str(), msg.header.frame_id.c_str(),
                      e.what());
    return std::nullopt;
  }
}

}  // namespace radio_follow
