// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <map>
#include <optional>
#include <string>

#include "radio_follow/common/param_source.hpp"
#include "radio_follow/config/layout.hpp"
#include "radio_follow/control/follower_state.hpp"
#include "radio_follow/control/obstacle_avoidance.hpp"
#include "radio_follow/control/pid.hpp"
#include "radio_follow/control/rate_limiter.hpp"
#include "radio_follow/control/safety_monitor.hpp"

namespace radio_follow {
namespace control {

/// Largest change a module's calibration may make to a range at safe_distance, m: beyond
/// it the calibration is more likely a typo than a module. Real DWM1001-class modules read
/// long by up to 0.31 m plus 2 % of the range (issue 14's recording; the simulator's
/// realistic profile draws from that span), 0.34 m at 1.3 m, so 0.3 m refused real ones.
constexpr double kMaxSafetyCalibrationShift = 0.5;

/// Parameters of the command pipeline every controller shares: the safety stop on raw
/// ranges and estimates, the laser-scan gate, the speed and acceleration limits.
/// Names are the controllers' private parameters (doc/nodes/velocity_controller.md).
struct CommandPipelineParams {
  SafetyParams safety;
  MotionLimits limits;
  AvoidanceParams avoidance;
  bool use_scan = false;
  double scan_timeout = 0.5;  ///< s
  /// Anchor carried by the target (normalised ID); empty = every anchor counts.
  std::string target_anchor_id;
  /// Apply each module's range calibration from the layout to its raw ranges before the
  /// safe_distance check (a sensor correction; the estimator is still not involved).
  bool calibrate_ranges = true;
  /// Range calibration per module ID (upper case), from the layout when calibrate_ranges.
  /// Ranges of a module not listed are compared raw.
  std::map<std::string, TwrModule> calibrated_modules;

  /// Reads `calibrate_ranges`; with a layout takes its target anchor and (when
  /// calibrate_ranges) its module calibrations; then reads `target_anchor_id` (over the
  /// layout's), `use_scan`, `scan_timeout`, the safety thresholds, the motion limits and
  /// `avoidance/*`. Absent keys keep their value.
  void load(const ParamSource& source, const Layout* layout);
  /// The safety thresholds, the limits, avoidance/*, use_scan, scan_timeout,
  /// calibrate_ranges and target_anchor_id.
  static const ParamTable<CommandPipelineParams>& table();
  /// Throws ParamError naming the first unusable parameter.
  void validate() const;
};

/// One command through the pipeline: its value, and the status that goes with it.
struct PipelineResult {
  VelocityCommand command;
  FollowerState state = FollowerState::kDisabled;
  std::string text;
  /// false: the safety layer stopped the robot (`command` is zero).
  bool moving = false;
  /// Avoidance was asked for but no fresh scan exists: forward motion was blocked.
  bool scan_missing = false;
};

/// The path from a control law's request to the command sent, shared by every controller
/// and by the lockstep closed loop (sim/closed_loop.hpp): the safety verdict before the
/// law runs, then scan gating (obstacle avoidance), the verdict again at the time of
/// sending, the rate and acceleration limits, and the gate that makes any stop condition
/// a zero command. Clock-free: every call carries its times (seconds, one clock).
/// Not thread-safe: a node with a separate safety thread holds one lock around it.
class CommandPipeline {
 public:
  /// `params` validated by the caller.
  explicit CommandPipeline(const CommandPipelineParams& params);

  /// A raw range of module `module_id` to anchor `anchor_id` stamped `stamp`, received at
  /// `now`, from `source` (e.g. "<topic>/<module>"). Ranges to other anchors than the
  /// target's are ignored; the module's calibration is applied. Returns true when this
  /// range alone blocks motion (too close, implausible or from the future): send zero at once.
  bool onRange(double stamp, double now, const std::string& source, const std::string& module_id,
               const std::string& anchor_id, double raw_range);
  /// An estimate (or bearing, for homing); false when refused (from the future).
  bool onEstimate(double stamp, double now, EstimateQuality quality);
  /// The node failed while handling an input (a callback threw): motion is blocked for
  /// hold_time (SafetyMonitor::onFault). Send stop(StopReason::kInternalFault) at once.
  void onFault(double now) { monitor_.onFault(now); }
  /// A laser scan's sectors, stamped `stamp`.
  void onScan(const SectorRanges& sectors, double stamp);
  void setEnabled(bool enabled) { monitor_.setEnabled(enabled); }
  bool enabled() const { return monitor_.enabled(); }

  /// The verdict before the law runs: when it forbids motion, call stop() instead.
  SafetyDecision check(double now) { return monitor_.evaluate(now); }
  /// The law's output through scan gating, the verdict at `now` (the time of sending),
  /// the limits (`dt` s since the previous command) and the gate.
  PipelineResult finish(const LawOutput& out, double now, double dt);
  /// The stop: zero command, the reason's state and text; the limiter starts from rest.
  PipelineResult stop(StopReason reason);

  /// Nearest fresh (calibrated) module range minus safe_distance at `now`, m; +inf when
  /// ranges are not watched or none is fresh (the safety layer stops the robot then).
  double moduleGap(double now) const;

  /// New parameters (live tuning; validated by the caller). Throws ParamError and keeps
  /// the old ones when the safety thresholds or limits are unusable.
  void setParams(const CommandPipelineParams& params);
  const CommandPipelineParams& params() const { return params_; }
  const SafetyMonitor& monitor() const { return monitor_; }
  /// How far ahead of `now` a stamp may be (futureStampTolerance of the receiver's clock).
  void setFutureTolerance(double seconds) { monitor_.setFutureTolerance(seconds); }

 private:
  CommandPipelineParams params_;
  SafetyMonitor monitor_;
  CommandLimiter limiter_;
  std::optional<SectorRanges> sectors_;
  double scan_stamp_ = 0.0;
};

}  // namespace control
}  // namespace radio_follow
