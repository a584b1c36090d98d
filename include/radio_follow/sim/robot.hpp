// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "radio_follow/common/param_table.hpp"
#include "radio_follow/common/pose2.hpp"

namespace radio_follow {
namespace sim {

using radio_follow::Pose2;

/// Speed and acceleration limits of the simulated base. The commanded velocity is
/// clamped to the speed limits and approached at no more than the accelerations.
struct RobotLimits {
  double max_linear = 1.5;        ///< m/s, both directions
  double max_angular = 1.5;       ///< rad/s
  double max_linear_accel = 1.0;  ///< m/s^2, speeding up
  /// m/s^2, slowing down (bases brake harder than they accelerate; 2.0 assumed for Spot).
  double max_linear_decel = 2.0;
  double max_angular_accel = 3.0;  ///< rad/s^2

  /// max_linear, max_angular, max_linear_accel, max_linear_decel, max_angular_accel.
  static const ParamTable<RobotLimits>& table();
  /// Throws ParamError naming the first non-positive or non-finite limit.
  void validate() const;
};

/// A unicycle (differential-drive) robot that integrates cmd_vel under limits.
class UnicycleRobot {
 public:
  explicit UnicycleRobot(const RobotLimits& limits, const Pose2& start = Pose2{});

  /// Advances by `dt` seconds towards the commanded velocities (m/s, rad/s).
  /// The velocity ramps within the step; the pose is integrated exactly on the arc
  /// of the step's mean velocities.
  void step(double cmd_linear, double cmd_angular, double dt);

  const Pose2& pose() const { return pose_; }
  double linear() const { return linear_; }
  double angular() const { return angular_; }
  /// Distance driven since the start, metres.
  double odometer() const { return odometer_; }

 private:
  RobotLimits limits_;
  Pose2 pose_;
  double linear_ = 0.0;
  double angular_ = 0.0;
  double odometer_ = 0.0;
};

}  // namespace sim
}  // namespace radio_follow
