// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cmath>
#include <vector>

#include "radio_follow/common/angles.hpp"

namespace radio_follow {
namespace estimation {

/// A two-way range from a module on the robot to the target, already calibrated.
struct RangeObservation {
  Eigen::Vector3d module = Eigen::Vector3d::Zero();  ///< module position, fixed frame, m
  double range = 0.0;                                ///< measured range, m
  double sigma = 0.03;                               ///< standard deviation, m
};

/// A TDoA distance difference |p - a| - |p - b|.
struct TdoaObservation {
  Eigen::Vector3d anchor_a = Eigen::Vector3d::Zero();  ///< fixed frame, m
  Eigen::Vector3d anchor_b = Eigen::Vector3d::Zero();  ///< fixed frame, m
  double difference = 0.0;                             ///< m
  double sigma = 0.1;                                  ///< m
};

/// An angle-of-arrival bearing measured by one board, in that board's frame.
struct BearingObservation {
  Eigen::Vector3d board = Eigen::Vector3d::Zero();  ///< board position, fixed frame, m
  /// Rotation board -> fixed frame (columns are the board axes in the fixed frame).
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  double azimuth = 0.0;    ///< rad, CCW about board z, 0 = boresight
  double elevation = 0.0;  ///< rad, towards board +z
  double sigma_azimuth = 0.035;
  double sigma_elevation = 0.087;
  bool use_elevation = true;  ///< false: the elevation residual is always zero
};

/// Distance assumed along a bearing when no range exists, m: the one default of the
/// locator's `default_range` (initializer, particle tracker).
constexpr double kDefaultRange = 3.0;

/// Everything one solve uses.
struct ObservationSet {
  std::vector<RangeObservation> ranges;
  std::vector<TdoaObservation> tdoas;
  std::vector<BearingObservation> bearings;

  bool empty() const { return ranges.empty() && tdoas.empty() && bearings.empty(); }
  void clear() {
    ranges.clear();
    tdoas.clear();
    bearings.clear();
  }
};

// The analytic models below are shared by the Ceres cost functions (residual and
// Jacobian), the Fisher information (Jacobian only) and the simulators (prediction).
// Residuals are whitened; Jacobians are with respect to the target position p.

/// Predicted range and its unit gradient; a zero-length difference gets a zero gradient
/// (the range has no derivative there, and any unit vector would bias the step).
inline double predictRange(const Eigen::Vector3d& p, const Eigen::Vector3d& module,
                           Eigen::RowVector3d* gradient) {
  const Eigen::Vector3d d = p - module;
  const double r = d.norm();
  if (gradient != nullptr) {
    *gradient = r > 1e-12 ? Eigen::RowVector3d(d.transpose() / r) : Eigen::RowVector3d::Zero();
  }
  return r;
}

inline double rangeResidual(const RangeObservation& z, const Eigen::Vector3d& p,
                            Eigen::RowVector3d* jacobian) {
  const double r = predictRange(p, z.module, jacobian);
  if (jacobian != nullptr) {
    *jacobian /= z.sigma;
  }
  return (r - z.range) / z.sigma;
}

inline double tdoaResidual(const TdoaObservation& z, const Eigen::Vector3d& p,
                           Eigen::RowVector3d* jacobian) {
  Eigen::RowVector3d ga;
  Eigen::RowVector3d gb;
  const double ra = predictRange(p, z.anchor_a, jacobian != nullptr ? &ga : nullptr);
  const double rb = predictRange(p, z.anchor_b, jacobian != nullptr ? &gb : nullptr);
  if (jacobian != nullptr) {
    *jacobian = (ga - gb) / z.sigma;
  }
  return (ra - rb - z.difference) / z.sigma;
}

/// Azimuth and elevation of p as seen from a board (board frame), radians.
inline Eigen::Vector2d predictBearing(const Eigen::Vector3d& p, const Eigen::Vector3d& board,
                                      const Eigen::Matrix3d& rotation) {
  const Eigen::Vector3d v = rotation.transpose() * (p - board);
  return {std::atan2(v.y(), v.x()), std::atan2(v.z(), std::hypot(v.x(), v.y()))};
}

/// Whitened, wrapped (azimuth, elevation) residual. Straight above or below the board the
/// azimuth is undefined: its Jacobian row is zero there rather than infinite.
inline Eigen::Vector2d bearingResidual(const BearingObservation& z, const Eigen::Vector3d& p,
                                       Eigen::Matrix<double, 2, 3>* jacobian) {
  const Eigen::Vector3d v = z.rotation.transpose() * (p - z.board);
  const double rho2 = v.x() * v.x() + v.y() * v.y();
  const double rho = std::sqrt(rho2);
  const double n2 = rho2 + v.z() * v.z();
  Eigen::Vector2d residual;
  residual(0) = wrapAngleFast(std::atan2(v.y(), v.x()) - z.azimuth) / z.sigma_azimuth;
  residual(1) = z.use_elevation
                    ? wrapAngleFast(std::atan2(v.z(), rho) - z.elevation) / z.sigma_elevation
                    : 0.0;
  if (jacobian != nullptr) {
    Eigen::Matrix<double, 2, 3> dv = Eigen::Matrix<double, 2, 3>::Zero();
    if (rho2 > 1e-18) {
      dv.row(0) << -v.y() / rho2, v.x() / rho2, 0.0;
      if (z.use_elevation) {
        dv.row(1) << -v.x() * v.z() / (rho * n2), -v.y() * v.z() / (rho * n2), rho / n2;
      }
    }
    dv.row(0) /= z.sigma_azimuth;
    dv.row(1) /= z.sigma_elevation;
    *jacobian = dv * z.rotation.transpose();
  }
  return residual;
}

}  // namespace estimation
}  // namespace radio_follow
