// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <nav_msgs/Path.h>
#include <ros/ros.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>

#include <memory>
#include <optional>
#include <string>

#include "radio_follow/common/param_table.hpp"
#include "radio_follow/control/path_follower.hpp"
#include "radio_follow/control/velocity_law.hpp"
#include "radio_follow/ros/common/params.hpp"
#include "radio_follow/ros/control/estimate_follower.hpp"

namespace radio_follow {

class FollowLawTuningConfig;

/// path_follower (thesis Section 4.7): stores the person's path in the odometry frame (the
/// locator's odometry-frame estimates) and follows it with pure pursuit, keeping
/// follow_distance along the path (control::PathFollowLaw). Without them, or without the
/// robot's pose from TF, it drives straight to the target and says so.
class PathFollowerNode : public EstimateFollowerNode {
 public:
  /// The frames and the law's own parameters (`path`).
  struct Params {
    /// The path's frame: the locator's odom_frame (estimates in another are not stored).
    std::string odom_frame = "odom";
    std::string base_frame = "base_link";
    control::PathFollowParams path;

    /// odom_frame, base_frame (the law's own: control::PathFollowParams::table()).
    static const ParamTable<Params>& table();
    void load(const ParamReader& private_nh);
    void validate() const;
  };

  PathFollowerNode(ros::NodeHandle& nh, ros::NodeHandle& private_nh);
  ~PathFollowerNode() override;

 private:
  std::optional<Pose2> robotPose() override;
  void afterTick(const ros::Time& now) override;
  void onTrackPoint(bool placed, bool kept, const ros::Time& stamp) override;
  bool acceptsOdomFrame(const std::string& frame) override;
  void publishPath(const ros::Time& stamp);

  Params params_;
  control::PathFollowLaw law_;
  std::unique_ptr<ReconfigureServer<FollowLawTuningConfig, control::VelocityLawParams>>
      law_reconfigure_;
  tf2_ros::Buffer tf_buffer_;  // the robot's pose each tick, never waited for
  tf2_ros::TransformListener tf_listener_;
  bool path_mode_ = false;  // false: the last track point had no odometry-frame part
  std::size_t published_points_ = 0;
  ros::Publisher path_pub_;
};

}  // namespace radio_follow
