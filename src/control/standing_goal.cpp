// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/control/standing_goal.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <vector>

#include "radio_follow/common/angles.hpp"
#include "radio_follow/common/median.hpp"

namespace radio_follow {
namespace control {

namespace {

constexpr int kIterations = 30;
constexpr double kConverged = 1e-4;  ///< m, a step this small ends the fit
/// A bearing taken this close to the goal has no direction worth fitting, m.
constexpr double kNearSensor = 0.05;
/// Floors of the estimated scales: readings that agree to better than this (a few
/// identical readings) must not get an infinite weight.
constexpr double kMinBearingScale = deg2rad(0.5);
constexpr double kMinDistanceScale = 0.01;  ///< m
/// Huber's constant: 95 % efficiency on Gaussian errors.
constexpr double kHuber = 1.345;
/// The median absolute deviation of a Gaussian, in sigmas.
constexpr double kMadToSigma = 1.4826;
/// One Gauss-Newton step moves the goal at most this far, m (a fit from a poor guess
/// must not jump past the sensors).
constexpr double kMaxStep = 2.0;

/// The distance error's scale as a function of the distance read, sigma(d)^2 = a^2 +
/// (b d)^2: a UWB range errs by about the same at every distance, an RSSI-derived one in
/// proportion to it (a log-normal path loss), and the readings tell which. Fitted to the
/// squared residuals (each clipped at 3 of its previous scales, so a reflection does not
/// set it) by least squares in a^2 and b^2, which stay >= 0.
struct DistanceScale {
  double a2 = 0.25;  ///< m^2; the first censored means use it
  double b2 = 0.0;

  double at(double d) const { return std::sqrt(a2 + b2 * d * d); }

