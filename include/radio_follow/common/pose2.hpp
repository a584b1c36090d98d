// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <Eigen/Core>
#include <cmath>

namespace radio_follow {

/// Planar pose: x, y in metres, yaw in radians (REP-103), in whatever fixed frame the
/// user states (the odometry frame for the controllers, the world for the simulator).
struct Pose2 {
  double x = 0.0;
  double y = 0.0;
  double yaw = 0.0;

  Eigen::Vector2d position() const { return {x, y}; }

  /// A point given in the frame of this pose (e.g. the robot's) in the pose's fixed frame
  /// (e.g. odom); z unchanged.
  Eigen::Vector3d toFixed(const Eigen::Vector3d& p) const {
    const double c = std::cos(yaw);
    const double s = std::sin(yaw);
    return {x + c * p.x() - s * p.y(), y + s * p.x() + c * p.y(), p.z()};
  }
  /// The inverse: a point of the fixed frame seen from this pose.
  Eigen::Vector3d fromFixed(const Eigen::Vector3d& p) const {
    const double c = std::cos(yaw);
    const double s = std::sin(yaw);
    const double dx = p.x() - x;
    const double dy = p.y() - y;
    return {c * dx + s * dy, -s * dx + c * dy, p.z()};
  }
};

}  // namespace radio_follow
