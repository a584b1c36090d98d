// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <deque>
#include <optional>

namespace radio_follow {
namespace control {

/// The goal of a standing target from every reading taken so far, from every pose: the
/// point whose bearings and distances from all the sensor positions fit the readings
/// best (a robust least-squares fit; doc/control/homing.md, "All readings").
///
/// Seed 000's estimators each use a part of the readings: the vector estimate the newest
/// 20, the parallax estimate one line per step. Here every reading counts once, so the
/// error averages down with their number, and a reading taken from one side corrects a
/// goal that readings from straight behind cannot (a straight approach sees the target
/// along its path). The fit needs no noise figures: each kind's scale is estimated from
/// its own residuals (median absolute deviation), and a Huber weight keeps a reflection
/// from pulling the goal.
///
/// A distance of zero is a censored reading: a sensor that cannot report less than zero
/// reports zero for every reading the noise took below it. It counts as the mean of the
/// distances below zero that the current goal predicts (the EM step for censored data),
/// not as zero, which would pull the goal towards the sensor, nor as nothing, which would
/// keep only the long readings near the target.
class StandingGoalEstimator {
 public:
  /// Readings kept: the newest this many (odometry drifts, so the oldest poses are the
  /// least true). 2 minutes of a board's 10 Hz, 40 s of its 30 events/s.
  static constexpr std::size_t kMaxReadings = 1200;
  /// Fewer readings give no fit (the scales need a few residuals).
  static constexpr std::size_t kMinReadings = 5;

  /// One reading from a sensor at `sensor` (odometry frame, m): the bearing to the
  /// target in that frame (rad) and its distance (m; NaN when none). Non-finite
  /// positions or bearings and negative distances are not stored (false).
  bool add(const Eigen::Vector2d& sensor, double bearing, double distance);

  /// The fit, starting from `guess` (the previous goal, or another estimator's). Nullopt
  /// with too few readings, or when they do not fix the goal in both directions
  /// (bearings along one line and no distance).
  std::optional<Eigen::Vector2d> solve(const Eigen::Vector2d& guess) const;

  std::size_t size() const { return readings_.size(); }
  void clear() { readings_.clear(); }

 private:
  struct Reading {
    Eigen::Vector2d sensor;
    double bearing;
    double distance;  ///< NaN: none
  };
  std::deque<Reading> readings_;
};

}  // namespace control
}  // namespace radio_follow
