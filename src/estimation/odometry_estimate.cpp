// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/estimation/odometry_estimate.hpp"

#include <algorithm>
#include <cmath>

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

std::optional<OdometryEstimate> OdometryTrack::update(const LocatorEstimate& estimate,
                                                      const PoseAt& pose_at) {
  std::optional<OdometryEstimate> out = inOdometry(estimate, pose_at);
  if (!out || out->velocity) {
    return out;
  }
  const double t = estimate.stamp;
  if (!samples_.empty() && t < samples_.back().t) {
    samples_.clear();
  }
  if (samples_.empty() || t > samples_.back().t) {
    samples_.push_back({t, out->position.head<2>()});
    while (samples_.front().t < t - kWindow) {
      samples_.pop_front();
    }
  }
  if (const std::optional<Eigen::Vector2d> v = fittedVelocity(t)) {
    out->velocity = Eigen::Vector3d(v->x(), v->y(), 0.0);
  }
  return out;
}

std::optional<Eigen::Vector2d> OdometryTrack::fittedVelocity(double now) const {
  // Least squares p(t) = a + v (t - t_mean): v = sum((t - t_mean) p) / sum((t - t_mean)^2).
  double t_sum = 0.0;
  int n = 0;
  for (const Sample& s : samples_) {
    if (s.t >= now - kWindow && s.t <= now) {
      t_sum += s.t;
      ++n;
    }
  }
  if (n < kMinSamples) {
    return std::nullopt;
  }
  const double t_mean = t_sum / n;
  double tt = 0.0;
  double first = now;
  double last = now - kWindow;
  Eigen::Vector2d tp = Eigen::Vector2d::Zero();
  for (const Sample& s : samples_) {
    if (s.t >= now - kWindow && s.t <= now) {
      const double dt = s.t - t_mean;
      tt += dt * dt;
      tp += dt * s.p;
      first = std::min(first, s.t);
      last = std::max(last, s.t);
    }
  }
  if (last - first < kMinSpanFraction * kWindow || !(tt > 0.0)) {
    return std::nullopt;
  }
  return Eigen::Vector2d(tp / tt);
}

}  // namespace estimation
}  // namespace radio_follow
