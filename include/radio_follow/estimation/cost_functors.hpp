// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <ceres/ceres.h>

#include "radio_follow/estimation/measurement_models.hpp"

namespace radio_follow {
namespace estimation {

// Two implementations of every residual: analytic cost functions (used by the solver,
// about three times cheaper to evaluate) and templated functors for ceres::AutoDiff
// (the reference the analytic Jacobians are tested against). Both take one parameter
// block: the target position [x, y, z] in the fixed frame.

/// Analytic (||p - m|| - r) / sigma.
class RangeCost final : public ceres::SizedCostFunction<1, 3> {
 public:
  explicit RangeCost(const RangeObservation& z) : z_(z) {}
  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override {
    const Eigen::Map<const Eigen::Vector3d> p(parameters[0]);
    Eigen::RowVector3d j;
    residuals[0] = rangeResidual(z_, p, jacobians != nullptr ? &j : nullptr);
    if (jacobians != nullptr && jacobians[0] != nullptr) {
      Eigen::Map<Eigen::RowVector3d> out(jacobians[0]);
      out = j;
    }
    return true;
  }

 private:
  RangeObservation z_;
};

/// Analytic (||p - a|| - ||p - b|| - d) / sigma.
class TdoaCost final : public ceres::SizedCostFunction<1, 3> {
 public:
  explicit TdoaCost(const TdoaObservation& z) : z_(z) {}
  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override {
    const Eigen::Map<const Eigen::Vector3d> p(parameters[0]);
    Eigen::RowVector3d j;
    residuals[0] = tdoaResidual(z_, p, jacobians != nullptr ? &j : nullptr);
    if (jacobians != nullptr && jacobians[0] != nullptr) {
      Eigen::Map<Eigen::RowVector3d> out(jacobians[0]);
      out = j;
    }
    return true;
  }

 private:
  TdoaObservation z_;
};

/// Analytic wrapped (azimuth, elevation) residual in the board frame.
class BearingCost final : public ceres::SizedCostFunction<2, 3> {
 public:
  explicit BearingCost(const BearingObservation& z) : z_(z) {}
  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override {
    const Eigen::Map<const Eigen::Vector3d> p(parameters[0]);
    Eigen::Matrix<double, 2, 3> j;
    Eigen::Map<Eigen::Vector2d> r(residuals);
    r = bearingResidual(z_, p, jacobians != nullptr ? &j : nullptr);
    if (jacobians != nullptr && jacobians[0] != nullptr) {
      Eigen::Map<Eigen::Matrix<double, 2, 3, Eigen::RowMajor>> out(jacobians[0]);
      out = j;
    }
    return true;
  }

 private:
  BearingObservation z_;
};

/// Autodiff reference for RangeCost.
struct RangeFunctor {
  explicit RangeFunctor(const RangeObservation& z) : z_(z) {}
  template <typename T>
  bool operator()(const T* p, T* residual) const {
    using std::sqrt;
    T sq = T(0.0);
    for (int i = 0; i < 3; ++i) {
      const T d = p[i] - T(z_.module[i]);
      sq += d * d;
    }
    residual[0] = (sqrt(sq) - T(z_.range)) / T(z_.sigma);
    return true;
  }
  RangeObservation z_;
};

/// Autodiff reference for TdoaCost.
struct TdoaFunctor {
  explicit TdoaFunctor(const TdoaObservation& z) : z_(z) {}
  template <typename T>
  bool operator()(const T* p, T* residual) const {
    using std::sqrt;
    T sa = T(0.0);
    T sb = T(0.0);
    for (int i = 0; i < 3; ++i) {
      const T da = p[i] - T(z_.anchor_a[i]);
      const T db = p[i] - T(z_.anchor_b[i]);
      sa += da * da;
      sb += db * db;
    }
    residual[0] = (sqrt(sa) - sqrt(sb) - T(z_.difference)) / T(z_.sigma);
    return true;
  }
  TdoaObservation z_;
};

/// Autodiff reference for BearingCost.
struct BearingFunctor {
  explicit BearingFunctor(const BearingObservation& z) : z_(z) {}
  template <typename T>
  bool operator()(const T* p, T* residual) const {
    using std::atan2;
    using std::sqrt;
    T v[3];
    for (int k = 0; k < 3; ++k) {
      v[k] = T(0.0);
      for (int i = 0; i < 3; ++i) {
        v[k] += T(z_.rotation(i, k)) * (p[i] - T(z_.board[i]));
      }
    }
    residual[0] = wrapAngle(atan2(v[1], v[0]) - T(z_.azimuth)) / T(z_.sigma_azimuth);
    residual[1] = z_.use_elevation
                      ? wrapAngle(atan2(v[2], sqrt(v[0] * v[0] + v[1] * v[1])) - T(z_.elevation)) /
                            T(z_.sigma_elevation)
                      : T(0.0);
    return true;
  }
  BearingObservation z_;
};

}  // namespace estimation
}  // namespace radio_follow
