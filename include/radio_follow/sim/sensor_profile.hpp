// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "radio_follow/common/angles.hpp"
#include "radio_follow/config/layout.hpp"
#include "radio_follow/sim/virtual_sensors.hpp"

namespace radio_follow {
namespace sim {

/// How the virtual sensors err (`sensor_profile`, doc/simulator.md).
enum class SensorProfile {
  /// The thesis's tables with white noise: what the simulator always did, bit for bit.
  kIdeal,
  /// The errors measured on a real recording: per-module bias and scale, a direction
  /// dependence, time-correlated noise, long reflections, dropouts; AoA boards mounted
  /// slightly rotated; TDoA anchors with offsets.
  kRealistic,
};

/// Throws ParamError naming `name` unless `text` is "ideal" or "realistic".
SensorProfile parseSensorProfile(const std::string& text, const std::string& name);
std::string toString(SensorProfile profile);

/// The realistic profile's figures. Where each comes from: doc/simulator.md.
struct RealisticFigures {
  double twr_bias_min = 0.08;    ///< m, per module-tag pair, uniform
  double twr_bias_max = 0.31;    ///< m
  double twr_scale_min = 0.006;  ///< per metre of distance
  double twr_scale_max = 0.02;
  double twr_direction_amplitude = 0.06;  ///< m, first harmonic of the bearing
  double twr_sigma = 0.065;               ///< m, total of both noise components
  double twr_slow_share = 0.65;           ///< share of the variance in the slow component
  double twr_slow_tau = 3.0;              ///< s
  double twr_fast_tau = 0.06;             ///< s
  double twr_outlier_start = 0.00075;     ///< chance per epoch that a reflection starts
  double twr_outlier_continue = 0.5;      ///< chance it lasts one more epoch
  double twr_outlier_short_share = 0.05;  ///< share of outliers that read short
  double twr_outlier_min = 0.3;           ///< m, the shortest excess of a reflection
  double twr_outlier_mean_excess = 0.7;   ///< m, mean excess beyond twr_outlier_min
  double twr_outlier_max = 3.0;           ///< m
  double twr_dropout = 0.03;              ///< chance per epoch, on top of twr_dropout
  double aoa_yaw_error_max = 0.035;       ///< rad (2 deg), per board, uniform +-
  // Real XPLR-AOA-1 boards' bearing errors (issue 35; doc/simulator.md, "Bearings from
  // real boards"): a per-board azimuth bias, an error that follows the tag's path
  // (multipath changes with the geometry, so a person who stands keeps the error),
  // heavy-tailed noise per event, reflections, elevations 2-11 deg low with a few shadowed
  // high. Together: |azimuth error| median 8 deg, p95 30 deg, as measured.
  double aoa_reflection = 0.05;           ///< chance an event reports a wrong direction
  double aoa_bias_sigma = deg2rad(3.5);   ///< rad, per board azimuth bias, Gaussian
  double aoa_slow_sigma = deg2rad(6.0);   ///< rad, Gauss-Markov along the tag's path
  double aoa_slow_length = 1.5;           ///< m of the tag's path (board frame) per decorrelation
  double aoa_slow_time = 20.0;            ///< s: the room changes too, slowly
  double aoa_event_scale = deg2rad(5.0);  ///< rad, Student-t scale per event
  double aoa_event_dof = 3.0;             ///< its degrees of freedom (heavy tails)
  double aoa_elevation_bias_min = deg2rad(-11.0);  ///< rad, per board elevation bias, uniform
  double aoa_elevation_bias_max = deg2rad(-2.0);   ///< rad
  double aoa_shadow = 0.03;               ///< chance an elevation reads high (body shadowing)
  double aoa_shadow_max = 0.6;            ///< rad (35 deg), that excess, uniform from 5 deg
  double tdoa_offset_max = 0.1;           ///< m, per anchor, uniform +-
  double tdoa_slow_sigma = 0.05;          ///< m, per anchor, Gauss-Markov on top of tdoa_sigma
  double tdoa_slow_tau = 3.0;             ///< s
};

/// A first-order Gauss-Markov process sampled at arbitrary times: exact discretisation
/// x' = a x + sqrt(1 - a^2) sigma w with a = exp(-dt / tau), so its statistics do not
/// depend on how irregularly it is sampled. Starts from its stationary distribution.
class GaussMarkov {
 public:
  GaussMarkov(double sigma, double tau) : sigma_(sigma), tau_(tau) {}
  double sample(double t, Rng& rng);

