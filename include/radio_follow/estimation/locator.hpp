// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstddef>
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

/// The target locator: keeps the newest measurement of every sensor (dropped after
/// max_age, or when stamped ahead of the clock), learns the TDoA offsets, and hands the
/// measurements to the configured PositionEstimator (ParticleEstimator or
/// SolverEstimator). Time is double seconds; no ROS.
class Locator {
 public:
  Locator(const Layout& layout, const LocatorConfig& config);

  // Sensors are named by their index in the layout's lists (Layout::twrModuleIndex and
  // the like): the wrappers resolve a message's IDs once, not the core on every message.
  // An index the layout does not have (kNoSensor) is refused and counted.

  /// Raw (uncalibrated) range of TWR module `module`; false if the module is unknown
  /// or the range is not finite and positive.
  /// `pose`: the robot in the odometry frame at `t` (particle estimator: the track is
  /// then kept in the odometry frame; give it for every measurement or for none).
  bool addRange(std::size_t module, double raw_range, double t,
                const std::optional<Pose2>& pose = std::nullopt);
  /// Bearing of board `board` in the board frame.
  bool addBearing(std::size_t board, double azimuth, double elevation, double rssi, double t,
                  const std::optional<Pose2>& pose = std::nullopt);
  /// Distance difference |p - a| - |p - b| of anchors a and b; variance <= 0 uses tdoa_sigma.
  /// With TDoA auto-calibration active (TdoaCalibration::active) the pair's learnt offset
  /// is subtracted first; until the pair has one the difference is held back (counted in
  /// LocatorStats::tdoa_uncalibrated, not refused).
  bool addTdoa(std::size_t a, std::size_t b, double difference, double variance, double t,
               const std::optional<Pose2>& pose = std::nullopt);
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
  struct Stamped {
    double t = -1.0;
    bool valid = false;
  };
  struct RangeSlot : Stamped {
    double range = 0.0;
  };
  struct BearingSlot : Stamped {
    double azimuth = 0.0;
    double elevation = 0.0;
    double rssi = 0.0;
  };
  struct TdoaSlot : Stamped {
    std::size_t a = 0;
    std::size_t b = 0;
    double difference = 0.0;
    double sigma = 0.0;
  };

  bool fresh(Stamped& slot, double now);
  /// The estimator config_.estimator names; the other one is idle.
  PositionEstimator& active();

  Layout layout_;
  LocatorConfig config_;
  /// One estimator of each kind (both get every setConfig and reset).
  SolverEstimator solver_;
  ParticleEstimator particle_;
  TdoaCalibration tdoa_calibration_;
  std::vector<RangeSlot> ranges_;
  std::vector<BearingSlot> bearings_;
  std::vector<TdoaSlot> tdoas_;
  LocatorStats stats_;
  TimePolicy time_;
};

}  // namespace estimation
}  // namespace radio_follow
