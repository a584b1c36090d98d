// SPDX-License-Identifier: BSD-3-Clause
#pragma once

// The locator's output vocabulary, shared by the estimator and the follow laws (the
// estimate-to-law translation, control/follow_inputs.hpp); header-only, so that a
// controller's wrapper reads an estimate's status without linking the estimator (Ceres).
#include <cstdint>

namespace radio_follow {

/// Same values as TargetEstimate.STATUS_*. Zero is no status: a zero-initialised message
/// must never read as a usable estimate.
enum class TargetStatus : std::uint8_t {
  kUnset = 0,
  kOk = 1,
  kHeadingOnly = 2,
  kDegraded = 3,
  kLost = 4,
  kAmbiguous = 5,
};
/// "UNSET", "OK", "HEADING_ONLY", "DEGRADED", "LOST", "AMBIGUOUS" (the message's constant
/// names).
inline const char* toString(TargetStatus status) {
  switch (status) {
    case TargetStatus::kUnset:
      return "UNSET";
    case TargetStatus::kOk:
      return "OK";
    case TargetStatus::kHeadingOnly:
      return "HEADING_ONLY";
    case TargetStatus::kDegraded:
      return "DEGRADED";
    case TargetStatus::kAmbiguous:
      return "AMBIGUOUS";
    case TargetStatus::kLost:
      break;
  }
  return "LOST";
}
/// OK or DEGRADED: the position may be driven towards (HEADING_ONLY: only the direction).
inline bool hasPosition(TargetStatus status) {
  return status == TargetStatus::kOk || status == TargetStatus::kDegraded;
}
/// Same bits as TargetEstimate.SOURCE_*.
constexpr std::uint8_t kSourceTwr = 1;
constexpr std::uint8_t kSourceTdoa = 2;
constexpr std::uint8_t kSourceAoa = 4;

}  // namespace radio_follow
