// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/control/target_track.hpp"

#include <cmath>

#include "radio_follow/common/plausibility.hpp"

namespace radio_follow {
namespace control {

std::optional<TrackPoint> trackPoint(const Eigen::Vector2d& robot, const Eigen::Vector2d& target,
                                     const std::optional<Eigen::Vector2d>& velocity) {
  const auto plausible = [](const Eigen::Vector2d& p) {
    return plausibleOdometryCoordinate(p.x()) && plausibleOdometryCoordinate(p.y());
  };
  if (!plausible(robot) || !plausible(target)) {
    return std::nullopt;
  }
  TrackPoint point;
  point.robot = robot;
  point.target = target;
  if (velocity && velocity->allFinite() && plausibleTargetSpeed(velocity->norm())) {
    point.velocity = velocity;
  }
  return point;
}

bool TargetTrack::add(double t, const TrackPoint& point) {
  if (!std::isfinite(t) || (!points_.empty() && t < points_.back().t)) {
    return false;
  }
  points_.push_back({t, point});
  while (points_.front().t < t - kWindow) {
    points_.pop_front();
  }
  return true;
}

std::optional<Eigen::Vector2d> TargetTrack::velocity(double now) const {
  Eigen::Vector2d sum = Eigen::Vector2d::Zero();
  int n = 0;
  for (const Stamped& s : points_) {
    if (s.point.velocity && now - s.t <= kWindow) {
      sum += *s.point.velocity;
      ++n;
    }
  }
  if (n == 0) {
    return std::nullopt;
  }
  return Eigen::Vector2d(sum / n);
}

std::optional<double> TargetTrack::speed(double now) const {
  const std::optional<Eigen::Vector2d> v = velocity(now);
  if (!v) {
    return std::nullopt;
  }
  return v->norm();
}

std::optional<double> TargetTrack::recedingSpeed(double now) const {
  const std::optional<Eigen::Vector2d> v = velocity(now);
  if (!v) {
    return std::nullopt;
  }
  const Eigen::Vector2d line = points_.back().point.target - points_.back().point.robot;
  if (!(line.norm() > 1e-6)) {
    return std::nullopt;
  }
  return v->dot(line.normalized());
}

}  // namespace control
}  // namespace radio_follow
