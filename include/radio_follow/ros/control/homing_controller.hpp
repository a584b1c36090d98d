// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <nav_msgs/Odometry.h>
#include <ros/ros.h>

#include <string>

#include "radio_follow/AoaBearing.h"
#include "radio_follow/UwbRanges.h"
#include "radio_follow/common/param_table.hpp"
#include "radio_follow/control/homing_controller.hpp"
#include "radio_follow/ros/common/params.hpp"
#include "radio_follow/ros/control/controller_base.hpp"

namespace radio_follow {

/// homing_controller (seed 000): homes to a static target of unknown position from
/// AoA bearings and odometry. Publishes the hybrid goal as a PoseStamped (for a planner
/// such as move_base) and drives there itself with eq 15. The law is
/// control::HomingController; this class converts messages to its inputs.
class HomingControllerNode : public ControllerBase {
 public:
  /// The node's own (ROS-side) parameters; the law's are control::HomingControllerParams.
  struct Params {
    /// Only bearings of this tag count; empty = every tag.
    std::string tag_id;
    /// UwbRanges topic of the target's ranges (distance_source "uwb").
    std::string distance_range_topic = "uwb_ranges";

    static const ParamTable<Params>& table();
    void load(const ParamReader& private_nh);
    void validate() const;
  };

  HomingControllerNode(ros::NodeHandle& nh, ros::NodeHandle& private_nh);

 private:
  void onBearing(const AoaBearing::ConstPtr& msg);
  void onOdom(const nav_msgs::Odometry::ConstPtr& msg);
  void onDistanceRanges(const UwbRanges::ConstPtr& msg);

  Params params_;
  control::HomingController law_;
  std::string odom_frame_;
  ros::Publisher goal_pub_;
  ros::Subscriber bearing_sub_;
  ros::Subscriber odom_sub_;
  ros::Subscriber distance_sub_;
};

}  // namespace radio_follow
