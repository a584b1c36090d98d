// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/sim/robot.hpp"

#include <algorithm>
#include <cmath>

#include "radio_follow/common/angles.hpp"
#include "radio_follow/common/param_error.hpp"

namespace radio_follow {
namespace sim {
namespace {

double approach(double current, double target, double max_step) {
  return current + std::clamp(target - current, -max_step, max_step);
}

}  // namespace

const ParamTable<RobotLimits>& RobotLimits::table() {
  using R = RobotLimits;
  static const ParamTable<R> t =
      ParamTable<R>()
          .add("max_linear", &R::max_linear, "m/s", "Top speed, both directions.",
               Range::above(0.0))
          .add("max_angular", &R::max_angular, "rad/s", "Top turn rate.", Range::above(0.0))
          .add("max_linear_accel", &R::max_linear_accel, "m/s^2", "Speeding up.", Range::above(0.0))
          .add("max_linear_decel", &R::max_linear_decel, "m/s^2", "Slowing down.",
               Range::above(0.0))
          .add("max_angular_accel", &R::max_angular_accel, "rad/s^2", "Turn acceleration.",
               Range::above(0.0));
  return t;
}

void RobotLimits::validate() const {
  table().check(*this);
}

UnicycleRobot::UnicycleRobot(const RobotLimits& limits, const Pose2& start)
    : limits_(limits), pose_(start) {
  limits_.validate();
}

void UnicycleRobot::step(double cmd_linear, double cmd_angular, double dt) {
  if (!(dt > 0.0)) {
    return;
  }
  // A non-finite command is treated as stop: the simulator must not propagate NaN.
  const double v_target = std::isfinite(cmd_linear)
                              ? std::clamp(cmd_linear, -limits_.max_linear, limits_.max_linear)
                              : 0.0;
  const double w_target = std::isfinite(cmd_angular)
                              ? std::clamp(cmd_angular, -limits_.max_angular, limits_.max_angular)
                              : 0.0;
  const double v0 = linear_;
  const double w0 = angular_;
  // Slowing down (towards zero speed) uses the braking limit.
  const bool slowing = std::abs(v_target) < std::abs(linear_) || v_target * linear_ < 0.0;
  linear_ = approach(linear_, v_target,
                     (slowing ? limits_.max_linear_decel : limits_.max_linear_accel) * dt);
  angular_ = approach(angular_, w_target, limits_.max_angular_accel * dt);
  const double v = 0.5 * (v0 + linear_);
  const double w = 0.5 * (w0 + angular_);

  const double dyaw = w * dt;
  if (std::abs(dyaw) < 1e-9) {
    pose_.x += v * dt * std::cos(pose_.yaw + 0.5 * dyaw);
    pose_.y += v * dt * std::sin(pose_.yaw + 0.5 * dyaw);
  } else {
    const double radius = v / w;
    pose_.x += radius * (std::sin(pose_.yaw + dyaw) - std::sin(pose_.yaw));
    pose_.y -= radius * (std::cos(pose_.yaw + dyaw) - std::cos(pose_.yaw));
  }
  pose_.yaw = wrapAngleFast(pose_.yaw + dyaw);
  odometer_ += std::abs(v) * dt;
}

}  // namespace sim
}  // namespace radio_follow
