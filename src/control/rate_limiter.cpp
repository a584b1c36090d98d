// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/control/rate_limiter.hpp"

#include <algorithm>
#include <cmath>

#include "radio_follow/common/param_error.hpp"

namespace radio_follow {
namespace control {

const ParamTable<MotionLimits>& MotionLimits::table() {
  static const ParamTable<MotionLimits> t =
      ParamTable<MotionLimits>()
          .add("max_linear", &MotionLimits::max_linear, "m/s", "Speed limit.", Range::above(0.0))
          .add("max_angular", &MotionLimits::max_angular, "rad/s", "Yaw-rate limit.",
               Range::above(0.0))
          .add("max_linear_accel", &MotionLimits::max_linear_accel, "m/s^2", "Speeding up.",
               Range::above(0.0))
          .add("max_linear_decel", &MotionLimits::max_linear_decel, "m/s^2",
               "Slowing down (safety stops bypass it).", Range::above(0.0))
          .add("max_angular_accel", &MotionLimits::max_angular_accel, "rad/s^2",
               "Yaw acceleration.", Range::above(0.0));
  return t;
}

void MotionLimits::validate() const {
  table().check(*this);
}

double RateLimiter::update(double request, double dt) {
  if (!std::isfinite(request)) {
    request = 0.0;
  }
  if (!(dt > 0.0)) {
    return value_;
  }
  // Moving away from zero (same sign, larger magnitude) is acceleration; everything
  // else, including a sign change, first has to pass through a deceleration.
  const bool speeding_up = value_ * request >= 0.0 && std::abs(request) > std::abs(value_);
  const double step = (speeding_up ? rise_ : fall_) * dt;
  value_ += std::clamp(request - value_, -step, step);
  return value_;
}

CommandLimiter::CommandLimiter(const MotionLimits& limits)
    : limits_(limits),
      linear_(limits.max_linear_accel, limits.max_linear_decel),
      angular_(limits.max_angular_accel, limits.max_angular_accel) {}

VelocityCommand CommandLimiter::update(const VelocityCommand& request, double dt) {
  const double v = std::isfinite(request.linear) ? request.linear : 0.0;
  const double w = std::isfinite(request.angular) ? request.angular : 0.0;
  VelocityCommand out;
  out.linear = linear_.update(std::clamp(v, -limits_.max_linear, limits_.max_linear), dt);
  out.angular = angular_.update(std::clamp(w, -limits_.max_angular, limits_.max_angular), dt);
  return out;
}

void CommandLimiter::setLimits(const MotionLimits& limits) {
  limits.validate();
  const double linear = linear_.value();
  const double angular = angular_.value();
  *this = CommandLimiter(limits);
  linear_.reset(linear);
  angular_.reset(angular);
}

void CommandLimiter::reset() {
  linear_.reset();
  angular_.reset();
}

}  // namespace control
}  // namespace radio_follow
