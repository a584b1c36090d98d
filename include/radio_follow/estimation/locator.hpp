// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cmath>
#include <cstddef>
#include <map>
#include <optional>
#include <vector>

#include "radio_follow/common/pose2.hpp"
#include "radio_follow/common/time_policy.hpp"
#include "radio_follow/config/layout.hpp"
#include "radio_follow/estimation/locator_types.hpp"
#include "radio_follow/estimation/particle_estimator.hpp"
#include "radio_follow/estimation/position_estimator.hpp"
#include "radio_follow/estimation/solver_estimator.hpp"
#include "radio_follow/estimation/tdoa_calibration.hpp"

namespace radio_follow {
namespace estimation {

/// What a kind's accept() and observe() may read (tracked_reading.hpp), and the
/// statistics they count in.
struct LocatorIntake {
  const Layout& layout;
  const LocatorConfig& config;
  const TdoaCalibration& tdoa_calibration;
  LocatorStats& stats;
};

/// The target locator: keeps the newest reading of every sensor (dropped after max_age,
/// or when stamped ahead of the clock), learns the TDoA offsets, and hands the readings
/// to the configured PositionEstimator (ParticleEstimator or SolverEstimator). It names
/// no measurement kind: each kind's reading checks and calibrates itself (accept) and
/// puts itself into an update (observe). Time is double seconds; no ROS.
class Locator {
 public:
  Locator(const Layout& layout, const LocatorConfig& config);

  /// A raw reading at `t`, its sensors named by their index in the layout's lists
  /// (Layout::twrModuleIndex and the like): the wrappers resolve a message's IDs once, not
  /// the core on every message. False when its kind refuses it (an index the layout does
  /// not have, kNoSensor, or an implausible value) or `t` is not finite: counted in
  /// LocatorStats::invalid_measurements. True when accepted, or held by its kind (a TDoA
  /// pair waiting for its offset).
  /// `pose`: the robot in the odometry frame at `t` (particle estimator: the track is
  /// then kept in the odometry frame; give it for every reading or for none).
  bool add(double t, TrackedReading reading, const std::optional<Pose2>& pose = std::nullopt);

  // Shorthands of add() for the kinds the package ships.

  /// Raw (uncalibrated) range of TWR module `module`.
  bool addRange(std::size_t module, double raw_range, double t,
                const std::optional<Pose2>& pose = std::nullopt) {
    return add(t, RangeReading{module, raw_range}, pose);
  }
  /// Bearing of board `board` in the board frame, with the board's RSSI, dBm.
  bool addBearing(std::size_t board, double azimuth, double elevation, double rssi, double t,
                  const std::optional<Pose2>& pose = std::nullopt) {
    return add(t, BearingReading{board, azimuth, elevation, rssi}, pose);
  }
  /// Distance difference |p - a| - |p - b| of anchors a and b; variance <= 0 uses tdoa_sigma.
  bool addTdoa(std::size_t a, std::size_t b, double difference, double variance, double t,
               const std::optional<Pose2>& pose = std::nullopt) {
    const double sigma = variance > 0.0 && std::isfinite(variance) ? std::sqrt(variance) : 0.0;
    return add(t, TdoaReading{a, b, difference, sigma}, pose);
  }
  /// A difference |m - a| - |m - b| of one of the robot's own TWR modules' blinks: feeds
  /// the anchors' offsets (TdoaCalibration), never the estimate. False for an unknown
  /// module or anchor or a value that is not finite.
  bool addTdoaCalibration(std::size_t module, std::size_t a, std::size_t b, double difference,
                          double t);

  /// Applies new tuning without a restart (live tuning). Throws ParamError and keeps the
  /// old tuning when `config` is invalid or changes `mode` (2d/3d: the state's size).
  /// The buffered measurements and statistics are kept. Every estimator gets its own part
  /// of the tuning (LocatorConfig::solverEstimator(), tracker()): the solver's filter
  /// keeps its track unless motion_model
  /// changes (then it restarts from the next solve); a change of the AoA selection
  /// settings restarts the board selection's RSSI history. A new `estimator` starts from
  /// no track. Returns false when an estimator was restarted.
  bool setConfig(const LocatorConfig& config);

  /// Solves and filters with what is fresh at `now`.
  LocatorEstimate update(double now);

  const LocatorStats& stats() const { return stats_; }
  /// The solver estimator's filter and the particle estimator's tracker (whichever is
  /// active: the other is idle).
  const KalmanFilter& filter() const { return solver_.filter(); }
  const ParticleTracker& tracker() const { return particle_.tracker(); }
  const Layout& layout() const { return layout_; }
  const LocatorConfig& config() const { return config_; }
  const TdoaCalibration& tdoaCalibration() const { return tdoa_calibration_; }

 private:
  /// A sensor's newest accepted reading.
  struct Slot {
    double t = -1.0;
    bool valid = false;
    TrackedReading reading;
  };

  LocatorIntake intake() { return {layout_, config_, tdoa_calibration_, stats_}; }
  bool fresh(Slot& slot, double now);
  /// The estimator config_.estimator names; the other one is idle.
  PositionEstimator& active();

  Layout layout_;
  LocatorConfig config_;
  /// One estimator of each kind (both get every setConfig and reset).
  SolverEstimator solver_;
  ParticleEstimator particle_;
  TdoaCalibration tdoa_calibration_;
  /// By sensor: an update visits them in SensorKey order (kind, then layout index).
  std::map<SensorKey, Slot> slots_;
  LocatorStats stats_;
  TimePolicy time_;
};

}  // namespace estimation
}  // namespace radio_follow
