// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/control/velocity_law.hpp"

#include <algorithm>
#include <cmath>

#include "radio_follow/common/angles.hpp"
#include "radio_follow/common/param_error.hpp"
#include "radio_follow/control/command_pipeline.hpp"

namespace radio_follow {
namespace control {

const ParamTable<VelocityLawParams>& VelocityLawParams::table() {
  using P = VelocityLawParams;
  static const ParamTable<P> t =
      ParamTable<P>()
          .add("follow_distance", &P::follow_distance, "m", "Desired gap to the target.",
               Range::above(0.0))
          .add("slowdown_distance", &P::slowdown_distance, "m",
               "Beyond the follow distance the speed cap ramps up to max_linear over this.",
               Range::above(0.0))
          .add("closing_distance", &P::closing_distance, "m",
               "Inside the follow distance the cap falls to zero over this.", Range::above(0.0))
          .add("stop_margin", &P::stop_margin, "m",
               "Keep the nearest module this far beyond safe_distance.", Range::atLeast(0.0))
          .add("feed_forward", &P::feed_forward, "",
               "Fraction of the target's own speed added to the command.", Range::closed(0.0, 1.0))
          .add("degraded_speed_factor", &P::degraded_speed_factor, "",
               "Speed factor while a DEGRADED estimate is too uncertain to steer by.",
               Range::closed(0.0, 1.0))
          .add("max_follow_sigma", &P::max_follow_sigma, "m",
               "A DEGRADED estimate within this range sigma, and bearing sigma sideways at the "
               "follow distance, is followed at full speed.",
               Range::above(0.0))
          .add("allow_backwards", &P::allow_backwards, "",
               "Drive backwards when the target stays behind (reversible robots only).")
          .addScaled("backwards_angle_deg", &P::backwards_angle, kPi / 180.0, "deg",
                     "|bearing| beyond this counts as behind.", Range::open(90.0, 180.0))
          .add("backwards_cycles", &P::backwards_cycles, "",
               "Consecutive behind cycles before the direction switches.", Range::atLeast(1))
          .include(PidGains::table(), &P::linear, "linear_pid/")
          .include(PidGains::table(), &P::angular, "angular_pid/");
  return t;
}

void VelocityLawParams::validate() const {
  table().check(*this);
  require(closing_distance < follow_distance, "~closing_distance", closing_distance,
          "a distance in (0, follow_distance) in metres");
  require(follow_distance - closing_distance >= safe_distance, "~follow_distance", follow_distance,
          "at least safe_distance + closing_distance (" + paramValueString(safe_distance) + " + " +
              paramValueString(closing_distance) +
              " m): the law must stop the robot before the safety stop trips");
  require(std::isfinite(max_linear) && max_linear > 0.0, "~max_linear", max_linear,
          "a speed > 0 in m/s");
  require(std::isfinite(max_linear_decel) && max_linear_decel > 0.0, "~max_linear_decel",
          max_linear_decel, "a deceleration > 0 in m/s^2");
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

Caution caution(const TargetPolar& target, const VelocityLawParams& params) {
  if (!target.degraded) {
    return Caution::kNone;
  }
  if (target.mirror) {
    return Caution::kMirror;
  }
  if (!(target.range_sigma <= params.max_follow_sigma)) {
    return Caution::kRange;
  }
  const bool steerable = target.bearing_sigma < 0.5 * kPi &&
                         params.follow_distance * std::tan(target.bearing_sigma) <=
                             params.max_follow_sigma;
  return steerable ? Caution::kNone : Caution::kBearing;
}

std::string followingText(const std::string& what, const TargetPolar& target, Caution why) {
  // No figures: the announcer speaks every new text, and a figure would change it with
  // every estimate. The locator's diagnostics carry the sigmas.
  switch (why) {
    case Caution::kMirror:
      return what + " slowly, the target may be at its mirror image.";
    case Caution::kRange:
      return what + " slowly, the distance is uncertain.";
    case Caution::kBearing:
      return what + " slowly, the direction is uncertain.";
    case Caution::kNone:
      break;
  }
  return target.degraded ? what + ", the direction is approximate." : what + ".";
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

bool insideStopMargin(double module_gap, const VelocityLawParams& params) {
  return module_gap <= params.stop_margin;
}

double brakingSpeed(double room, double decel, double delay) {
  if (!(room > 0.0)) {
    return 0.0;
  }
  const double reaction = decel * delay;
  return std::sqrt(reaction * reaction + 2.0 * decel * room) - reaction;
}

double gapSpeed(double gap, double target_speed, double dt, Pid& pid,
                const VelocityLawParams& params) {
  const double feed_forward =
      std::isfinite(target_speed) ? params.feed_forward * std::max(0.0, target_speed) : 0.0;
  const double speed = std::max(0.0, feed_forward + pid.update(gap, dt));
  const double cap =
      std::min(slowdownCap(gap, params.slowdown_distance, params.closing_distance,
                           params.max_linear, feed_forward),
               brakingSpeed(gap + params.closing_distance, params.max_linear_decel, dt));
  return std::min(speed, cap);
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
  if (arrived_ || insideStopMargin(target.module_gap, params_)) {
    speed = 0.0;
  }
  // Do not drive forward while the target is off to the side: cos() fades speed to zero
  // at 90 deg so the robot turns first instead of circling.
  speed *= std::max(0.0, std::cos(heading_error));
  if (caution(target, params_) != Caution::kNone) {
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
  } else {
    out.text = followingText(driving_backwards() ? "Following backwards" : "Following", target,
                             caution(target, params_));
  }
  return out;
}

VelocityLawParams loadVelocityLawParams(const ParamSource& p, const CommandPipelineParams& common) {
  VelocityLawParams law;
  VelocityLawParams::table().load(p, law);
  return lawWithCommon(law, common);
}

LawOutput VelocityLaw::step(const FollowInput& input, double dt) {
  if (!input.target) {
    LawOutput out;
    out.state = FollowerState::kWaitingForTarget;
    return out;
  }
  return step(*input.target, dt);
}

void VelocityLaw::setCommon(const CommandPipelineParams& next) {
  setParams(lawWithCommon(params_, next));
}

VelocityLawParams lawWithCommon(VelocityLawParams law, const CommandPipelineParams& common) {
  law.max_linear = common.limits.max_linear;
  law.max_linear_decel = common.limits.max_linear_decel;
  law.safe_distance = common.safety.safe_distance;
  law.linear.output_limit = common.limits.max_linear;
  law.angular.output_limit = common.limits.max_angular;
  law.validate();
  return law;
}

}  // namespace control
}  // namespace radio_follow
