// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <Eigen/Core>
#include <memory>
#include <type_traits>
#include <vector>

#include "radio_follow/config/layout.hpp"
#include "radio_follow/estimation/measurement_models.hpp"

namespace radio_follow {
namespace estimation {

/// Each kind's default loss (its observation type's kDefaultLoss), kindIndex() order.
inline PerObservationKind<LossConfig> defaultLosses() {
  PerObservationKind<LossConfig> losses;
  ObservationSet{}.forEach([&](const auto& list) {
    using Observation = typename std::decay_t<decltype(list)>::value_type;
    losses[kindIndex<Observation>()] = Observation::kDefaultLoss;
  });
  return losses;
}

struct SolverConfig {
  /// 2D mode: z is held at `height` (a Ceres subset manifold), 3D mode: z is free.
  bool planar = true;
  double height = kDefaultTargetHeight;
  /// The robust loss of each kind's residuals (range_loss, tdoa_loss, bearing_loss).
  PerObservationKind<LossConfig> losses = defaultLosses();
  int max_iterations = 25;
  /// Covariance from ceres::Covariance (robust-loss-weighted Jacobian, SVD, rank deficiency
  /// reported) instead of the inverse Fisher information at the solution.
  bool ceres_covariance = false;
  /// Without any range the distance to the target is unobservable; a weak prior on the
  /// distance from the frame origin keeps the normal equations regular so the direction
  /// (the observable part) can be solved. Metres.
  double prior_range = kDefaultRange;
  double prior_range_sigma = 10.0;

  template <typename Observation>
  LossConfig& loss() {
    return losses[kindIndex<Observation>()];
  }
  template <typename Observation>
  const LossConfig& loss() const {
    return losses[kindIndex<Observation>()];
  }
};

struct SolveResult {
  /// The minimiser converged (or stopped at the iteration limit with a finite cost).
  bool success = false;
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  /// 0.5 * sum of robustified squared whitened residuals.
  double cost = 0.0;
  /// Position covariance, m^2 (z row/column zero in 2D mode); valid only if covariance_valid.
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  bool covariance_valid = false;
  int iterations = 0;
};

/// Nonlinear least squares for the target position with Ceres: one residual block per
/// observation (its kind's analytic cost), each with its kind's loss.
/// Stateless between calls; the caller chooses the starting point.
class PositionSolver {
 public:
  explicit PositionSolver(const SolverConfig& config);
  ~PositionSolver();
  PositionSolver(const PositionSolver&) = delete;
  PositionSolver& operator=(const PositionSolver&) = delete;

  /// Solves from a start close to the answer (the last estimate).
  SolveResult solve(const ObservationSet& observations, const Eigen::Vector3d& initial) const;

  /// Solves from a rough start (closed-form guess): first with a convex Huber loss on every
  /// residual, then with the configured losses from there. A redescending loss (Cauchy)
  /// started far away can settle where the residuals it ignores are the good ones.
  SolveResult solveCold(const ObservationSet& observations, const Eigen::Vector3d& initial) const;

  /// Like solve(), without the covariance: where a start leads and at what cost (the
  /// locator's mirror test).
  SolveResult solveCostOnly(const ObservationSet& observations,
                            const Eigen::Vector3d& initial) const;

  /// Convex first stage from every start, the lowest cost wins, then the configured losses
  /// from there (covariance only for the result).
  SolveResult solveMultiStart(const ObservationSet& observations,
                              const std::vector<Eigen::Vector3d>& starts) const;

  const SolverConfig& config() const { return config_; }

 private:
  SolveResult solveOnce(const ObservationSet& observations, const Eigen::Vector3d& initial,
                        bool with_covariance, bool convex_stage) const;
  void computeCovariance(const ObservationSet& observations, SolveResult& result) const;

  struct CeresParts;
  SolverConfig config_;
  std::unique_ptr<CeresParts> parts_;
};

}  // namespace estimation
}  // namespace radio_follow