 private:
  double sigma_;
  double tau_;
  std::optional<double> last_t_;
  double value_ = 0.0;
};

/// One module's constant errors with one tag (the antenna delays and the pair's
/// clock-offset estimate are both ends'), drawn from `hardware_seed` and the module's and
/// tag's IDs, so a simulated robot keeps them whatever the noise seed.
struct TwrHardware {
  double bias = 0.0;       ///< m
  double scale = 0.0;      ///< per metre
  double direction = 0.0;  ///< m, amplitude of the bearing dependence
  double phase = 0.0;      ///< rad, bearing of its maximum
};
TwrHardware drawTwrHardware(std::uint64_t hardware_seed, const std::string& module_id,
                            const std::string& tag_id, const RealisticFigures& figures = {});

/// The time-correlated noise and reflection bursts of one module (the World keeps one
/// per module).
class TwrNoiseState {
 public:
  explicit TwrNoiseState(const RealisticFigures& figures = {}, double sigma_scale = 1.0);
  /// The noise at time t, m.
  double noise(double t, Rng& rng);
  /// The reflection excess of this epoch, m (0 without one).
  double outlier(Rng& rng);
  const RealisticFigures& figures() const { return figures_; }

 private:
  RealisticFigures figures_;
  GaussMarkov slow_;
  GaussMarkov fast_;
  int burst_left_ = 0;
  double burst_excess_ = 0.0;
};

/// The realistic range of `module` for a target at `target` (fixed frame, m) at time t, or
/// nothing (dropout). `noise` supplies the dropout probability and occlusion sectors.
std::optional<double> simulateRealisticTwr(const TwrModule& module, const TwrHardware& hardware,
                                           const TwrNoise& noise, TwrNoiseState& state,
                                           const Eigen::Vector3d& target, double t, Rng& rng);

/// The board as mounted: the layout's orientation turned by a small yaw error about its z
/// axis, drawn from `hardware_seed` and the board's ID.
AoaBoard mountedAoaBoard(const AoaBoard& board, std::uint64_t hardware_seed,
                         const RealisticFigures& figures = {});

/// One board's realistic bearings: the board as mounted (mountedAoaBoard), its constant
/// azimuth and elevation biases (drawn from `hardware_seed` and its ID), the error that
/// follows the tag's path in the board frame, heavy-tailed noise per event, reflections
/// (an azimuth uniform over the hemisphere) and shadowed elevations. The World keeps one
/// per board.
class AoaErrorState {
 public:
  AoaErrorState(const AoaBoard& board, std::uint64_t hardware_seed,
                const RealisticFigures& figures = {});
  const AoaBoard& mounted() const { return mounted_; }
  double azimuthBias() const { return azimuth_bias_; }      ///< rad, reported minus true
  double elevationBias() const { return elevation_bias_; }  ///< rad
  /// simulateAoa on the mounted board with these errors added, for a target at `target`
  /// (the board's parent frame) at time t; nothing when the event is lost.
  std::optional<AoaSample> simulate(const AoaNoise& noise, const Eigen::Vector3d& target,
                                    double t, Rng& rng);

 private:
  RealisticFigures figures_;
  AoaBoard mounted_;
  double azimuth_bias_ = 0.0;
  double elevation_bias_ = 0.0;
  GaussMarkov slow_azimuth_;
  GaussMarkov slow_elevation_;
  std::optional<Eigen::Vector3d> last_local_;
  double path_ = 0.0;  ///< the tag's path so far in the board frame, m
};

/// The realistic TDoA errors added to simulateTdoa's white noise: a constant offset per
/// anchor and a slow per-anchor drift (common to every tag the anchors hear), long
/// reflections on one anchor's path and blinks missed, both as often as the same radio's
/// TWR ranges show them (twr_outlier_*, twr_dropout: the stationary share of outlier
/// epochs, one blink each).
class TdoaHardware {
 public:
  TdoaHardware(const std::vector<TdoaAnchor>& anchors, std::uint64_t hardware_seed,
               const RealisticFigures& figures = {});
  /// The differences vs anchor `reference` with the anchors' errors added; empty when
  /// the blink was missed.
  std::vector<double> simulate(const std::vector<TdoaAnchor>& anchors, std::size_t reference,
                               double sigma, const Eigen::Vector3d& target, double t, Rng& rng);

 private:
  RealisticFigures figures_;
  std::vector<double> offsets_;
  std::vector<GaussMarkov> drift_;
};

/// One blink's differences vs anchor `reference`, sent from `target`: with `hardware`
/// (the realistic profile) its errors are added, without it (the ideal profile) only
/// simulateTdoa's white noise. Empty when the blink was missed.
std::vector<double> simulateBlink(std::optional<TdoaHardware>& hardware,
                                  const std::vector<TdoaAnchor>& anchors, std::size_t reference,
                                  double sigma, const Eigen::Vector3d& target, double t, Rng& rng);

}  // namespace sim
}  // namespace radio_follow
