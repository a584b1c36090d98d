// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <nav_msgs/Odometry.h>
#include <ros/ros.h>

#include <optional>
#include <string>

#include "radio_follow/AoaBearing.h"
#include "radio_follow/UwbRanges.h"
#include "radio_follow/common/time_policy.hpp"
#include "radio_follow/control/homing.hpp"
#include "radio_follow/control/rssi_model.hpp"
#include "radio_follow/ros/controller_base.hpp"
#include "radio_follow/ros/params.hpp"

namespace radio_follow {

/// homing_controller (seed 000): homes to a static target of unknown position from
/// AoA bearings and odometry. Publishes the hybrid goal as a PoseStamped (for a planner
/// such as move_base) and drives there itself with eq 15.
class HomingControllerNode : public ControllerBase {
 public:
  struct Params {
    /// Only bearings of this tag count; empty = every tag.
    std::string tag_id;
    /// AoA board mounting in base_link: position (m) and yaw of its boresight (rad).
    double board_x = 0.0;
    double board_y = 0.0;
    double board_yaw = 0.0;
    /// "rssi" (log-distance model) or "uwb" (newest range on distance_range_topic).
    std::string distance_source = "rssi";
    std::string distance_range_topic = "uwb_ranges";
    /// A UWB range older than this is not used as the vector estimate's distance, s.
    double distance_max_age = 0.5;
    /// Odometry older than this (at a bearing or a tick) is not used, s.
    double odom_timeout = 0.5;
    /// Forward speed while no goal exists yet (building the parallax baseline), m/s.
    double search_speed = 0.15;
    control::RssiModel rssi;
    control::HomingParams homing;

    void load(const ParamReader& private_nh);
    void validate() const;
  };

  HomingControllerNode(ros::NodeHandle& nh, ros::NodeHandle& private_nh);

 private:
  Output compute(const ros::Time& now, double dt) override;
  void onBearing(const AoaBearing::ConstPtr& msg);
  void onOdom(const nav_msgs::Odometry::ConstPtr& msg);
  void onDistanceRanges(const UwbRanges::ConstPtr& msg);

  Params params_;
  control::HybridHoming homing_;
  std::optional<control::Pose2> robot_;
  std::optional<double> last_bearing_;  // odometry frame, rad
  ros::Time odom_stamp_;
  TimePolicy time_;
  unsigned long odom_refused_ = 0;
  /// Forgets the pose, the distance and the homing estimate (clock jump).
  void resetTrack(const char* why);
  std::string odom_frame_;
  double uwb_distance_ = 0.0;
  ros::Time uwb_stamp_;
  ros::Publisher goal_pub_;
  ros::Subscriber bearing_sub_;
  ros::Subscriber odom_sub_;
  ros::Subscriber distance_sub_;
};

}  // namespace radio_follow
