// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/control/target_motion.hpp"

#include <algorithm>
#include <cmath>

namespace radio_follow {
namespace control {

void TargetMotion::add(double t, const Eigen::Vector2d& position) {
  if (!std::isfinite(t) || !position.allFinite() || (!samples_.empty() && t <= samples_.back().t)) {
    return;
  }
  samples_.push_back({t, position});
  while (!samples_.empty() && samples_.front().t < t - config_.window) {
    samples_.pop_front();
  }
}

std::optional<Eigen::Vector2d> TargetMotion::velocity(double now) const {
  // Least squares p(t) = a + v (t - t_mean): v = sum((t - t_mean) p) / sum((t - t_mean)^2).
  double t_sum = 0.0;
  int n = 0;
  for (const Sample& s : samples_) {
    if (s.t >= now - config_.window && s.t <= now) {
      t_sum += s.t;
      ++n;
    }
  }
  if (n < config_.min_samples) {
    return std::nullopt;
  }
  const double t_mean = t_sum / n;
  double tt = 0.0;
  double first = now;
  double last = now - config_.window;
  Eigen::Vector2d tp = Eigen::Vector2d::Zero();
  for (const Sample& s : samples_) {
    if (s.t >= now - config_.window && s.t <= now) {
      const double dt = s.t - t_mean;
      tt += dt * dt;
      tp += dt * s.p;
      first = std::min(first, s.t);
      last = std::max(last, s.t);
    }
  }
  if (last - first < config_.min_span_fraction * config_.window || !(tt > 0.0)) {
    return std::nullopt;
  }
  return Eigen::Vector2d(tp / tt);
}

void TargetTrack::add(double t, const Eigen::Vector2d& robot, const Eigen::Vector2d& target) {
  robot_ = robot;
  target_ = target;
  motion_.add(t, target);
}

std::optional<double> TargetTrack::speed(double now) const {
  const std::optional<Eigen::Vector2d> v = motion_.velocity(now);
  if (!v) {
    return std::nullopt;
  }
  return v->norm();
}

std::optional<double> TargetTrack::recedingSpeed(double now) const {
  const std::optional<Eigen::Vector2d> v = motion_.velocity(now);
  const Eigen::Vector2d line = target_ - robot_;
  if (!v || !(line.norm() > 1e-6)) {
    return std::nullopt;
  }
  return v->dot(line.normalized());
}

}  // namespace control
}  // namespace radio_follow
