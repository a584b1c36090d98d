// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/ros/control/homing_controller.hpp"

#include <geometry_msgs/PoseStamped.h>
#include <tf2/utils.h>

#include <cmath>
#include <optional>

#include "radio_follow/common/param_error.hpp"
#include "radio_follow/common/param_keys.hpp"

namespace radio_follow {

const ParamTable<HomingControllerNode::Params>& HomingControllerNode::Params::table() {
  using P = HomingControllerNode::Params;
  static const ParamTable<P> t =
      ParamTable<P>()
          .add("tag_id", &P::tag_id, "", "Only bearings of this tag count; empty = every tag.")
          .add("distance_range_topic", &P::distance_range_topic, "",
               "UwbRanges topic of the target's ranges (distance_source uwb).");
  return t;
}

void HomingControllerNode::Params::load(const ParamReader& pnh) {
  table().load(pnh, *this);
  tag_id = normalizeId(tag_id);
}

void HomingControllerNode::Params::validate() const {
  requireGraphName("~distance_range_topic", distance_range_topic);
}

HomingControllerNode::HomingControllerNode(ros::NodeHandle& nh, ros::NodeHandle& private_nh)
    : ControllerBase(nh, private_nh, false), params_(loadValidated<Params>(params())), law_([&] {
        control::HomingControllerParams p;
        p.load(params(), common().limits);
        return p;
      }()) {
  requireKnownParams();
  goal_pub_ = private_nh_.advertise<geometry_msgs::PoseStamped>("goal", 1, true);
  odom_sub_ = barrier_.subscribe(nh_, "odom", 10, &HomingControllerNode::onOdom, this);
  bearing_sub_ = barrier_.subscribe(nh_, "aoa_bearing", 20, &HomingControllerNode::onBearing, this);
  debugSubscribed(odom_sub_);
  debugSubscribed(bearing_sub_);
  if (law_.params().usesUwb()) {
    distance_sub_ = barrier_.subscribe(nh_, params_.distance_range_topic, 10,
                                       &HomingControllerNode::onDistanceRanges, this);
  }
  start(law_);
}

void HomingControllerNode::onOdom(const nav_msgs::Odometry::ConstPtr& msg) {
  const ros::Time now = ros::Time::now();
  const ros::Time stamp = msg->header.stamp.isZero() ? now : msg->header.stamp;
  control::Pose2 pose;
  pose.x = msg->pose.pose.position.x;
  pose.y = msg->pose.pose.position.y;
  pose.yaw = tf2::getYaw(msg->pose.pose.orientation);
  const auto result = law_.onOdometry(pose, stamp.toSec(), now.toSec());
  if (result.clock_jumped) {
    ROS_WARN("%s: the clock jumped back, homing starts over", ros::this_node::getName().c_str());
  }
  if (!result.accepted) {
    ROS_WARN_THROTTLE(5.0, "%s: odometry refused (non-finite or implausible pose, or stamp from the future)",
                      ros::this_node::getName().c_str());
    return;
  }
  odom_frame_ = msg->header.frame_id;
}

void HomingControllerNode::onDistanceRanges(const UwbRanges::ConstPtr& msg) {
  const ros::Time stamp = msg->header.stamp.isZero() ? ros::Time::now() : msg->header.stamp;
  // With ~layout_file the module's calibration corrects the range, as for the safety stop
  // and the locator: a DWM1001 reads long by up to 0.3 m, which at homing distances is a
  // large share of the vector estimate's distance.
  // The module's antenna position from the layout places the range (it is measured
  // from there, in 3-D, not from the AoA board): HomingController::onRange.
  const auto& calibrated = common().calibrated_modules;
  const auto module = calibrated.find(normalizeId(msg->tag_id));
  std::optional<Eigen::Vector3d> antenna;
  if (const TwrModule* m =
          common().layout ? common().layout->findTwrModule(msg->tag_id) : nullptr) {
    antenna = m->position;
  }
  for (const auto& r : msg->ranges) {
    if (common().target_anchor_id.empty() ||
        normalizeId(r.anchor_id) == common().target_anchor_id) {
      law_.onRange(module == calibrated.end() ? r.range : module->second.correctRange(r.range),
                   stamp.toSec(), antenna);
    }
  }
}

void HomingControllerNode::onBearing(const AoaBearing::ConstPtr& msg) {
  if (!params_.tag_id.empty() && normalizeId(msg->tag_id) != params_.tag_id) {
    return;
  }
  const ros::Time stamp = msg->header.stamp.isZero() ? ros::Time::now() : msg->header.stamp;
  const auto result = law_.onBearing(msg->azimuth, msg->rssi, stamp.toSec());
  if (result == control::HomingController::BearingResult::kNoOdometry) {
    ROS_WARN_THROTTLE(5.0, "%s: bearing without odometry within %.2f s, ignored",
                      ros::this_node::getName().c_str(), law_.params().odom_timeout);
  }
  if (result != control::HomingController::BearingResult::kUsed) {
    return;
  }
  // A fresh bearing is a usable observation even before a goal exists: compute() then
  // searches along it, which is how the parallax estimate gets its baseline.
  noteEstimate(stamp, control::EstimateQuality::kUsable);

  if (const auto goal_pose = law_.goalPose()) {
    geometry_msgs::PoseStamped goal;
    goal.header.stamp = stamp;
    goal.header.frame_id = odom_frame_;
    goal.pose.position.x = goal_pose->x;
    goal.pose.position.y = goal_pose->y;
    goal.pose.orientation.z = std::sin(0.5 * goal_pose->yaw);
    goal.pose.orientation.w = std::cos(0.5 * goal_pose->yaw);
    goal_pub_.publish(goal);
  }
}

}  // namespace radio_follow