  void fit(const std::vector<double>& distances, const std::vector<double>& residuals) {
    double s11 = 0.0, s1x = 0.0, sxx = 0.0, sy = 0.0, sxy = 0.0;
    for (std::size_t i = 0; i < distances.size(); ++i) {
      const double x = distances[i] * distances[i];
      const double clip = 3.0 * at(distances[i]);
      const double e = std::min(std::abs(residuals[i]), clip);
      s11 += 1.0;
      s1x += x;
      sxx += x * x;
      sy += e * e;
      sxy += x * e * e;
    }
    const double det = s11 * sxx - s1x * s1x;
    double a2_new = sy / s11;
    double b2_new = 0.0;
    if (det > 1e-12 * s11 * sxx) {
      a2_new = (sxx * sy - s1x * sxy) / det;
      b2_new = (s11 * sxy - s1x * sy) / det;
      if (a2_new < 0.0) {  // all relative: b^2 alone
        a2_new = 0.0;
        b2_new = sxy / sxx;
      } else if (b2_new < 0.0) {  // all absolute: a^2 alone
        a2_new = sy / s11;
        b2_new = 0.0;
      }
    }
    const double floor2 = kMinDistanceScale * kMinDistanceScale;
    a2 = std::max(a2_new, floor2);
    b2 = std::max(b2_new, 0.0);
  }
};

double huberWeight(double residual, double scale) {
  const double z = std::abs(residual) / scale;
  return z <= kHuber ? 1.0 : kHuber / z;
}

/// E[x | x <= 0] for x ~ N(mean, scale^2): what a reading reported as zero stands for.
double censoredMean(double mean, double scale) {
  const double a = -mean / scale;
  const double cdf = 0.5 * std::erfc(-a / std::sqrt(2.0));
  const double pdf = std::exp(-0.5 * a * a) / std::sqrt(2.0 * kPi);
  // Far in the tail the ratio pdf / cdf tends to -a (Mills' ratio).
  const double ratio = cdf > 1e-300 ? pdf / cdf : -a;
  return mean - scale * ratio;
}

}  // namespace

bool StandingGoalEstimator::add(const Eigen::Vector2d& sensor, double bearing, double distance) {
  if (!sensor.allFinite() || !std::isfinite(bearing) || distance < 0.0 ||
      std::isinf(distance)) {
    return false;
  }
  readings_.push_back({sensor, bearing, distance});
  if (readings_.size() > kMaxReadings) {
    readings_.pop_front();
  }
  return true;
}

std::optional<Eigen::Vector2d> StandingGoalEstimator::solve(const Eigen::Vector2d& guess) const {
  if (readings_.size() < kMinReadings || !guess.allFinite()) {
    return std::nullopt;
  }
  const std::size_t n = readings_.size();
  std::vector<double> bearing_res(n), distance_res(n);
  std::vector<Eigen::Vector2d> bearing_jac(n), distance_jac(n);
  std::vector<double> rho(n);  ///< the goal's distance from each reading's sensor
  std::vector<bool> has_bearing(n), has_distance(n);
  std::vector<double> abs_b, uncensored_rho, uncensored_res;
  abs_b.reserve(n);
  uncensored_rho.reserve(n);
  uncensored_res.reserve(n);

  Eigen::Vector2d goal = guess;
  double bearing_scale = kMinBearingScale;
  DistanceScale distance_scale;
  Eigen::Matrix2d info = Eigen::Matrix2d::Zero();
  for (int iteration = 0; iteration < kIterations; ++iteration) {
    abs_b.clear();
    uncensored_rho.clear();
    uncensored_res.clear();
    for (std::size_t i = 0; i < n; ++i) {
      const Reading& r = readings_[i];
      const Eigen::Vector2d delta = goal - r.sensor;
      rho[i] = delta.norm();
      has_bearing[i] = rho[i] > kNearSensor;
      if (has_bearing[i]) {
        bearing_res[i] = wrapAngleFast(std::atan2(delta.y(), delta.x()) - r.bearing);
        bearing_jac[i] = Eigen::Vector2d(-delta.y(), delta.x()) / (rho[i] * rho[i]);
        abs_b.push_back(std::abs(bearing_res[i]));
      }
      has_distance[i] = std::isfinite(r.distance) && rho[i] > 1e-9;
      if (has_distance[i]) {
        const bool censored = r.distance <= 0.0;
        const double reading =
            censored ? censoredMean(rho[i], distance_scale.at(rho[i])) : r.distance;
        distance_res[i] = rho[i] - reading;
        distance_jac[i] = delta / rho[i];
        if (!censored) {
          uncensored_rho.push_back(rho[i]);
          uncensored_res.push_back(distance_res[i]);
        }
      }
    }
    if (!abs_b.empty()) {
      bearing_scale = std::max(kMinBearingScale, kMadToSigma * median(abs_b));
    }
    if (!uncensored_rho.empty()) {
      distance_scale.fit(uncensored_rho, uncensored_res);
    }
    info.setZero();
    Eigen::Vector2d gradient = Eigen::Vector2d::Zero();
    for (std::size_t i = 0; i < n; ++i) {
      if (has_bearing[i]) {
        const double w = huberWeight(bearing_res[i], bearing_scale) /
                         (bearing_scale * bearing_scale);
        info += w * bearing_jac[i] * bearing_jac[i].transpose();
        gradient += w * bearing_res[i] * bearing_jac[i];
      }
      if (has_distance[i]) {
        // At the goal's distance, not the reading's: a reading's own error must not set
        // its weight (short readings would count more, and pull the goal short).
        const double scale = distance_scale.at(rho[i]);
        const double w = huberWeight(distance_res[i], scale) / (scale * scale);
        info += w * distance_jac[i] * distance_jac[i].transpose();
        gradient += w * distance_res[i] * distance_jac[i];
      }
    }
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eigen(info);
    if (!(eigen.eigenvalues()(0) > 1e-9 * eigen.eigenvalues()(1))) {
      return std::nullopt;  // the readings fix one direction only
    }
    Eigen::Vector2d step = -info.ldlt().solve(gradient);
    if (step.norm() > kMaxStep) {
      step *= kMaxStep / step.norm();
    }
    goal += step;
    if (!goal.allFinite()) {
      return std::nullopt;
    }
    if (step.norm() < kConverged) {
      break;
    }
  }
  // A goal fixed to no better than half its distance along its weakest direction is
  // no goal: bearings along nearly one line, no distance.
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eigen(info);
  const double weakest_sigma = 1.0 / std::sqrt(eigen.eigenvalues()(0));
  const double distance = (goal - readings_.back().sensor).norm();
  if (!(weakest_sigma <= std::max(1.0, 0.5 * distance))) {
    return std::nullopt;
  }
  return goal;
}

}  // namespace control
}  // namespace radio_follow
