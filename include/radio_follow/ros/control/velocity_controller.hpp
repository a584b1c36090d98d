// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <ros/ros.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>

#include <memory>
#include <optional>
#include <string>

#include "radio_follow/TargetEstimate.h"
#include "radio_follow/control/velocity_law.hpp"
#include "radio_follow/ros/control/controller_base.hpp"
#include "radio_follow/ros/common/params.hpp"
#include "radio_follow/ros/control/target_motion_tracker.hpp"

namespace radio_follow {

class FollowLawTuningConfig;

// The law's parameter loading and its tie to the safety layer live in the core
// (control/velocity_law.hpp), so that the lockstep closed loop loads the same keys.
using control::lawWithCommon;
using control::loadVelocityLawParams;

/// Converts an estimate into the law's input (HEADING_ONLY -> no range, DEGRADED flag
/// with the position's spread along and across the line of sight and the mirror
/// hypothesis, the target's receding speed when known, the nearest module's gap to the stop:
/// ControllerBase::moduleGap()).
control::TargetPolar targetPolar(const TargetEstimate& estimate,
                                 std::optional<double> receding_speed, double module_gap);

/// velocity_controller (thesis Section 4.6): drives straight towards the target's
/// estimate with PID on distance and heading, behind the shared safety layer.
class VelocityControllerNode : public ControllerBase {
 public:
  /// Where the person's ground speed (the speed feed-forward) comes from.
  struct Params {
    std::string odom_frame = "odom";  ///< empty: no feed-forward, no tf needed
    double tf_timeout = 0.05;         ///< s

    void load(const ParamReader& private_nh);
    void validate() const;
  };

  VelocityControllerNode(ros::NodeHandle& nh, ros::NodeHandle& private_nh);
  ~VelocityControllerNode() override;

 private:
  Output compute(const ros::Time& now, double dt) override;
  void onStopped() override { law_.reset(); }
  void onCommonChange(const ControllerCommonParams& next) override;
  void onEstimate(const TargetEstimate::ConstPtr& msg);

  Params params_;
  control::VelocityLaw law_;
  tf2_ros::Buffer tf_buffer_;
  tf2_ros::TransformListener tf_listener_;
  TargetMotionTracker motion_;
  std::unique_ptr<ReconfigureServer<FollowLawTuningConfig, control::VelocityLawParams>>
      law_reconfigure_;
  TargetEstimate::ConstPtr estimate_;
  ros::Subscriber estimate_sub_;
};

}  // namespace radio_follow
