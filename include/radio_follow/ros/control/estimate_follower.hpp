// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <ros/ros.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>

#include <Eigen/Core>
#include <optional>
#include <string>
#include <utility>

#include "radio_follow/TargetEstimate.h"
#include "radio_follow/control/controller_params.hpp"
#include "radio_follow/control/follow_law.hpp"
#include "radio_follow/ros/common/params.hpp"
#include "radio_follow/ros/control/controller_base.hpp"

namespace radio_follow {

/// What the velocity and path controllers share: they follow the locator's estimate
/// (`target`). Each estimate goes to the follower core (control::Follower); each track
/// point (control::TrackGate) is placed in the odometry frame through TF at the
/// estimate's stamp, which gives the target's ground speed (the speed feed-forward) and
/// the path follower's path.
class EstimateFollowerNode : public ControllerBase {
 public:
  /// Where the estimates are placed to track the target's motion.
  using Params = control::TrackParams;

 protected:
  EstimateFollowerNode(ros::NodeHandle& nh, ros::NodeHandle& private_nh);

  /// Subscribes to `target` and starts the controller with `law` (ControllerBase::start).
  void startFollowing(control::FollowLaw& law);
  /// A track point was placed in the odometry frame (`kept`: the law kept it) or could not
  /// be (`placed` false: no transform at its stamp). Called on the main thread.
  virtual void onTrackPoint(bool /*placed*/, bool /*kept*/, const ros::Time& /*stamp*/) {}

  const Params& followParams() const { return follow_params_; }
  tf2_ros::Buffer tf_buffer_;

 private:
  void onEstimate(const TargetEstimate::ConstPtr& msg);
  /// The robot's and the target's positions in odom_frame at the estimate's stamp (or with
  /// the newest transform when that is within tf_timeout of it; it never waits for TF);
  /// nullopt with a warning when TF has neither.
  std::optional<std::pair<Eigen::Vector2d, Eigen::Vector2d>> place(const TargetEstimate& msg);

  Params follow_params_;
  tf2_ros::TransformListener tf_listener_;
  ros::Subscriber estimate_sub_;
};

}  // namespace radio_follow
