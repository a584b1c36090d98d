// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstdint>
#include <limits>
#include <map>
#include <string>

#include "radio_follow/common/param_table.hpp"
#include "radio_follow/common/time_policy.hpp"
#include "radio_follow/control/follower_state.hpp"
#include "radio_follow/control/rate_limiter.hpp"

namespace radio_follow {
namespace control {

/// Bounds of the safety parameters, enforced at start and in live tuning.
constexpr double kMinSafeDistance = 0.3;      ///< m: several times a range's error
constexpr double kMaxSafeDistance = 10.0;     ///< m: beyond that no follow law works
constexpr double kMaxFreshnessTimeout = 3.0;  ///< s: estimate_timeout, range_timeout
constexpr double kMaxHoldTime = 30.0;         ///< s

/// Parameters of the safety layer shared by all controllers.
struct SafetyParams {
  /// Any raw range to the target below this stops the robot, metres.
  double safe_distance = 1.3;
  /// An estimate older than this (by its stamp) stops the robot, seconds.
  double estimate_timeout = 0.5;
  /// When ranges are watched, a range source silent for longer than this is
  /// forgotten, and with every source silent the robot stops, seconds.
  double range_timeout = 1.0;
  /// A stop condition must have been clear this long before motion resumes, seconds.
  double hold_time = 1.0;
  /// Whether raw ranges are watched at all (false for AoA-only homing).
  bool watch_ranges = true;

  /// The parameters (not watch_ranges, which the node derives): names, units, bounds.
  static const ParamTable<SafetyParams>& table();
  void validate() const;
};

/// The safety layer's verdict.
struct SafetyDecision {
  bool may_move = false;
  StopReason reason = StopReason::kNoEstimateYet;
};

/// Decides "may the robot move?" from raw events only, never from what a controller
/// computed. Pure and clock-free: every call carries its times (seconds, one clock).
/// It does not trust the estimator: a raw range below safe_distance blocks motion even
/// when the estimate says the target is far away. Time follows TimePolicy: freshness is
/// judged by stamp on the receiver's clock, a stamp from the future blocks motion and
/// never counts as fresh, the hold after a violation runs from its receive time (a
/// stale short range keeps the robot stopped for hold_time instead of flapping), and a
/// clock that runs backwards resets the state (motion resumes only after a new estimate,
/// new ranges and hold_time).
class SafetyMonitor {
 public:
  explicit SafetyMonitor(const SafetyParams& params);

  /// A raw range from `source` (e.g. "<topic>/<module>") stamped `stamp`, received at
  /// `now`. Returns true when this range alone blocks motion (too close, NaN or from the
  /// future); the node then publishes zero at once, before the next control tick.
  bool onRange(double stamp, double now, const std::string& source, double range);

  /// A range received at `now` that no module can report (common/plausibility.hpp):
  /// blocks motion and is not stored, so it never counts as a live range.
  void onImplausibleRange(double now);
  /// The node failed while handling an input at `now` (a callback threw): blocks motion
  /// for hold_time, as a violation does.
  void onFault(double now);
  std::uint64_t implausibleRanges() const { return implausible_ranges_; }

  /// An estimate stamped `stamp` received at `now`, of the given quality.
  /// Returns false when it was refused (from the future; motion is then blocked).
  bool onEstimate(double stamp, double now, EstimateQuality quality);

  /// New thresholds at runtime (live tuning). Throws ParamError and keeps the old ones
  /// when `params` fails validate(); the latched state and the last ranges are kept.
  void setParams(const SafetyParams& params);
  const SafetyParams& params() const { return params_; }

  void setEnabled(bool enabled) { enabled_ = enabled; }
  bool enabled() const { return enabled_; }

  /// Smallest range heard within range_timeout before `now` (m), +inf when none. For the
  /// control laws' clearance from the stop (VelocityLawParams::stop_margin), not a verdict.
  double nearestRange(double now) const;

  /// The verdict at `now`. Blocking conditions latch for `hold_time` after they clear.
  SafetyDecision evaluate(double now);

  /// Stamps refused as from the future, clock jumps seen.
  const TimePolicy& time() const { return time_; }
  /// How far ahead of `now` a stamp may be (futureStampTolerance of the receiver's clock).
  void setFutureTolerance(double seconds) { time_.setFutureTolerance(seconds); }

 private:
  StopReason rawReason(double now);
  void block(double now, StopReason reason);
  /// Resets the time-dependent state when the clock ran backwards.
  void observe(double now);

  SafetyParams params_;
  TimePolicy time_;
  bool enabled_ = false;
  std::map<std::string, std::pair<double, double>> ranges_;  // source -> (stamp, range)
  bool has_estimate_ = false;
  double estimate_stamp_ = 0.0;
  EstimateQuality estimate_quality_ = EstimateQuality::kLost;
  bool blocked_once_ = false;
  double last_block_time_ = 0.0;
  StopReason last_block_reason_ = StopReason::kNoEstimateYet;
  std::uint64_t implausible_ranges_ = 0;
  /// Receive time of the latest implausible range.
  double last_implausible_ = -std::numeric_limits<double>::infinity();
};

/// The command actually sent: `command` when the decision allows motion, else zero.
/// Kept separate so that the property "stop condition => zero" is checked on exactly
/// the function the nodes use.
VelocityCommand gateCommand(const SafetyDecision& decision, const VelocityCommand& command);

}  // namespace control
}  // namespace radio_follow
