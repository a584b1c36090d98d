// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <memory>
#include <optional>
#include <variant>

#include "radio_follow/estimation/aoa_selector.hpp"
#include "radio_follow/estimation/initializer.hpp"
#include "radio_follow/estimation/kalman_filter.hpp"
#include "radio_follow/estimation/position_estimator.hpp"
#include "radio_follow/estimation/position_solver.hpp"

namespace radio_follow {
namespace estimation {

/// The solver estimator's tuning. Made by LocatorConfig::solverEstimator() from the
/// locator's parameters, which hold every default (the zeros below are none).
struct SolverEstimatorConfig {
  SolverConfig solver;  ///< also the mode (planar) and the planar height
  KalmanConfig kalman;
  InitializerConfig initializer;
  AoaSelectorConfig aoa;
  /// The bearings' sigmas, rad, and whether their elevations count.
  double azimuth_sigma = 0.0;
  double elevation_sigma = 0.0;
  bool use_elevation = true;
  /// OK while the worst axis's sigma is within the larger of these: m, and a fraction of
  /// the distance.
  double max_position_sigma = 0.0;
  double max_relative_sigma = 0.0;
  /// The mirror test's margin, 0.5 chi-square units; 0: no test.
  double ambiguity_margin = 0.0;
  /// The filter's measurement noise: the solver's covariance, else measurement_noise * I
  /// (m^2).
  bool filter_uses_solver_covariance = true;
  double measurement_noise = 0.0;
};

/// Estimator::kSolver: per update, the boards that may speak (AoaSelector), a Ceres solve
/// of the newest measurement of each sensor (warm, cold or multi-start), the mirror test,
/// and a Kalman filter in the robot frame.
class SolverEstimator : public PositionEstimator {
 public:
  SolverEstimator(std::size_t board_count, const SolverEstimatorConfig& config);

  /// Measurements are read from the Locator's fresh lists at each update: nothing to do.
  void add(const TrackedMeasurement& /*m*/) override {}
  /// A bearing's RSSI: the board selection's history.
  void record(const TrackedMeasurement& m) override {
    if (const auto* bearing = std::get_if<BearingReading>(&m.reading)) {
      selector_.recordRssi(bearing->board, bearing->rssi);
    }
  }
  LocatorEstimate estimate(double now, const FreshMeasurements& fresh, LocatorEstimate partial,
                           LocatorStats& stats) override;
  /// Forgets the filter's track, the warm start and the mirror test's side; keeps the
  /// board selection's RSSI history and votes.
  void reset() override;
  /// New validated tuning of the same mode. Rebuilds the solver (it owns the losses); a
  /// change of the AoA selection settings restarts the selection's RSSI history. False
  /// when the filter restarted (motion_model). May throw (the solver's losses) before
  /// changing anything.
  bool setConfig(const SolverEstimatorConfig& config);

  const KalmanFilter& filter() const { return filter_; }

 private:
  LocatorEstimate lose(LocatorEstimate estimate, LocatorStats& stats);
  /// The mirror test (LocatorConfig::ambiguity_margin): true when `solution` may as well
  /// be its mirror image. Updates the run of epochs that preferred this side.
  bool mirrorAmbiguous(const ObservationSet& obs, const SolveResult& solution, double sigma);
  void forgetSide();

  std::size_t board_count_;
  SolverEstimatorConfig config_;
  std::unique_ptr<PositionSolver> solver_;  // rebuilt by setConfig (it owns the losses)
  AoaSelector selector_;
  KalmanFilter filter_;
  /// Last solution, and whether it had a range (a heading-only one does not tell where
  /// along the bearing the target is, so it cannot warm-start a ranged solve).
  std::optional<Eigen::Vector3d> warm_;
  bool warm_ranged_ = false;
  /// Mirror test: epochs in a row whose data preferred the tracked side, and whether the
  /// track has been confirmed so since it started.
  int side_votes_ = 0;
  bool side_confirmed_ = false;
};

}  // namespace estimation
}  // namespace radio_follow
