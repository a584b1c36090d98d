// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>

#include "radio_follow/common/param_table.hpp"

namespace radio_follow {
namespace control {

/// A planar velocity command: forward speed (m/s) and yaw rate (rad/s, CCW positive).
struct VelocityCommand {
  double linear = 0.0;
  double angular = 0.0;

  bool isZero() const { return linear == 0.0 && angular == 0.0; }
};

/// Limits of the commanded motion. Deceleration has its own (usually larger) limit
/// so the robot still stops promptly when the gap closes.
struct MotionLimits {
  double max_linear = 1.5;         ///< m/s
  double max_angular = 1.0;        ///< rad/s
  double max_linear_accel = 0.5;   ///< m/s^2, speeding up
  double max_linear_decel = 2.0;   ///< m/s^2, slowing down
  double max_angular_accel = 2.0;  ///< rad/s^2, both ways

  static const ParamTable<MotionLimits>& table();
  /// Throws ParamError naming the first unusable field.
  void validate() const;
};

/// Slew-rate limiter on one signal: the output moves towards the request by at most
/// `rise * dt` when |value| grows and `fall * dt` when it shrinks.
class RateLimiter {
 public:
  RateLimiter(double rise, double fall) : rise_(rise), fall_(fall) {}

  double update(double request, double dt);
  void reset(double value = 0.0) { value_ = value; }
  double value() const { return value_; }

 private:
  double rise_;
  double fall_;
  double value_ = 0.0;
};

/// Saturates a command to the speed limits and smooths it with the acceleration
/// limits. The safety stop bypasses it (zero at once) and then calls reset().
class CommandLimiter {
 public:
  explicit CommandLimiter(const MotionLimits& limits);

  VelocityCommand update(const VelocityCommand& request, double dt);
  void reset();
  /// New limits at runtime (live tuning); the current output is kept, so the next update
  /// moves from it at the new rates. Throws ParamError and keeps the old limits when
  /// `limits` fails validate().
  void setLimits(const MotionLimits& limits);

 private:
  MotionLimits limits_;
  RateLimiter linear_;
  RateLimiter angular_;
};

}  // namespace control
}  // namespace radio_follow
