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
#include "radio_follow/ros/controller_base.hpp"
#include "radio_follow/ros/params.hpp"
#include "radio_follow/ros/target_motion_tracker.hpp"

namespace radio_follow {

class FollowLawTuningConfig;

/// Loads the velocity law's parameters (shared by velocity_controller and the
/// path_follower's straight-line fallback); speed limits come from `common`.
control::VelocityLawParams loadVelocityLawParams(const ParamReader& private_nh,
                                                 const ControllerCommonParams& common);

/// `law` with the safety layer's values it depends on (safe_distance, the speed limits as
/// the PIDs' output limits), validated: throws ParamError when the law no longer clears
/// the stop. The one check at start, in live tuning of the law and of the common values.
control::VelocityLawParams lawWithCommon(control::VelocityLawParams law,
                                         const ControllerCommonParams& common);

/// Converts an estimate into the law's input (HEADING_ONLY -> no range, DEGRADED flag,
/// the target's receding speed when known, the nearest module's gap to the stop:
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
