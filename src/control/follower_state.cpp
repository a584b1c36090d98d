// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/control/follower_state.hpp"

namespace radio_follow {
namespace control {

const char* toString(FollowerState state) {
  switch (state) {
    case FollowerState::kDisabled:
      return "disabled";
    case FollowerState::kWaitingForTarget:
      return "waiting_for_target";
    case FollowerState::kFollowing:
      return "following";
    case FollowerState::kTooClose:
      return "too_close";
    case FollowerState::kTargetLost:
      return "target_lost";
    case FollowerState::kArrived:
      return "arrived";
    case FollowerState::kTargetAmbiguous:
      return "target_ambiguous";
  }
  return "unknown";
}

FollowerState stateFor(StopReason reason) {
  switch (reason) {
    case StopReason::kNone:
      return FollowerState::kFollowing;
    case StopReason::kDisabled:
      return FollowerState::kDisabled;
    case StopReason::kNoEstimateYet:
      return FollowerState::kWaitingForTarget;
    case StopReason::kTooClose:
      return FollowerState::kTooClose;
    case StopReason::kEstimateStale:
    case StopReason::kTargetLost:
    case StopReason::kRangesSilent:
    case StopReason::kFutureStamp:
    case StopReason::kImplausibleRange:
    case StopReason::kInternalFault:
      return FollowerState::kTargetLost;
    case StopReason::kClockJumped:
      return FollowerState::kWaitingForTarget;
    case StopReason::kTargetAmbiguous:
      return FollowerState::kTargetAmbiguous;
  }
  return FollowerState::kTargetLost;
}

std::string stopText(StopReason reason) {
  switch (reason) {
    case StopReason::kNone:
      return "Following.";
    case StopReason::kDisabled:
      return "Following disabled.";
    case StopReason::kNoEstimateYet:
      return "Waiting for the target.";
    case StopReason::kTooClose:
      return "Too close, stopping.";
    case StopReason::kEstimateStale:
      return "Target estimate too old, stopping.";
    case StopReason::kTargetLost:
      return "Target lost, stopping.";
    case StopReason::kTargetAmbiguous:
      return "Cannot tell where the target is, it may be the mirror image: stopping.";
    case StopReason::kRangesSilent:
      return "No range to the target, stopping.";
    case StopReason::kFutureStamp:
      return "Clock mismatch, a message from the future, stopping.";
    case StopReason::kClockJumped:
      return "Clock jumped back, starting over.";
    case StopReason::kImplausibleRange:
      return "A range no sensor can report, stopping.";
    case StopReason::kInternalFault:
      return "Internal error while handling a message, stopping.";
  }
  return "Stopping.";
}

std::string defaultText(FollowerState state) {
  switch (state) {
    case FollowerState::kDisabled:
      return stopText(StopReason::kDisabled);
    case FollowerState::kWaitingForTarget:
      return stopText(StopReason::kNoEstimateYet);
    case FollowerState::kFollowing:
      return "Following.";
    case FollowerState::kTooClose:
      return stopText(StopReason::kTooClose);
    case FollowerState::kTargetLost:
      return stopText(StopReason::kTargetLost);
    case FollowerState::kArrived:
      return "Arrived, waiting.";
    case FollowerState::kTargetAmbiguous:
      return stopText(StopReason::kTargetAmbiguous);
  }
  return "Stopping.";
}

bool StatusTracker::announce(FollowerState state, const std::string& text) {
  has_announced_ = true;
  announced_state_ = state;
  announced_text_ = text;
  contradicted_ = false;
  return true;
}

bool StatusTracker::update(FollowerState state, const std::string& text, double now) {
  // A clock that ran back restarts every span from now.
  if (now < state_since_ || now < text_since_ || (contradicted_ && now < contradicted_since_)) {
    state_since_ = text_since_ = contradicted_since_ = now;
  }
  if (!has_current_ || state != current_state_) {
    state_since_ = now;
  }
  if (!has_current_ || state != current_state_ || text != current_text_) {
    text_since_ = now;
  }
  has_current_ = true;
  current_state_ = state;
  current_text_ = text;

  if (!has_announced_ || state == FollowerState::kDisabled) {
    if (has_announced_ && state == announced_state_ && text == announced_text_) {
      return false;
    }
    return announce(state, text);
  }
  if (state == announced_state_) {
    contradicted_ = false;
    return text != announced_text_ && now - text_since_ >= kStatusSettleTime &&
           announce(state, text);
  }
  if (!contradicted_) {
    contradicted_ = true;
    contradicted_since_ = now;
  }
  if (now - state_since_ >= kStatusSettleTime || now - contradicted_since_ >= kStatusSettleTime) {
    return announce(state, text);
  }
  return false;
}

}  // namespace control
}  // namespace radio_follow
