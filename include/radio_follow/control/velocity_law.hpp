// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <limits>
#include <string>

#include "radio_follow/common/param_source.hpp"
#include "radio_follow/control/follow_law.hpp"
#include "radio_follow/control/follower_state.hpp"
#include "radio_follow/control/pid.hpp"
#include "radio_follow/control/rate_limiter.hpp"
#include "radio_follow/control/safety_monitor.hpp"

namespace radio_follow {
namespace control {

/// Parameters of the "drive straight to the target" law (thesis Section 4.6).
struct VelocityLawParams {
  /// Desired gap to the target, metres.
  double follow_distance = 1.6;
  /// Beyond the follow distance the speed cap ramps from the person's speed at
  /// follow_distance to max_linear at follow_distance + slowdown_distance, metres: the
  /// robot slows smoothly as the gap closes (see slowdownCap()).
  double slowdown_distance = 0.2;
  /// Inside the follow distance the cap falls from the person's speed to zero at
  /// follow_distance - closing_distance, metres. Keep it at most follow_distance -
  /// safe_distance, so that the robot has stopped before the safety stop trips.
  double closing_distance = 0.2;
  /// The law also holds the nearest UWB module (its calibrated range to the person)
  /// this far beyond safe_distance, metres: on a robot whose modules sit far from its
  /// centre (a corner module of the tracked layout is 0.39 m off), a person at the follow
  /// distance can otherwise be within the safety stop of a corner, and the stop trips
  /// while following. See governingGap().
  double stop_margin = 0.1;
  /// Fraction of the target's own speed (TargetPolar::receding_speed, the path follower's
  /// walking speed) added to the command before the PID and to the speed cap; 0 disables.
  /// It lets the robot match a walking person at the follow distance instead of trailing
  /// by the gap error the slow-down ramp needs.
  double feed_forward = 1.0;
  /// Linear speed is multiplied by this while a DEGRADED estimate is too uncertain to
  /// steer by (caution()): a mirror hypothesis, or a spread beyond max_follow_sigma.
  double degraded_speed_factor = 0.5;
  /// A DEGRADED estimate is followed at full speed while its range sigma, and its bearing
  /// sigma as a sideways distance at the follow distance, are at most this, metres. The
  /// locator calls an estimate OK when its worst sigma is within its max_position_sigma
  /// or a share of the distance; far away, a bearing spread of a few degrees is metres
  /// sideways and the estimate DEGRADED, though steering needs only the angle: the robot
  /// heads along the bearing and the sideways error shrinks as it closes in.
  double max_follow_sigma = 0.5;
  /// Maximum forward speed, m/s (also the linear PID's output limit).
  double max_linear = MotionLimits().max_linear;
  /// The base's braking deceleration (MotionLimits::max_linear_decel, copied by the node),
  /// m/s^2: the speed is never more than the robot can still brake from before the point
  /// where the law has it at rest (brakingSpeed()).
  double max_linear_decel = MotionLimits().max_linear_decel;
  /// The safety layer's stop distance (SafetyParams::safe_distance, copied by the node):
  /// the law must come to rest before it, so follow_distance - closing_distance >= it.
  double safe_distance = SafetyParams().safe_distance;
  /// Drive backwards when the target stays behind the robot (reversible robots only).
  bool allow_backwards = false;
  /// |bearing| beyond this angle from the current driving direction counts as "behind", rad.
  double backwards_angle = 2.6179938779914944;  // 150 deg
  /// Consecutive "behind" cycles before the driving direction switches.
  int backwards_cycles = 5;
  /// Output limits: the pipeline's max_linear and max_angular (set by lawWithCommon).
  PidGains linear{1.0, 0.0, 0.0, 0.3, 0.2, MotionLimits().max_linear};
  PidGains angular{1.5, 0.0, 0.1, 0.3, 0.1, MotionLimits().max_angular};

  /// The law's parameters (max_linear and safe_distance are the pipeline's, copied by
  /// lawWithCommon), linear_pid/* and angular_pid/* included.
  static const ParamTable<VelocityLawParams>& table();
  void validate() const;
};

/// Feed-forward of the target's receding speed plus PID on (range - follow_distance) for
/// speed (see gapSpeed()), PID on the heading error for yaw rate.
/// It never backs away to grow the gap: the speed is zero, not negative, when the
/// target is closer than follow_distance. With allow_backwards the reference direction
/// flips to the robot's rear once the target stayed behind for backwards_cycles cycles.
class VelocityLaw : public FollowLaw {
 public:
  explicit VelocityLaw(const VelocityLawParams& params);

  VelocityCommand update(const TargetPolar& target, double dt);
  /// update() with the state and status text the controller reports: turning to a
  /// direction-only target, arrived, following (slowly when degraded, backwards).
  LawOutput step(const TargetPolar& target, double dt);
  /// FollowLaw: step() on the newest estimate (its receding speed is the feed-forward);
  /// waiting without one.
  LawOutput step(const FollowInput& input, double dt) override;
  void onStopped() override { reset(); }
  /// The common speed caps and stop distance through lawWithCommon (throws ParamError).
  void setCommon(const CommandPipelineParams& next) override;
  /// New parameters (live tuning; validated by the caller): the PIDs keep their state.
  void setParams(const VelocityLawParams& params);
  const VelocityLawParams& params() const { return params_; }
  void reset();

