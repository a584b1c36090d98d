// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/control/path_follower.hpp"

#include <cmath>
#include <limits>

namespace radio_follow {
namespace control {

PathBuffer::PathBuffer(double min_spacing, std::size_t max_points)
    : min_spacing_(min_spacing), max_points_(max_points) {}

bool PathBuffer::add(const Eigen::Vector2d& point) {
  if (!point.allFinite()) {
    return false;
  }
  if (!points_.empty() && (point - points_.back()).norm() < min_spacing_) {
    return false;
  }
  points_.push_back(point);
  while (points_.size() > max_points_) {
    points_.pop_front();
  }
  return true;
}

void PathBuffer::prune(const Eigen::Vector2d& robot, double reached_radius) {
  if (points_.empty()) {
    return;
  }
  std::size_t nearest = 0;
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < points_.size(); ++i) {
    const double d = (points_[i] - robot).norm();
    if (d < best) {
      best = d;
      nearest = i;
    }
  }
  std::size_t drop = nearest;
  // Keep the newest point: it is where the person is, the robot must never lose it.
  if (best < reached_radius && nearest + 1 < points_.size()) {
    drop = nearest + 1;
  }
  points_.erase(points_.begin(), points_.begin() + static_cast<std::ptrdiff_t>(drop));
}

double PathBuffer::lengthFrom(const Eigen::Vector2d& robot) const {
  if (points_.empty()) {
    return 0.0;
  }
  double length = (points_.front() - robot).norm();
  for (std::size_t i = 1; i < points_.size(); ++i) {
    length += (points_[i] - points_[i - 1]).norm();
  }
  return length;
}

PursuitTarget purePursuit(const std::deque<Eigen::Vector2d>& path, const Pose2& robot,
                          double lookahead) {
  PursuitTarget target;
  if (path.empty()) {
    return target;
  }
  target.point = path.back();
  for (const auto& p : path) {
    if ((p - robot.position()).norm() >= lookahead) {
      target.point = p;
      break;
    }
  }
  const Eigen::Vector2d delta = target.point - robot.position();
  const double c = std::cos(robot.yaw);
  const double s = std::sin(robot.yaw);
  target.local = Eigen::Vector2d(c * delta.x() + s * delta.y(), -s * delta.x() + c * delta.y());
  const double l2 = target.local.squaredNorm();
  target.curvature = l2 > 1e-12 ? 2.0 * target.local.y() / l2 : 0.0;
  target.valid = true;
  return target;
}

}  // namespace control
}  // namespace radio_follow
