// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <map>
#include <string>

#include "radio_follow/control/follower_state.hpp"
#include "radio_follow/control/rate_limiter.hpp"

namespace radio_follow {
namespace control {

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

  void validate() const;
};

/// The safety layer's verdict.
struct SafetyDecision {
  bool may_move = false;
  StopReason reason = StopReason::kNoEstimateYet;
};

/// Decides "may the robot move?" from raw events only, never from what a controller
/// computed. Pure and clock-free: every call carries its time (seconds, one clock).
/// It does not trust the estimator: a raw range below safe_distance blocks motion even
/// when the estimate says the target is far away.
class SafetyMonitor {
 public:
  explicit SafetyMonitor(const SafetyParams& params);

  /// A raw range from source `source` (e.g. "<topic>/<module>") measured at `time`.
  /// Returns true when this range alone is a violation (the node then publishes zero
  /// at once, before the next control tick).
  bool onRange(double time, const std::string& source, double range);

  /// An estimate stamped `stamp`; `usable` is false for a LOST estimate.
  void onEstimate(double stamp, bool usable);

  /// New thresholds at runtime (live tuning). Throws ParamError and keeps the old ones
  /// when `params` fails validate(); the latched state and the last ranges are kept.
  void setParams(const SafetyParams& params);

  void setEnabled(bool enabled) { enabled_ = enabled; }
  bool enabled() const { return enabled_; }

  /// Smallest range heard within range_timeout before `now` (m), +inf when none. For the
  /// control laws' clearance from the stop (VelocityLawParams::stop_margin), not a verdict.
  double nearestRange(double now) const;

  /// The verdict at `now`. Blocking conditions latch for `hold_time` after they clear.
  SafetyDecision evaluate(double now);

 private:
  StopReason rawReason(double now);

  SafetyParams params_;
  bool enabled_ = false;
  std::map<std::string, std::pair<double, double>> ranges_;  // source -> (time, range)
  bool has_estimate_ = false;
  double estimate_stamp_ = 0.0;
  bool estimate_usable_ = false;
  bool blocked_once_ = false;
  double last_block_time_ = 0.0;
  StopReason last_block_reason_ = StopReason::kNoEstimateYet;
};

/// The command actually sent: `command` when the decision allows motion, else zero.
/// Kept separate so that the property "stop condition => zero" is checked on exactly
/// the function the nodes use.
VelocityCommand gateCommand(const SafetyDecision& decision, const VelocityCommand& command);

}  // namespace control
}  // namespace radio_follow
