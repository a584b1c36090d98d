// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <Eigen/Core>

namespace radio_follow {

/// Planar pose: x, y in metres, yaw in radians (REP-103), in whatever fixed frame the
/// user states (the odometry frame for the controllers, the world for the simulator).
struct Pose2 {
  double x = 0.0;
  double y = 0.0;
  double yaw = 0.0;

  Eigen::Vector2d position() const { return {x, y}; }
};

}  // namespace radio_follow
