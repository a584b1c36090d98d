// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/control/homing.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "radio_follow/common/angles.hpp"
#include "radio_follow/common/param_error.hpp"

namespace radio_follow {
namespace control {

VectorEstimator::VectorEstimator(double tau, std::size_t window) : tau_(tau), window_(window) {}

Eigen::Vector2d VectorEstimator::rawGoal(const Eigen::Vector2d& robot, double bearing,
                                         double distance) {
  return robot + distance * Eigen::Vector2d(std::cos(bearing), std::sin(bearing));
}

bool VectorEstimator::isOutlier(const Eigen::Vector2d& raw, double z_threshold) const {
  if (goals_.size() < 3) {
    return false;
  }
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  for (const auto& g : goals_) {
    mean += g;
  }
  mean /= static_cast<double>(goals_.size());
  Eigen::Vector2d var = Eigen::Vector2d::Zero();
  for (const auto& g : goals_) {
    var += (g - mean).cwiseAbs2();
  }
  var /= static_cast<double>(goals_.size() - 1);
  for (int axis = 0; axis < 2; ++axis) {
    const double sd = std::sqrt(var[axis]);
    const double dev = std::abs(raw[axis] - mean[axis]);
    // Identical history (sd = 0): anything off it by more than a millimetre is new.
    if (sd < 1e-9 ? dev > 1e-3 : dev / sd > z_threshold) {
      return true;
    }
  }
  return false;
}

void VectorEstimator::add(const Eigen::Vector2d& raw) {
  if (!raw.allFinite()) {
    return;
  }
  goals_.push_front(raw);
  while (goals_.size() > window_) {
    goals_.pop_back();
  }
}

std::optional<Eigen::Vector2d> VectorEstimator::estimate() const {
  if (goals_.empty()) {
    return std::nullopt;
  }
  Eigen::Vector2d sum = Eigen::Vector2d::Zero();
  double weights = 0.0;
  for (std::size_t i = 0; i < goals_.size(); ++i) {
    const double w = std::exp(-static_cast<double>(i) / tau_);
    sum += w * goals_[i];
    weights += w;
  }
  return Eigen::Vector2d(sum / weights);
}

ParallaxEstimator::ParallaxEstimator(double k, double min_baseline, double min_angle)
    : k_(k), min_baseline_(min_baseline), min_angle_(min_angle) {}

std::optional<Eigen::Vector2d> ParallaxEstimator::intersect(const Eigen::Vector2d& r1, double b1,
                                                            const Eigen::Vector2d& r2, double b2,
                                                            double min_angle) {
  const double crossing = std::sin(b2 - b1);
  if (std::abs(crossing) < std::sin(min_angle)) {
    return std::nullopt;
  }
  const Eigen::Vector2d dr = r2 - r1;
  const double baseline = dr.norm();  // eq 9
  const double heading = std::atan2(dr.y(), dr.x());
  const double d1 = -baseline * std::sin(heading - b2) / crossing;  // eq 8
  if (!(d1 > 0.0)) {
    return std::nullopt;
  }
  return VectorEstimator::rawGoal(r1, b1, d1);  // eqs 6-7
}

Eigen::Vector2d ParallaxEstimator::kohonenStep(const Eigen::Vector2d& old_goal,
                                               const Eigen::Vector2d& robot, double bearing,
                                               double k) {
  const Eigen::Vector2d rel = old_goal - robot;
  const double d_o = rel.norm();                                                       // eq 13
  const double d_e = d_o * std::sin(std::atan2(rel.y(), rel.x()) - bearing);           // eq 12
  return old_goal + k * d_e * Eigen::Vector2d(std::sin(bearing), -std::cos(bearing));  // 10-11
}

std::optional<Eigen::Vector2d> ParallaxEstimator::update(const Eigen::Vector2d& robot,
                                                         double bearing) {
  if (goal_) {
    goal_ = kohonenStep(*goal_, robot, bearing, k_);
    return goal_;
  }
  if (!first_) {
    first_ = std::make_pair(robot, bearing);
    return std::nullopt;
  }
  if ((robot - first_->first).norm() < min_baseline_) {
    return std::nullopt;
  }
  // Nearly parallel rays: keep the first reading and wait for more parallax.
  if (std::abs(std::sin(bearing - first_->second)) < std::sin(min_angle_)) {
    return std::nullopt;
  }
  goal_ = intersect(first_->first, first_->second, robot, bearing, min_angle_);
  // Rays that meet behind the first position mean one reading was wrong: start over
  // from this one instead of keeping a bad anchor forever.
  if (!goal_) {
    first_ = std::make_pair(robot, bearing);
  }
  return goal_;
}

void HomingParams::validate() const {
  const auto positive = [](double v) { return std::isfinite(v) && v > 0.0; };
  require(goal_estimator == "all_readings" || goal_estimator == "seed000", "~goal_estimator",
          goal_estimator, "all_readings or seed000");
  require(positive(tau), "~tau", tau, "a decay > 0 in readings");
  require(window >= 3, "~window", window, "a count >= 3");
  require(k > 0.0 && k <= 1.0, "~kohonen_k", k, "a step in (0, 1]");
  require(positive(min_baseline), "~min_baseline", min_baseline, "a distance > 0 in metres");
  require(min_parallax_angle > 0.0 && min_parallax_angle < kPi / 2.0, "~min_parallax_angle",
          min_parallax_angle, "an angle in (0, pi/2) rad");
  require(positive(error_threshold), "~error_threshold", error_threshold, "a ratio > 0");
  require(range_step >= 0.0 && range_step <= 1.0, "~range_step", range_step, "a step in [0, 1]");
  require(positive(z_threshold), "~z_threshold", z_threshold, "a z value > 0");
  require(positive(arrival_distance), "~arrival_distance", arrival_distance, "metres > 0");
  require(positive(agreement_distance), "~agreement_distance", agreement_distance, "metres > 0");
  require(positive(max_linear), "~max_linear", max_linear, "a speed > 0 in m/s");
  require(positive(linear_gain), "~linear_gain", linear_gain, "a gain > 0 in 1/s");
  require(positive(angular_gain), "~angular_gain", angular_gain, "a gain > 0 in 1/s");
  require(positive(max_angular), "~max_angular", max_angular, "a yaw rate > 0 in rad/s");
}

Eigen::Vector2d rangeStep(const Eigen::Vector2d& goal, const Eigen::Vector2d& robot,
                          double distance, double k) {
  const Eigen::Vector2d rel = goal - robot;
  const double d_p = rel.norm();
  if (!(d_p > 1e-9) || !std::isfinite(distance)) {
    return goal;  // on the robot: no line of sight to step along
  }
  return robot + rel * (1.0 + k * (distance - d_p) / d_p);
}

double distanceAlongBearing(const Eigen::Vector2d& sensor, double bearing,
                            const Eigen::Vector2d& origin, double height_difference, double range) {
  if (!std::isfinite(range) || range < 0.0) {
    return std::numeric_limits<double>::quiet_NaN();
  }
  // Horizontal radius of the range sphere at the target's height.
  const double radius =
      std::sqrt(std::max(0.0, range * range - height_difference * height_difference));
  const Eigen::Vector2d u(std::cos(bearing), std::sin(bearing));
  const Eigen::Vector2d offset = sensor - origin;
  // |offset + t u| = radius: t^2 + 2 b t + |offset|^2 - radius^2 = 0.
  const double b = offset.dot(u);
  const double disc = b * b - offset.squaredNorm() + radius * radius;
  // A circle that does not reach the ray (a short range): the ray's closest point to it.
  const double t = disc > 0.0 ? -b + std::sqrt(disc) : -b;
  return std::max(0.0, t);
}

HybridHoming::HybridHoming(const HomingParams& params)
    : params_(params),
      vector_(params.tau, static_cast<std::size_t>(params.window)),
      parallax_(params.k, params.min_baseline, params.min_parallax_angle) {}

double homingErrorMetric(const Eigen::Vector2d& parallax, const Eigen::Vector2d& vector,
                         const Eigen::Vector2d& robot) {
  const double mean_distance = 0.5 * ((parallax - robot).norm() + (vector - robot).norm());
  if (!(mean_distance > 1e-9)) {
    return 0.0;
  }
  return (parallax - vector).norm() / mean_distance;
}

void HybridHoming::update(const Eigen::Vector2d& robot, double bearing, double distance) {
  if (!robot.allFinite() || !std::isfinite(bearing)) {
    ++refused_;  // one NaN would stay in the parallax estimate and every goal after it
    return;
  }
  updateHybrid(robot, bearing, distance);
  if (params_.goal_estimator != "all_readings") {
    return;
  }
  const bool has_distance = std::isfinite(distance) && distance >= 0.0;
  all_readings_.add(robot, bearing,
                    has_distance ? distance : std::numeric_limits<double>::quiet_NaN());
  if (!goal_) {
    return;
  }
  // The previous fit is the best start; the hybrid goal gives the first one.
  const auto fit = all_readings_.solve(fit_ ? *fit_ : *goal_);
  if (fit) {
    fit_ = fit;
  }
  if (fit_) {
    goal_ = fit_;
    source_ = HomingSource::kAllReadings;
  }
}

void HybridHoming::updateHybrid(const Eigen::Vector2d& robot, double bearing, double distance) {
  bool vector_outlier = true;
  // A zero distance is a reading like any other (the target at the sensor): a sensor that
  // reports at least zero turns every short reading into one, and dropping them would
  // leave only the long readings near the target (doc/control/homing.md, "Distance").
  if (std::isfinite(distance) && distance >= 0.0) {
    const Eigen::Vector2d raw = VectorEstimator::rawGoal(robot, bearing, distance);
    vector_outlier = vector_.isOutlier(raw, params_.z_threshold);
    vector_.add(raw);
  }
  auto parallax = parallax_.update(robot, bearing);
  const auto vector = vector_.estimate();
  if (parallax && vector && params_.range_step > 0.0) {
    parallax = rangeStep(*parallax, robot, (*vector - robot).norm(), params_.range_step);
    parallax_.set(*parallax);
  }

  if (!parallax) {
    goal_ = vector;
    source_ = vector ? HomingSource::kVector : HomingSource::kNone;
    return;
  }
  if (!vector || homingErrorMetric(*parallax, *vector, robot) < params_.error_threshold) {
    goal_ = parallax;
    source_ = HomingSource::kParallax;
    return;
  }
  if (!vector_outlier) {
    const Eigen::Vector2d average = 0.5 * (*parallax + *vector);
    parallax_.set(average);
    goal_ = average;
    source_ = HomingSource::kAverage;
    return;
  }
  goal_ = parallax;
  source_ = HomingSource::kParallax;
}

bool HybridHoming::arrived(const Eigen::Vector2d& robot) const {
  if (!goal_ || (*goal_ - robot).norm() >= params_.arrival_distance) {
    return false;
  }
  const auto vector = vector_.estimate();
  const auto& parallax = source_ == HomingSource::kAllReadings ? goal_ : parallax_.goal();
  // Bearings only (no distance ever): nothing to cross-check the parallax goal with,
  // and refusing to arrive would leave the robot circling the goal.
  if (!vector) {
    return parallax.has_value();
  }
  if (!parallax) {
    return false;
  }
  return (*vector - *parallax).norm() < params_.agreement_distance;
}

VelocityCommand homingVelocity(const Pose2& robot, const Eigen::Vector2d& goal,
                               const HomingParams& params) {
  const Eigen::Vector2d delta = goal - robot.position();
  const double distance = delta.norm();
  const double theta = wrapAngle(std::atan2(delta.y(), delta.x()) - robot.yaw);
  VelocityCommand cmd;
  const double v = std::min(params.max_linear, params.linear_gain * distance);
  cmd.linear = std::abs(theta) >= kPi / 2.0 ? 0.0 : (2.0 / kPi) * v * (kPi / 2.0 - std::abs(theta));
  cmd.angular = std::clamp(params.angular_gain * theta, -params.max_angular, params.max_angular);
  return cmd;
}

}  // namespace control
}  // namespace radio_follow
