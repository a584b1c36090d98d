// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/estimation/correlated_error.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>

namespace radio_follow {
namespace estimation {
namespace {

/// Eigenvalues of J below this share of the largest are unobserved directions.
constexpr double kRankTolerance = 1e-9;
/// Gradients this short (a target on top of a sensor) carry no direction.
constexpr double kMinDistance = 1e-6;

}  // namespace

Eigen::Matrix3d correlatedErrorCovariance(const std::vector<InformingSensor>& sensors) {
  Eigen::Matrix3d information = Eigen::Matrix3d::Zero();
  Eigen::Matrix3d meat = Eigen::Matrix3d::Zero();
  for (const InformingSensor& s : sensors) {
    if (!(s.white_sigma > 0.0) || !s.gradient.allFinite()) {
      continue;
    }
    const double w = 1.0 / (s.white_sigma * s.white_sigma);
    const Eigen::Matrix3d outer = s.gradient * s.gradient.transpose();
    information += w * outer;
    meat += w * w * s.bias_sigma * s.bias_sigma * outer;
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(information);
  const Eigen::Vector3d values = eigen.eigenvalues();
  const double largest = values.maxCoeff();
  if (!(largest > 0.0)) {
    return Eigen::Matrix3d::Zero();
  }
  Eigen::Vector3d inverse = Eigen::Vector3d::Zero();
  for (int i = 0; i < 3; ++i) {
    if (values(i) > kRankTolerance * largest) {
      inverse(i) = 1.0 / values(i);
    }
  }
  const Eigen::Matrix3d pseudo_inverse =
      eigen.eigenvectors() * inverse.asDiagonal() * eigen.eigenvectors().transpose();
  const Eigen::Matrix3d p = pseudo_inverse * meat * pseudo_inverse;
  return 0.5 * (p + p.transpose());
}

Eigen::Vector3d rangeGradient(const Eigen::Vector3d& sensor, const Eigen::Vector3d& target,
                              bool planar) {
  const Eigen::Vector3d d = target - sensor;
  const double range = d.norm();
  if (range < kMinDistance) {
    return Eigen::Vector3d::Zero();
  }
  Eigen::Vector3d g = d / range;
  if (planar) {
    g.z() = 0.0;  // the height is not a state
  }
  return g;
}

Eigen::Vector3d azimuthGradient(const Eigen::Vector3d& sensor, const Eigen::Vector3d& target) {
  const Eigen::Vector2d d = (target - sensor).head<2>();
  const double squared = d.squaredNorm();
  if (squared < kMinDistance * kMinDistance) {
    return Eigen::Vector3d::Zero();
  }
  return Eigen::Vector3d(-d.y() / squared, d.x() / squared, 0.0);
}

}  // namespace estimation
}  // namespace radio_follow
