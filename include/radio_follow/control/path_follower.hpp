// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <Eigen/Core>
#include <deque>

#include "radio_follow/common/pose2.hpp"

namespace radio_follow {
namespace control {

using radio_follow::Pose2;  ///< in the odometry frame here

/// The human's path in a fixed (odometry) frame (thesis Section 4.7): points at least
/// `min_spacing` apart, oldest first, pruned as the robot passes them.
class PathBuffer {
 public:
  PathBuffer(double min_spacing, std::size_t max_points);

  /// Appends the target's position unless it is closer than min_spacing to the newest
  /// point (a standing person then does not fill the buffer with noise).
  /// Returns true when the point was stored.
  bool add(const Eigen::Vector2d& point);

  /// Drops the points the robot has passed: everything before the stored point nearest
  /// to the robot, and that point too once it is within `reached_radius`.
  void prune(const Eigen::Vector2d& robot, double reached_radius);

  /// Distance from the robot along the stored path to its newest point, metres:
  /// straight to the first point, then along the segments.
  double lengthFrom(const Eigen::Vector2d& robot) const;

  const std::deque<Eigen::Vector2d>& points() const { return points_; }
  bool empty() const { return points_.empty(); }
  void clear() { points_.clear(); }

 private:
  double min_spacing_;
  std::size_t max_points_;
  std::deque<Eigen::Vector2d> points_;
};

/// Pure pursuit's output: the goal point and the curvature of the arc through it.
struct PursuitTarget {
  Eigen::Vector2d point = Eigen::Vector2d::Zero();
  /// Goal in the robot frame (x forward, y left), metres.
  Eigen::Vector2d local = Eigen::Vector2d::Zero();
  /// Signed curvature 2 y / L^2 of the arc from the robot through the goal, 1/m.
  double curvature = 0.0;
  bool valid = false;
};

/// Picks the first path point at least `lookahead` from the robot (else the newest
/// point) and returns the pure-pursuit arc to it.
PursuitTarget purePursuit(const std::deque<Eigen::Vector2d>& path, const Pose2& robot,
                          double lookahead);

}  // namespace control
}  // namespace radio_follow
