// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/control/velocity_law.hpp"

#include <algorithm>
#include <cmath>

#include "radio_follow/common/angles.hpp"
#include "radio_follow/common/param_error.hpp"
#include "radio_follow/control/command_pipeline.hpp"

namespace radio_follow {
namespace control {

void VelocityLawParams::validate() const {
  require(std::isfinite(follow_distance) && follow_distance > 0.0, "~follow_distance",
          follow_distance, "a distance > 0 in metres");
  require(std::isfinite(slowdown_distance) && slowdown_distance > 0.0, "~slowdown_distance",
          slowdown_distance, "a distance > 0 in metres");
  require(std::isfinite(closing_distance) && closing_distance > 0.0 &&
              closing_distance < follow_distance,
          "~closing_distance", closing_distance, "a distance in (0, follow_distance) in metres");
  require(follow_distance - closing_distance >= safe_distance, "~follow_distance", follow_distance,
          "at least safe_distance + closing_distance (" + paramValueString(safe_distance) + " + " +
              paramValueString(closing_distance) +
              " m): the law must stop the robot before the safety stop trips");
  require(std::isfinite(stop_margin) && stop_margin >= 0.0, "~stop_margin", stop_margin,
          "a distance >= 0 in metres");
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

double slowdownCap(double gap, double slowdown_distance, double closing_distance, double max_speed,
                   double target_speed) {
  const double v = std::clamp(std::isfinite(target_speed) ? target_speed : 0.0, 0.0, max_speed);
  if (std::isnan(gap)) {
    return 0.0;
  }
  if (gap >= 0.0) {
    return std::min(max_speed, v + (max_speed - v) * gap / slowdown_distance);
  }
  return v * std::max(0.0, 1.0 + gap / closing_distance);
}

bool updateArrived(bool arrived, double gap, double target_speed) {
  if (target_speed > kWalkingAwaySpeed) {
    return false;
  }
  return arrived ? !(gap > kArrivalHysteresis) : !(gap > 0.0);
}

double governingGap(double gap, double module_gap, const VelocityLawParams& params) {
  return std::isnan(module_gap) ? gap : std::min(gap, module_gap - params.stop_margin);
}

double gapSpeed(double gap, double target_speed, double dt, Pid& pid,
                const VelocityLawParams& params) {
  const double feed_forward =
      std::isfinite(target_speed) ? params.feed_forward * std::max(0.0, target_speed) : 0.0;
  const double speed = std::max(0.0, feed_forward + pid.update(gap, dt));
  return std::min(speed, slowdownCap(gap, params.slowdown_distance, params.closing_distance,
                                     params.max_linear, feed_forward));
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

  const double gap =
      governingGap(target.range - params_.follow_distance, target.module_gap, params_);
  arrived_ = target.range_valid && updateArrived(arrived_, gap, target.receding_speed);
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

LawOutput VelocityLaw::step(const TargetPolar& target, double dt) {
  LawOutput out;
  out.command = update(target, dt);
  if (!target.range_valid) {
    out.text = "Direction only, turning to the target.";
  } else if (arrived()) {
    out.state = FollowerState::kArrived;
    out.text = "At follow distance, waiting.";
  } else if (target.degraded) {
    out.text = driving_backwards() ? "Following backwards slowly, the position is uncertain."
                                   : "Following slowly, the position is uncertain.";
  } else {
    out.text = driving_backwards() ? "Following backwards." : "Following.";
  }
  return out;
}

VelocityLawParams loadVelocityLawParams(const ParamSource& p, const CommandPipelineParams& common) {
  VelocityLawParams law;
  p.param("follow_distance", law.follow_distance, law.follow_distance);
  p.param("slowdown_distance", law.slowdown_distance, law.slowdown_distance);
  p.param("closing_distance", law.closing_distance, law.closing_distance);
  p.param("stop_margin", law.stop_margin, law.stop_margin);
  p.param("feed_forward", law.feed_forward, law.feed_forward);
  p.param("degraded_speed_factor", law.degraded_speed_factor, law.degraded_speed_factor);
  p.param("allow_backwards", law.allow_backwards, law.allow_backwards);
  double backwards_deg = rad2deg(law.backwards_angle);
  p.param("backwards_angle_deg", backwards_deg, backwards_deg);
  law.backwards_angle = deg2rad(backwards_deg);
  p.param("backwards_cycles", law.backwards_cycles, law.backwards_cycles);
  loadPidGains(p, "linear_pid", law.linear);
  loadPidGains(p, "angular_pid", law.angular);
  return lawWithCommon(law, common);
}

VelocityLawParams lawWithCommon(VelocityLawParams law, const CommandPipelineParams& common) {
  law.max_linear = common.limits.max_linear;
  law.safe_distance = common.safety.safe_distance;
  law.linear.output_limit = common.limits.max_linear;
  law.angular.output_limit = common.limits.max_angular;
  law.validate();
  return law;
}

}  // namespace control
}  // namespace radio_follow
