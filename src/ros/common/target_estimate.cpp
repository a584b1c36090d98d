// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/ros/common/target_estimate.hpp"

#include <cmath>
#include <cstdint>

#include "radio_follow/estimation/target_status.hpp"
#include "radio_follow/evaluation/follow_inputs.hpp"

namespace radio_follow {
namespace {

constexpr std::uint8_t value(estimation::TargetStatus status) {
  return static_cast<std::uint8_t>(status);
}
static_assert(
    TargetEstimate::STATUS_UNSET == value(estimation::TargetStatus::kUnset) &&
        TargetEstimate::STATUS_OK == value(estimation::TargetStatus::kOk) &&
        TargetEstimate::STATUS_HEADING_ONLY == value(estimation::TargetStatus::kHeadingOnly) &&
        TargetEstimate::STATUS_DEGRADED == value(estimation::TargetStatus::kDegraded) &&
        TargetEstimate::STATUS_LOST == value(estimation::TargetStatus::kLost) &&
        TargetEstimate::STATUS_AMBIGUOUS == value(estimation::TargetStatus::kAmbiguous),
    "estimation::TargetStatus must equal TargetEstimate.STATUS_* (locator_node copies them)");

}  // namespace

bool hasPosition(const TargetEstimate& estimate) {
  return estimation::hasPosition(static_cast<estimation::TargetStatus>(estimate.status));
}

control::EstimateQuality estimateQuality(const TargetEstimate& estimate) {
  const auto status = static_cast<estimation::TargetStatus>(estimate.status);
  // A position no UWB network spans (non-finite, beyond kMaxCoordinate) is no target.
  const auto& p = estimate.position;
  if (hasPosition(status) && !(plausibleCoordinate(p.x) && plausibleCoordinate(p.y) &&
                               plausibleCoordinate(p.z))) {
    return control::EstimateQuality::kLost;
  }
  return evaluation::estimateQuality(status, estimate.range, estimate.bearing);
}

}  // namespace radio_follow
