// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <nav_msgs/Path.h>
#include <ros/ros.h>

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

/// path_follower (thesis Section 4.7): stores the person's path in the odometry frame
/// and follows it with pure pursuit, keeping follow_distance along the path
/// (control::PathFollowLaw). Without the odometry transform it drives straight to the
/// target and says so.
class PathFollowerNode : public EstimateFollowerNode {
 public:
  /// The robot's frame and the law's own parameters (`path`); odom_frame and tf_timeout
  /// are EstimateFollowerNode's.
  struct Params {
    std::string base_frame = "base_link";
    control::PathFollowParams path;

    /// base_frame (the law's own parameters: control::PathFollowParams::table()).
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
  void publishPath(const ros::Time& stamp);

  Params params_;
  control::PathFollowLaw law_;
  std::unique_ptr<ReconfigureServer<FollowLawTuningConfig, control::VelocityLawParams>>
      law_reconfigure_;
  bool path_mode_ = false;  // false: the last track point could not be put into odom
  std::size_t published_points_ = 0;
  ros::Publisher path_pub_;
};

}  // namespace radio_follow
