// SPDX-License-Identifier: BSD-3-Clause
// The locator's tuning and output, shared by the Locator and its estimators.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "radio_follow/common/angles.hpp"
#include "radio_follow/common/param_source.hpp"
#include "radio_follow/common/param_table.hpp"
#include "radio_follow/common/pose2.hpp"
#include "radio_follow/common/target_status.hpp"
#include "radio_follow/estimation/aoa_selector.hpp"
#include "radio_follow/estimation/initializer.hpp"
#include "radio_follow/estimation/kalman_filter.hpp"
#include "radio_follow/estimation/particle_tracker.hpp"
#include "radio_follow/estimation/position_solver.hpp"
#include "radio_follow/estimation/rss_direction.hpp"
#include "radio_follow/estimation/tdoa_calibration.hpp"

namespace radio_follow {
namespace estimation {

/// How the position is estimated (doc/nodes/locator.md, "Particle estimator" and
/// "Behaviour of the solver estimator").
enum class Estimator {
  /// Every measurement at its stamp into a particle filter in the odometry frame, with a
  /// mirror hypothesis (ParticleTracker). The default.
  kParticle,
  /// A Ceres solve of the newest measurement of each sensor per update, filtered by a
  /// Kalman filter in the robot frame (the thesis's structure).
  kSolver,
};

struct SolverEstimatorConfig;  // solver_estimator.hpp

/// The locator's tuning, as its parameters name it (the sensor positions come from the
/// Layout). Each estimator gets its own configuration from it (solverEstimator(),
/// tracker()).
struct LocatorConfig {
  Estimator estimator = Estimator::kParticle;
  bool planar = true;                               ///< 2D mode: target on the plane z = height
  double height = ParticleFilter::Config().height;  ///< m
  double range_sigma = RangeLikelihood().sigma;  ///< m (real DWM1001 ranges, doc/nodes/locator.md)
  double tdoa_sigma = 0.1;                       ///< m, when a difference has no variance
  double azimuth_sigma = BearingLikelihood().azimuth_sigma;      ///< rad
  double elevation_sigma = BearingLikelihood().elevation_sigma;  ///< rad
  bool use_elevation = true;
  LossConfig range_loss = RangeObservation::kDefaultLoss;
  LossConfig tdoa_loss = TdoaObservation::kDefaultLoss;
  LossConfig bearing_loss = BearingObservation::kDefaultLoss;
  double max_age = ParticleTrackerConfig().max_age;  ///< s; older measurements are dropped
  AoaSelectorConfig aoa;
  MotionModel motion_model = MotionModel::kConstantVelocity;
  /// See KalmanConfig; the particle filter's acceleration PSD (both filters' default).
  double process_noise = kDefaultProcessNoise;
  /// true: R = the solver's covariance; false: R = measurement_noise * I (thesis: 50).
  bool filter_uses_solver_covariance = true;
  double measurement_noise = 50.0;  ///< m^2
  double gate_probability = KalmanConfig().gate_probability;
  int max_consecutive_rejections = KalmanConfig().max_consecutive_rejections;
  bool ceres_covariance = false;
  /// Largest position standard deviation (worst axis) still reported as OK, m.
  double max_position_sigma = ParticleTrackerConfig().max_position_sigma;
  /// ... or this fraction of the target's distance, whichever is larger: a bearing's
  /// sideways error grows with distance, and a far target that is DEGRADED (so followed
  /// slowly) only gets farther away. 0 disables.
  double max_relative_sigma = ParticleTrackerConfig().max_relative_sigma;
  /// Distance assumed along a bearing when no range exists, m.
  double default_range = kDefaultRange;
  /// Mirror test: each ranged solve is repeated from the solution's mirror image across
  /// the ranging modules' main axis. When that second solution lies elsewhere and its cost
  /// is within this margin of the first (0.5 chi-square units; 2 = the data prefer one
  /// side by less than about 2 sigma), the data cannot tell the two apart: the estimate is
  /// AMBIGUOUS until a few epochs in a row have preferred one side by more. 0 disables.
  double ambiguity_margin = ParticleTrackerConfig().ambiguity_margin;
  /// Particle estimator: particles of the main hypothesis (the mirror gets a quarter).
  int particles = static_cast<int>(ParticleFilter::Config().particles);
  /// Share of ranges (and TDoA differences) that are outliers, mostly long (reflections).
  double range_outlier_share = RangeLikelihood().outlier_share;
  /// Mean excess of a long range outlier, m.
  double range_outlier_length = RangeLikelihood().outlier_length;
  /// Share of bearings that are reflections (any direction).
  double bearing_outlier_share = BearingLikelihood().outlier_share;
  /// Share of elevations that are shadowed (the wearer's body between tag and board: the
  /// elevation reads high while the azimuth holds).
  double elevation_outlier_share = BearingLikelihood().elevation_outlier_share;
  /// Worst-axis sigma beyond which a ranged track is LOST and restarts (or twice
  /// max_relative_sigma times the distance, if larger), m.
  double lost_sigma = ParticleTrackerConfig().lost_sigma;
  /// Particle estimator: time constant over which the mirror test's evidence fades, s.
  double mirror_memory = ParticleTrackerConfig().mirror_memory;
  /// Particle estimator: a person who walks and stands by turns (particle_filter.hpp):
  /// mean length of a standing spell and of a walking one, s (stand_time 0: every
  /// particle walks, the plain constant-velocity model), and a standing person's sway,
  /// a random walk of this PSD per axis, m^2/s.
  double stand_time = ParticleFilter::Config().stand_time;
  double walk_time = ParticleFilter::Config().walk_time;
  double stand_noise = ParticleFilter::Config().stand_noise;
  /// Particle estimator: a module's ranges closer in time than this count as a fraction
  /// of a measurement (RangeReading::Tuning::decorrelation_time), s; 0: all fully.
  double range_decorrelation_time = RangeReading::Tuning().decorrelation_time;
  /// Particle estimator: the same for a board's bearings
  /// (BearingReading::Tuning::decorrelation_time), s; 0: all fully.
  double bearing_decorrelation_time = BearingReading::Tuning().decorrelation_time;
  /// Particle estimator: the slowly varying part of each sensor's error, which filtering
  /// cannot average away (correlated_error.hpp); the floor of the reported covariance.
  double range_bias_sigma = RangeReading::Tuning().bias_sigma;      ///< m, TWR ranges
  double tdoa_bias_sigma = TdoaReading::Tuning().bias_sigma;        ///< m, TDoA differences
  double azimuth_bias_sigma = BearingReading::Tuning().bias_sigma;  ///< rad, AoA azimuths
  /// Particle estimator: seed 001's RSS direction. The RSSI difference of two opposed
  /// boards (rss_direction.hpp) weighs which side of the pair the target is on; an
  /// optional input, off by default.
  bool rss_direction = RssDirectionReading::Tuning().enabled;
  /// g: the difference with the target straight ahead of one board of a pair, dB (the
  /// front-to-back drop of one board: doc/nodes/locator.md, "RSS direction").
  double rss_direction_gain = RssDirectionLikelihood().gain;
  /// Standard deviation of a pair's difference, dB.
  double rss_direction_sigma = RssDirectionLikelihood().sigma;
  /// The TDoA anchors' offsets, learnt from the robot's own modules' blinks.
  TdoaCalibrationConfig tdoa_calibration;

