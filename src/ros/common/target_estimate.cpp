// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/ros/common/target_estimate.hpp"

#include <cmath>
#include <cstdint>

#include "radio_follow/common/target_status.hpp"
#include "radio_follow/control/follow_inputs.hpp"
#include "radio_follow/control/target_track.hpp"

namespace radio_follow {
namespace {

constexpr std::uint8_t value(TargetStatus status) {
  return static_cast<std::uint8_t>(status);
}
static_assert(TargetEstimate::STATUS_UNSET == value(TargetStatus::kUnset) &&
                  TargetEstimate::STATUS_OK == value(TargetStatus::kOk) &&
                  TargetEstimate::STATUS_HEADING_ONLY == value(TargetStatus::kHeadingOnly) &&
                  TargetEstimate::STATUS_DEGRADED == value(TargetStatus::kDegraded) &&
                  TargetEstimate::STATUS_LOST == value(TargetStatus::kLost) &&
                  TargetEstimate::STATUS_AMBIGUOUS == value(TargetStatus::kAmbiguous),
              "TargetStatus must equal TargetEstimate.STATUS_* (locator_node copies them)");

}  // namespace

bool hasPosition(const TargetEstimate& estimate) {
  return hasPosition(static_cast<TargetStatus>(estimate.status));
}

control::EstimateQuality estimateQuality(const TargetEstimate& estimate) {
  const auto status = static_cast<TargetStatus>(estimate.status);
  // A position no UWB network spans (non-finite, beyond kMaxCoordinate) is no target.
  const auto& p = estimate.position;
  if (hasPosition(status) && !(plausibleCoordinate(p.x) && plausibleCoordinate(p.y) &&
                               plausibleCoordinate(p.z))) {
    return control::EstimateQuality::kLost;
  }
  // The odometry-frame part, when there is one: positions a robot's odometry can hold, a
  // velocity unknown (NaN) or a person's.
  const auto vector = [](const auto& q) { return Eigen::Vector3d(q.x, q.y, q.z); };
  if (!estimate.odom_frame.empty() &&
      !control::plausibleOdometryPart(vector(estimate.odom_robot), vector(estimate.odom_position),
                                      vector(estimate.odom_velocity))) {
    return control::EstimateQuality::kLost;
  }
  return control::estimateQuality(status, estimate.range, estimate.bearing);
}

}  // namespace radio_follow
