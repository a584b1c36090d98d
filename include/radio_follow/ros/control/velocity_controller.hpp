// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <ros/ros.h>

#include <memory>

#include "radio_follow/control/velocity_law.hpp"
#include "radio_follow/ros/control/estimate_follower.hpp"

namespace radio_follow {

class FollowLawTuningConfig;

// The law's parameter loading and its tie to the safety layer live in the core
// (control/velocity_law.hpp), so that the lockstep closed loop loads the same keys.
using control::lawWithCommon;
using control::loadVelocityLawParams;

/// velocity_controller (thesis Section 4.6): drives straight towards the target's
/// estimate with PID on distance and heading (control::VelocityLaw), behind the shared
/// safety layer.
class VelocityControllerNode : public EstimateFollowerNode {
 public:
  VelocityControllerNode(ros::NodeHandle& nh, ros::NodeHandle& private_nh);
  ~VelocityControllerNode() override;

 private:
  control::VelocityLaw law_;
  std::unique_ptr<ReconfigureServer<FollowLawTuningConfig, control::VelocityLawParams>>
      law_reconfigure_;
};

}  // namespace radio_follow
