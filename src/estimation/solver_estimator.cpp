// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/estimation/solver_estimator.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include "radio_follow/estimation/mirror_axis.hpp"

namespace radio_follow {
namespace estimation {

namespace {

/// A second solution closer than this to the first is the same answer, m.
constexpr double kSameSolutionDistance = 0.5;
/// Epochs in a row that must prefer the tracked side before it counts as confirmed.
constexpr int kSideConfirmEpochs = 5;

/// `p` reflected across the main axis of the ranging modules: the other solution the
/// ranges of nearly collinear modules allow. nullopt with fewer than two.
std::optional<Eigen::Vector3d> mirrorImage(const ObservationSet& obs, const Eigen::Vector3d& p) {
  std::vector<Eigen::Vector3d> modules;
  for (const auto& z : obs.ranges) {
    modules.push_back(z.module);
  }
  const std::optional<MirrorAxis> axis = mirrorAxis(modules);
  return axis ? std::optional<Eigen::Vector3d>(axis->reflect(p)) : std::nullopt;
}

}  // namespace

SolverEstimator::SolverEstimator(std::size_t board_count, const SolverEstimatorConfig& config)
    : board_count_(board_count),
      config_(config),
      solver_(std::make_unique<PositionSolver>(config_.solver)),
      selector_(board_count, config_.aoa),
      filter_(config_.kalman) {}

bool SolverEstimator::setConfig(const SolverEstimatorConfig& config) {
  const bool selection_changed = config.aoa.mode != config_.aoa.mode ||
                                 config.aoa.rssi_window != config_.aoa.rssi_window ||
                                 config.aoa.vote_window != config_.aoa.vote_window;
  auto solver = std::make_unique<PositionSolver>(config.solver);
  // Nothing below throws: the new tuning is applied entirely or not at all.
  config_ = config;
  solver_ = std::move(solver);
  if (selection_changed) {
    selector_ = AoaSelector(board_count_, config_.aoa);
  }
  return filter_.reconfigure(config_.kalman);
}

void SolverEstimator::reset() {
  warm_.reset();
  filter_.reset();
  forgetSide();
}

LocatorEstimate SolverEstimator::lose(LocatorEstimate estimate, LocatorStats& stats) {
  estimate.status = TargetStatus::kLost;
  ++stats.lost;
  warm_.reset();
  filter_.reset();
  selector_.reset();
  forgetSide();
  return estimate;
}

void SolverEstimator::forgetSide() {
  side_votes_ = 0;
  side_confirmed_ = false;
}

bool SolverEstimator::mirrorAmbiguous(const ObservationSet& obs, const SolveResult& solution,
                                      double sigma) {
  if (config_.ambiguity_margin <= 0.0 || !config_.solver.planar) {
    return false;
  }
  if (side_confirmed_ && obs.size() > obs.ranges.size()) {
    // A bearing (or any reading but a range) of a confirmed track: the mirror's residual
    // is tens of sigmas, the test would only repeat what it found. Range-only epochs keep
    // testing, so that a track that drifts onto the wrong side is caught.
    return false;
  }
  const std::optional<Eigen::Vector3d> mirrored = mirrorImage(obs, solution.position);
  if (!mirrored || (*mirrored - solution.position).head<2>().norm() <= kSameSolutionDistance) {
    return false;  // on the modules' axis both sides meet: nothing to tell apart
  }
  // The mirror of a solution is where the ranges of collinear modules fit as well, so a
  // warm solve from there finds the other minimum (no convex stage, no covariance).
  const SolveResult other = solver_->solveCostOnly(obs, *mirrored);
  const double separation = (other.position - solution.position).head<2>().norm();
  const auto vote = [this] {
    side_confirmed_ = side_confirmed_ || ++side_votes_ >= kSideConfirmEpochs;
    return false;
  };
  if (!other.success || !std::isfinite(other.cost)) {
    return false;  // no second answer to compare with: no evidence either way
  }
  if (!(separation > std::max(kSameSolutionDistance, 3.0 * sigma))) {
    return vote();  // the mirror start came back: the data have one solution here
  }
  const double preference = other.cost - solution.cost;  // > 0: the data prefer ours
  if (preference <= -config_.ambiguity_margin) {
    forgetSide();  // the data contradict the tracked side
    return true;
  }
  if (preference >= config_.ambiguity_margin) {
    return vote();
  }
  side_votes_ = 0;
  return !side_confirmed_;
}

LocatorEstimate SolverEstimator::estimate(double now, const FreshMeasurements& fresh,
                                          LocatorEstimate out, LocatorStats& stats) {
  ObservationSet obs = fresh.obs;
  double newest = fresh.newest;
  // Bearings: which boards may speak depends on where the target is believed to be.
  std::optional<Eigen::Vector3d> believed;
  if (warm_ && warm_ranged_) {
    believed = warm_;
  } else {
    believed = trilaterate(obs.ranges, config_.initializer);
  }
  const std::vector<std::size_t> chosen = selector_.select(fresh.boards, believed);
  stats.bearings_rejected_fov += fresh.boards.size() - chosen.size();
  for (std::size_t k : chosen) {
    BearingObservation z;
    z.board = fresh.boards[k].position;
    z.rotation = fresh.boards[k].rotation;
    z.azimuth = fresh.angles[k].x();
    z.elevation = fresh.angles[k].y();
    z.sigma_azimuth = config_.azimuth_sigma;
    z.sigma_elevation = config_.elevation_sigma;
    z.use_elevation = config_.use_elevation;
    obs.bearings.push_back(z);
    out.bearings_used.push_back(fresh.boards[k].board);
    newest = std::max(newest, fresh.bearing_stamps[k]);
  }
  out.sources = obs.sources();
  out.stamp = std::isfinite(newest) ? newest : now;

  // Is the position determined at all by what is fresh? Ranges fix the distance from the
  // robot (and start the solve, trilaterate); every other kind helps them.
  const bool ranged = !obs.ranges.empty();
  const bool helpers = obs.size() > obs.ranges.size();
  const std::size_t full_ranges = config_.solver.planar ? 3 : 4;
  const bool warm_usable = warm_.has_value() && warm_ranged_ == ranged;
  if (obs.empty() || (ranged && !helpers && obs.ranges.size() < full_ranges - 1) ||
      (ranged && !helpers && obs.ranges.size() < full_ranges && !warm_usable)) {
    return lose(out, stats);
  }

  const auto start = std::chrono::steady_clock::now();
  SolveResult result;
  if (warm_usable) {
    result = solver_->solve(obs, *warm_);
  } else if (const auto guess = trilaterate(obs.ranges, config_.initializer)) {
    result = solver_->solveCold(obs, *guess);
  } else {
    result = solver_->solveMultiStart(obs, multiStartCandidates(obs, config_.initializer));
  }
  stats.last_solve_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ++stats.solves;
  if (!result.success || !result.position.allFinite()) {
    ++stats.solver_failures;
    return lose(out, stats);
  }
  out.solver_cost = result.cost;
  warm_ = result.position;
  warm_ranged_ = ranged;

  if (!ranged) {
    // Direction only: the distance is the prior's, so the filter (which would treat it as
    // a position) is left alone; it resumes when ranges return.
    out.status = TargetStatus::kHeadingOnly;
    out.position = result.position;
    out.covariance = result.covariance;
    return out;
  }

  double worst_sigma = std::numeric_limits<double>::infinity();
  if (result.covariance_valid) {
    worst_sigma =
        std::sqrt(std::max(0.0, Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(result.covariance)
                                    .eigenvalues()
                                    .maxCoeff()));
  }
  const bool underdetermined = !helpers && obs.ranges.size() < full_ranges;
  const double allowed_sigma = std::max(
      config_.max_position_sigma, config_.max_relative_sigma * result.position.head<2>().norm());
  out.status = worst_sigma <= allowed_sigma && !underdetermined ? TargetStatus::kOk
                                                                : TargetStatus::kDegraded;
  if (mirrorAmbiguous(obs, result, worst_sigma)) {
    out.status = TargetStatus::kAmbiguous;
    ++stats.ambiguous;
  }

  const int d = config_.solver.planar ? 2 : 3;
  Eigen::MatrixXd r = config_.measurement_noise * Eigen::MatrixXd::Identity(d, d);
  if (config_.filter_uses_solver_covariance && result.covariance_valid) {
    r = result.covariance.topLeftCorner(d, d);
  }
  filter_.predict(now);
  filter_.correct(result.position.head(d), r, now);
  if (!filter_.initialized()) {
    // The very first measurement was invalid for the filter (covariance not usable).
    out.position = result.position;
    out.covariance = result.covariance;
    return out;
  }
  out.position.head(d) = filter_.position();
  out.velocity.head(d) = filter_.velocity();
  out.covariance.topLeftCorner(d, d) = filter_.positionCovariance();
  if (config_.solver.planar) {
    out.position.z() = config_.solver.height;
  }
  if (!out.position.allFinite() || !out.velocity.allFinite() || !out.covariance.allFinite()) {
    ++stats.non_finite;  // never hand a NaN to a controller; the next epoch starts cold
    return lose(out, stats);
  }
  return out;
}

}  // namespace estimation
}  // namespace radio_follow