  /// Reads the fields from their parameters (the locator node's names, e.g. `range_sigma`,
  /// `azimuth_sigma_deg`, `measurement_covariance`); absent keys keep their value.
  void load(const ParamSource& source);
  /// The parameters, as the locator node names them.
  static const ParamTable<LocatorConfig>& table();
  /// Throws ParamError naming the first invalid field (names match the ROS parameters).
  void validate() const;
  /// Each estimator's own configuration from these fields: the only place the
  /// parameters are mapped onto them.
  SolverEstimatorConfig solverEstimator() const;
  ParticleTrackerConfig tracker() const;
  /// One line per parameter that is set away from its default but that `estimator` never
  /// reads (the solver's robust losses and Kalman filter under the particle estimator,
  /// the particle filter's settings under the solver), naming it, its value and the
  /// estimator that reads it: tuning it changes nothing.
  std::vector<std::string> ignoredSettings() const;
};

struct LocatorEstimate {
  TargetStatus status = TargetStatus::kLost;
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  std::uint8_t sources = 0;
  double solver_cost = 0.0;  ///< NaN when no solve ran
  double stamp = 0.0;        ///< time of the newest measurement used, s
  /// What the solve used (layout indices), for markers and diagnostics.
  std::vector<std::size_t> ranges_used;
  std::vector<double> ranges_m;  ///< calibrated range of each entry of ranges_used, m
  std::vector<std::size_t> bearings_fresh;
  /// (azimuth, elevation) in the board frame of each entry of bearings_fresh, rad.
  std::vector<Eigen::Vector2d> bearing_angles;
  std::vector<std::size_t> bearings_used;
  /// The particle estimator's view: the state in the tracking frame (the odometry frame
  /// when the measurements came with poses, else the robot frame) at `stamp`.
  bool in_odom = false;
  Pose2 robot_pose;  ///< robot in the tracking frame at `stamp`
  Eigen::Vector3d tracking_position = Eigen::Vector3d::Zero();
  Eigen::Vector3d tracking_velocity = Eigen::Vector3d::Zero();
  Eigen::Matrix3d tracking_covariance = Eigen::Matrix3d::Zero();
  /// Hypotheses the data allow (1; 2 when the mirror image holds probability; 0 = not
  /// computed: the solver estimator, or LOST), the probability of `position`'s, and the
  /// other one's position (robot frame).
  int hypotheses = 0;
  double hypothesis_weight = 1.0;
  Eigen::Vector3d alternative = Eigen::Vector3d::Zero();
};

struct LocatorStats {
  std::size_t updates = 0;
  std::size_t solves = 0;
  std::size_t solver_failures = 0;
  std::size_t stale_dropped = 0;
  std::size_t future_dropped = 0;  ///< measurements stamped ahead of update()'s clock
  std::size_t non_finite = 0;      ///< epochs whose filter output was not finite
  std::size_t invalid_measurements = 0;
  std::size_t bearings_rejected_fov = 0;
  std::size_t lost = 0;
  std::size_t ambiguous = 0;  ///< epochs reported AMBIGUOUS (mirror test)
  /// Target TDoA differences held back: their pair had no learnt offset yet.
  std::size_t tdoa_uncalibrated = 0;
  std::size_t tdoa_calibration_differences = 0;  ///< module differences fed to the calibration
  double last_solve_seconds = 0.0;
};

}  // namespace estimation
}  // namespace radio_follow
