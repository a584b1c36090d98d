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

/// Remembers the last reported (state, text) so the node publishes status only on a
/// change, as the announcer speaks each message it receives.
class StatusTracker {
 public:
  /// True when (state, text) differs from the last call (always true the first time).
  bool update(FollowerState state, const std::string& text);

 private:
  bool has_last_ = false;
  FollowerState last_state_ = FollowerState::kDisabled;
  std::string last_text_;
};

/// What a control law wants this tick.
struct LawOutput {
  VelocityCommand command;
  FollowerState state = FollowerState::kFollowing;
  std::string text;  ///< empty: defaultText(state)
};

}  // namespace control
}  // namespace radio_follow
