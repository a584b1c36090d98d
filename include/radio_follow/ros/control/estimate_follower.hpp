// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <ros/ros.h>

#include <string>

#include "radio_follow/TargetEstimate.h"
#include "radio_follow/control/follow_law.hpp"
#include "radio_follow/ros/control/controller_base.hpp"

namespace radio_follow {

/// What the velocity and path controllers share: they follow the locator's estimate
/// (`target`). Each estimate goes to the follower core (control::Follower); each track
/// point (control::TrackGate) hands the core the estimate's odometry-frame part as the
/// locator filled it (`odom_*`: the target's ground velocity for the speed feed-forward,
/// its position for the path follower's path), without TF and without differentiating.
class EstimateFollowerNode : public ControllerBase {
 protected:
  EstimateFollowerNode(ros::NodeHandle& nh, ros::NodeHandle& private_nh)
      : ControllerBase(nh, private_nh, true) {}

  /// Subscribes to `target` and starts the controller with `law` (ControllerBase::start).
  void startFollowing(control::FollowLaw& law);
  /// A track point came with a usable odometry-frame part (`placed`; `kept`: the law kept
  /// it) or without one (`placed` false: the locator has no odometry, or another frame
  /// than acceptsOdomFrame() takes). Called on the main thread.
  virtual void onTrackPoint(bool /*placed*/, bool /*kept*/, const ros::Time& /*stamp*/) {}
  /// Whether track points in the locator's odometry frame `frame` (not empty) are taken.
  /// Default: any (a ground velocity is one in every world-fixed frame).
  virtual bool acceptsOdomFrame(const std::string& /*frame*/) { return true; }

 private:
  void onEstimate(const TargetEstimate::ConstPtr& msg);

  ros::Subscriber estimate_sub_;
};

}  // namespace radio_follow
