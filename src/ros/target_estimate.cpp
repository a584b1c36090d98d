// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/ros/target_estimate.hpp"

#include <cmath>

namespace radio_follow {

bool hasPosition(const TargetEstimate& estimate) {
  return estimate.status == TargetEstimate::STATUS_OK ||
         estimate.status == TargetEstimate::STATUS_DEGRADED;
}

control::EstimateQuality estimateQuality(const TargetEstimate& estimate) {
  if (estimate.status == TargetEstimate::STATUS_AMBIGUOUS) {
    return control::EstimateQuality::kAmbiguous;
  }
  const bool known =
      hasPosition(estimate) || estimate.status == TargetEstimate::STATUS_HEADING_ONLY;
  return known && std::isfinite(estimate.bearing) && std::isfinite(estimate.range)
             ? control::EstimateQuality::kUsable
             : control::EstimateQuality::kLost;
}

}  // namespace radio_follow
