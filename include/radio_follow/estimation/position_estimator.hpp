// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <Eigen/Core>
#include <limits>
#include <vector>

#include "radio_follow/estimation/aoa_selector.hpp"
#include "radio_follow/estimation/locator_types.hpp"
#include "radio_follow/estimation/measurement_models.hpp"
#include "radio_follow/estimation/particle_tracker.hpp"

namespace radio_follow {
namespace estimation {

/// What is fresh at an update, as the Locator assembled it from its slots (the newest
/// measurement of each sensor, none older than max_age nor stamped ahead of the clock).
struct FreshMeasurements {
  /// Every kind's fresh readings (calibrated, with their sigmas) but the bearings: which
  /// boards may speak is the estimator's choice.
  ObservationSet obs;
  /// Every board with a fresh bearing, in layout order, and of each its (azimuth,
  /// elevation) in the board frame (elevation offset removed), rad, and stamp, s.
  std::vector<AoaCandidate> boards;
  std::vector<Eigen::Vector2d> angles;
  std::vector<double> bearing_stamps;
  /// Newest stamp among obs's readings, s; -inf when there are none.
  double newest = -std::numeric_limits<double>::infinity();
};

/// One way of turning measurements into a position (LocatorConfig::estimator): the
/// Locator keeps the measurements (slots, freshness, plausibility, calibration, the
/// statistics of refused inputs) and hands each estimator what it needs.
///
/// The Locator holds one estimator of each kind and uses the configured one; each has
/// its own configuration (ParticleTrackerConfig, SolverEstimatorConfig), which the
/// Locator makes from LocatorConfig and hands to every estimator on each change of
/// tuning, and reset() when the clock jumps back or the estimator changes.
class PositionEstimator {
 public:
  virtual ~PositionEstimator() = default;

  /// An accepted, calibrated measurement, at once (only the active estimator gets them).
  virtual void add(const TrackedMeasurement& m) = 0;
  /// Every accepted measurement, whichever estimator is active: history that must be
  /// there when a live switch makes this estimator the active one. Default: none kept.
  virtual void record(const TrackedMeasurement& /*m*/) {}
  /// The estimate at `now`. `partial` carries what the Locator filled in (solver_cost NaN,
  /// ranges_used, ranges_m, bearings_fresh, bearing_angles); the estimator adds its part
  /// and counts solves, failures, LOST, AMBIGUOUS and non-finite epochs in `stats`.
  virtual LocatorEstimate estimate(double now, const FreshMeasurements& fresh,
                                   LocatorEstimate partial, LocatorStats& stats) = 0;
  /// Forgets the track (keeps the tuning and the counters of its parts).
  virtual void reset() = 0;
};

}  // namespace estimation
}  // namespace radio_follow