  bool driving_backwards() const { return backwards_; }
  /// True once the target came within the follow distance, until the gap opens again by
  /// more than kArrivalHysteresis or the person walks away (updateArrived()). While
  /// arrived the robot does not drive forward: the estimate's noise does not inch it
  /// towards a person who stands.
  bool arrived() const { return arrived_; }

 private:
  VelocityLawParams params_;
  Pid linear_pid_;
  Pid angular_pid_;
  bool backwards_ = false;
  int behind_count_ = 0;
  bool arrived_ = false;
};

/// Why a DEGRADED estimate slows the robot to degraded_speed_factor, or kNone.
enum class Caution {
  kNone,     ///< OK, or DEGRADED but within max_follow_sigma: full speed
  kMirror,   ///< a mirror hypothesis holds probability: either side may be the person
  kRange,    ///< range sigma beyond max_follow_sigma
  kBearing,  ///< bearing sigma beyond max_follow_sigma sideways at the follow distance
};

/// What the laws slow down for. Only a DEGRADED estimate can: one with a mirror
/// hypothesis, else one whose range sigma or whose bearing sigma (as a sideways sigma at
/// the follow distance, follow_distance * tan(bearing_sigma)) exceeds max_follow_sigma.
/// An unknown (non-finite) spread is too wide.
Caution caution(const TargetPolar& target, const VelocityLawParams& params);

/// The status text of a follower that drives `what` ("Following", "Following the
/// path", ...): plain for an OK estimate; "the direction is approximate" for a DEGRADED
/// one followed at full speed; "slowly" and the reason otherwise.
std::string followingText(const std::string& what, const TargetPolar& target, Caution why);

/// Gap (m) beyond the follow distance at which an arrived follower reports following again.
constexpr double kArrivalHysteresis = 0.1;
/// A person moving away faster than this (m/s) is being followed, not waited for.
constexpr double kWalkingAwaySpeed = 0.2;

/// Arrived-state with hysteresis: true from gap <= 0 until gap > kArrivalHysteresis,
/// and never while the person walks away faster than kWalkingAwaySpeed (the robot then
/// holds the follow distance while moving; that is following, not waiting).
bool updateArrived(bool arrived, double gap, double target_speed);

/// Speed cap as the gap (distance beyond the follow distance, m) closes, with v the
/// person's speed away from the robot (`target_speed` < 0 counted as 0):
///   gap >= 0:  min(max_speed, v + (max_speed - v) * gap / slowdown_distance)
///   gap <  0:  v * max(0, 1 + gap / closing_distance)
/// Continuous, and equal to the person's speed at the follow distance, so a robot
/// matching a walking person can hold the gap there (the PID settles it) instead of
/// trailing by the distance a cap that is zero at the follow distance would need. It
/// reaches zero at closing_distance inside the follow distance; with v = 0 it is zero at
/// and inside the follow distance, so the robot never drives towards a standing person
/// closer than follow_distance.
double slowdownCap(double gap, double slowdown_distance, double closing_distance, double max_speed,
                   double target_speed = 0.0);

/// Whether the nearest module's range is within stop_margin of safe_distance (module_gap
/// <= stop_margin). The laws then do not drive forward, whatever the estimate says: an
/// estimate that runs long, or the receding speed differentiated from it, must not carry
/// the robot into the stop while the raw range says the person is that close. NaN and
/// +inf (no range watched) are not inside.
bool insideStopMargin(double module_gap, const VelocityLawParams& params);

/// The gap the speed law regulates: min(gap, module_gap - stop_margin), where `gap` is
/// the distance beyond the follow distance (from the robot's centre) and `module_gap` the
/// nearest module's range beyond safe_distance. Whichever is closer to its limit governs.
double governingGap(double gap, double module_gap, const VelocityLawParams& params);

/// The fastest speed from which the robot comes to rest within `room` metres: braking at
/// `decel` after a reaction time `delay` (the command's period), v with
/// v delay + v^2 / (2 decel) = room; 0 without room.
double brakingSpeed(double room, double decel, double delay);

/// Forward speed that holds the gap: feed_forward * target_speed plus the PID on `gap`,
/// within [0, slowdownCap()] and never above brakingSpeed() to the point where the cap is
/// zero (gap = -closing_distance): the person may stop at any step, and a robot closing in
/// at walking speed needs a quarter of a metre to stop. Shared by the velocity law and the
/// path follower.
double gapSpeed(double gap, double target_speed, double dt, Pid& pid,
                const VelocityLawParams& params);

struct CommandPipelineParams;

/// The follow law's parameters from their names (doc/nodes/velocity_controller.md:
/// follow_distance, ..., linear_pid/*, angular_pid/*), with the speed cap and stop
/// distance taken from the pipeline's (lawWithCommon). Throws ParamError.
VelocityLawParams loadVelocityLawParams(const ParamSource& source,
                                        const CommandPipelineParams& common);
/// `law` with max_linear, safe_distance and the PIDs' output limits from `common`,
/// validated (throws ParamError): the law must stop before the safety stop trips.
VelocityLawParams lawWithCommon(VelocityLawParams law, const CommandPipelineParams& common);

}  // namespace control
}  // namespace radio_follow
