// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <nav_msgs/Path.h>
#include <ros/ros.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>

#include <memory>
#include <optional>
#include <string>

#include "radio_follow/TargetEstimate.h"
#include "radio_follow/control/path_follower.hpp"
#include "radio_follow/control/velocity_law.hpp"
#include "radio_follow/ros/control/controller_base.hpp"
#include "radio_follow/ros/common/params.hpp"
#include "radio_follow/ros/control/target_motion_tracker.hpp"

namespace radio_follow {

class FollowLawTuningConfig;

/// path_follower (thesis Section 4.7): stores the person's path in the odometry frame
/// and follows it with pure pursuit, keeping follow_distance along the path. Without
/// the odometry transform it drives straight to the target and says so.
class PathFollowerNode : public ControllerBase {
 public:
  /// The node's frames and TF tolerance; the law's own parameters are `path`.
  struct Params {
    std::string odom_frame = "odom";
    std::string base_frame = "base_link";
    double tf_timeout = 0.05;  ///< s
    control::PathFollowParams path;

    void load(const ParamReader& private_nh);
    void validate() const;
  };

  PathFollowerNode(ros::NodeHandle& nh, ros::NodeHandle& private_nh);
  ~PathFollowerNode() override;

 private:
  Output compute(const ros::Time& now, double dt) override;
  void onStopped() override;
  void onCommonChange(const ControllerCommonParams& next) override;
  void onEstimate(const TargetEstimate::ConstPtr& msg);
  std::optional<control::Pose2> robotPose();
  void publishPath(const ros::Time& stamp);

  Params params_;
  control::PathFollowLaw law_;
  tf2_ros::Buffer tf_buffer_;
  tf2_ros::TransformListener tf_listener_;
  TargetMotionTracker motion_;
  std::unique_ptr<ReconfigureServer<FollowLawTuningConfig, control::VelocityLawParams>>
      law_reconfigure_;
  TargetEstimate::ConstPtr estimate_;
  bool path_mode_ = false;  // false: the last estimate could not be put into odom
  ros::Publisher path_pub_;
  ros::Subscriber estimate_sub_;
};

}  // namespace radio_follow
