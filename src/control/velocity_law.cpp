// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/control/velocity_law.hpp"

#include <algorithm>
#include <cmath>

#include "radio_follow/common/angles.hpp"
#include "radio_follow/common/param_error.hpp"

namespace radio_follow {
namespace control {

void VelocityLawParams::validate() const {
  require(std::isfinite(follow_distance) && follow_distance > 0.0, "~follow_distance",
          follow_distance, "a distance > 0 in metres");
  require(std::isfinite(slowdown_distance) && slowdown_distance > 0.0, "~slowdown_distance",
          slowdown_distance, "a distance > 0 in metres");
  require(degraded_speed_factor >= 0.0 && degraded_speed_factor <= 1.0, "~degraded_speed_factor",
          degraded_speed_factor, "a factor in [0, 1]");
  require(std::isfinite(feed_forward) && feed_forward >= 0.0 && feed_forward <= 1.0,
          "~feed_forward", feed_forward, "a fraction in [0, 1]");
  require(std::isfinite(max_linear) && max_linear > 0.0, "~max_linear", max_linear,
          "a speed > 0 in m/s");
  require(backwards_angle > kPi / 2.0 && backwards_angle < kPi, "~backwards_angle", backwards_angle,
          "an angle in (pi/2, pi) rad");
  require(backwards_cycles >= 1, "~backwards_cycles", backwards_cycles, "a count >= 1");
  linear.validate("~linear_pid");
  angular.validate("~angular_pid");
}

double slowdownCap(double gap, double slowdown_distance, double max_speed, double target_speed) {
  if (!(gap > 0.0)) {
    return 0.0;
  }
  // The ramp's slope grows with the speed it has to take away, so the cap is continuous
  // at the follow distance and the robot settles just outside it instead of on the edge.
  const double ramp = std::min(1.0, gap / slowdown_distance);
  return std::min(max_speed, (std::max(0.0, target_speed) + max_speed) * ramp);
}

bool updateArrived(bool arrived, double gap) {
  return arrived ? !(gap > kArrivalHysteresis) : !(gap > 0.0);
}

double gapSpeed(double gap, double target_speed, double dt, Pid& pid,
                const VelocityLawParams& params) {
  const double feed_forward =
      std::isfinite(target_speed) ? params.feed_forward * std::max(0.0, target_speed) : 0.0;
  const double speed = std::max(0.0, feed_forward + pid.update(gap, dt));
  return std::min(speed,
                  slowdownCap(gap, params.slowdown_distance, params.max_linear, feed_forward));
}

VelocityLaw::VelocityLaw(const VelocityLawParams& params)
    : params_(params), linear_pid_(params.linear), angular_pid_(params.angular) {}

void VelocityLaw::setParams(const VelocityLawParams& params) {
  params_ = params;
  linear_pid_.setGains(params.linear);
  angular_pid_.setGains(params.angular);
}

void VelocityLaw::reset() {
  linear_pid_.reset();
  angular_pid_.reset();
  behind_count_ = 0;
  arrived_ = false;
}

VelocityCommand VelocityLaw::update(const TargetPolar& target, double dt) {
  // Heading error relative to the current driving direction (front, or rear when reversing).
  double heading_error = wrapAngle(target.bearing + (backwards_ ? kPi : 0.0));
  if (params_.allow_backwards) {
    behind_count_ = std::abs(heading_error) > params_.backwards_angle ? behind_count_ + 1 : 0;
    if (behind_count_ >= params_.backwards_cycles) {
      backwards_ = !backwards_;
      behind_count_ = 0;
      heading_error = wrapAngle(heading_error + kPi);
      linear_pid_.reset();
      angular_pid_.reset();
    }
  }

  VelocityCommand cmd;
  cmd.angular = angular_pid_.update(heading_error, dt);

  const double gap = target.range - params_.follow_distance;
  arrived_ = target.range_valid && updateArrived(arrived_, gap);
  if (!target.range_valid) {
    linear_pid_.reset();
    return cmd;
  }
  double speed = gapSpeed(gap, target.receding_speed, dt, linear_pid_, params_);
  // Do not drive forward while the target is off to the side: cos() fades speed to zero
  // at 90 deg so the robot turns first instead of circling.
  speed *= std::max(0.0, std::cos(heading_error));
  if (target.degraded) {
    speed *= params_.degraded_speed_factor;
  }
  cmd.linear = backwards_ ? -speed : speed;
  return cmd;
}

}  // namespace control
}  // namespace radio_follow
