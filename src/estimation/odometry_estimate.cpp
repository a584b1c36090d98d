// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/estimation/odometry_estimate.hpp"

namespace radio_follow {
namespace estimation {

std::optional<OdometryEstimate> inOdometry(const LocatorEstimate& estimate, const PoseAt& pose_at) {
  if (estimate.status == TargetStatus::kLost) {
    return std::nullopt;
  }
  OdometryEstimate out;
  if (estimate.in_odom) {
    out.robot = estimate.robot_pose.position();
    out.position = estimate.tracking_position;
    out.velocity = estimate.tracking_velocity;
  } else {
    const std::optional<Pose2> pose = pose_at ? pose_at(estimate.stamp) : std::nullopt;
    if (!pose) {
      return std::nullopt;
    }
    out.robot = pose->position();
    out.position = pose->toFixed(estimate.position);
  }
  if (!out.robot.allFinite() || !out.position.allFinite()) {
    return std::nullopt;
  }
  if (out.velocity && !out.velocity->allFinite()) {
    out.velocity.reset();
  }
  return out;
}

}  // namespace estimation
}  // namespace radio_follow
