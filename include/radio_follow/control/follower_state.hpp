// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstdint>
#include <string>

#include "radio_follow/control/rate_limiter.hpp"

namespace radio_follow {
namespace control {

/// Controller states; the numeric values equal FollowerStatus.STATE_*.
enum class FollowerState : std::uint8_t {
  kDisabled = 0,
  kWaitingForTarget = 1,
  kFollowing = 2,
  kTooClose = 3,
  kTargetLost = 4,
  kArrived = 5,
  kTargetAmbiguous = 6,
};

/// What a controller may do with the newest estimate.
enum class EstimateQuality {
  kUsable,     ///< OK, DEGRADED or HEADING_ONLY with a finite range and bearing
  kLost,       ///< LOST, unset or not finite
  kAmbiguous,  ///< AMBIGUOUS: the target may be at its mirror image
};

/// Why the safety layer holds the robot (or kNone when it may move).
enum class StopReason {
  kNone,
  kDisabled,
  kNoEstimateYet,
  kTooClose,
  kEstimateStale,
  kTargetLost,
  /// The estimate is AMBIGUOUS (mirror image possible).
  kTargetAmbiguous,
  kRangesSilent,
  /// A range or estimate stamped ahead of this node's clock (TimePolicy).
  kFutureStamp,
  /// This node's clock ran backwards (bag loop, simulator restart): state was reset.
  kClockJumped,
  /// A range no module can report (non-finite, negative or beyond kMaxUwbRange,
  /// common/plausibility.hpp): a faulty publisher, so the ranges cannot be trusted.
  kImplausibleRange,
  /// A callback of the node threw (CallbackBarrier): whatever it was handling is unknown.
  kInternalFault,
};

/// The state's name as diagnostics and logs show it: "disabled", "waiting_for_target",
/// "following", "too_close", "target_lost", "arrived", "target_ambiguous"
/// (FollowerStatus.STATE_* in lower
/// case, without the prefix); "unknown" for a value outside the enum.
const char* toString(FollowerState state);

/// The state a stop reason is reported as (kNone maps to kFollowing).
FollowerState stateFor(StopReason reason);

/// A short sentence a person can hear, e.g. "Too close, stopping."
std::string stopText(StopReason reason);

/// Default sentence for a state (used when the controller gives no more specific one).
std::string defaultText(FollowerState state);

/// How long a status must hold before it is announced, s. Inputs at the edge of two stop
/// reasons (steady future-stamped ranges: "Clock mismatch" / "No range to the target")
/// used to flip the status 20 times a second, and the announcer spoke both in turn. Half
/// a second is shorter than the shipped stop's hold (hold_time), so every stop is still
/// announced; cmd_vel does not wait for it.
constexpr double kStatusSettleTime = 0.5;

/// Decides when the node announces its status (FollowerStatus, the announcer speaks each
/// one). The first status and "disabled" (an operator's command) are announced at once.
/// Otherwise a new state is announced once it has held kStatusSettleTime, or once the
/// announced state has not been the current one for kStatusSettleTime (states that flap
/// faster than that are announced as the one current then, not left untold); a new text
/// within the announced state once it has held kStatusSettleTime.
class StatusTracker {
 public:
  /// The current (state, text) at `now` (s, the node's clock): true when it is to be
  /// announced now.
  bool update(FollowerState state, const std::string& text, double now);

 private:
  bool announce(FollowerState state, const std::string& text);

  bool has_announced_ = false;
  FollowerState announced_state_ = FollowerState::kDisabled;
  std::string announced_text_;
  bool has_current_ = false;
  FollowerState current_state_ = FollowerState::kDisabled;
  std::string current_text_;
  double state_since_ = 0.0;         ///< the current state holds since
  double text_since_ = 0.0;          ///< the current text holds since
  double contradicted_since_ = 0.0;  ///< the announced state is not current since
  bool contradicted_ = false;
};

/// What a control law wants this tick.
struct LawOutput {
  VelocityCommand command;
  FollowerState state = FollowerState::kFollowing;
  std::string text;  ///< empty: defaultText(state)
};

}  // namespace control
}  // namespace radio_follow
