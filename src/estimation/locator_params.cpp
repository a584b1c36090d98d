// SPDX-License-Identifier: BSD-3-Clause
// The locator's tuning as one parameter table (names are the node's parameters,
// doc/nodes/locator.md): loading from ROS or YAML, bounds, live tuning and the docs'
// coverage test all read it.
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "radio_follow/common/angles.hpp"
#include "radio_follow/common/param_error.hpp"
#include "radio_follow/estimation/locator.hpp"
#include "radio_follow/estimation/solver_estimator.hpp"

namespace radio_follow {
namespace estimation {
namespace {

/// The choices of an enum, named as its toString() names them.
template <typename E>
std::vector<std::pair<std::string, E>> named(std::initializer_list<E> values) {
  std::vector<std::pair<std::string, E>> choices;
  for (const E v : values) {
    choices.emplace_back(toString(v), v);
  }
  return choices;
}

const ParamTable<LossConfig>& lossTable() {
  static const ParamTable<LossConfig> t =
      ParamTable<LossConfig>()
          .addChoice(
              "", &LossConfig::type,
              named({LossType::kNone, LossType::kHuber, LossType::kSoftL1, LossType::kCauchy}),
              "Robust loss of the residuals.")
          .add("_scale", &LossConfig::scale, "sigma", "Where the loss starts, in sigmas.",
               Range::above(0.0));
  return t;
}

const ParamTable<AoaSelectorConfig>& aoaTable() {
  static const ParamTable<AoaSelectorConfig> t =
      ParamTable<AoaSelectorConfig>()
          .addChoice("aoa_selection", &AoaSelectorConfig::mode,
                     named({AoaSelectionMode::kRssi, AoaSelectionMode::kExternal,
                            AoaSelectionMode::kAllInFov}),
                     "Which AoA boards' bearings the solve uses.")
          .add("aoa_rssi_window", &AoaSelectorConfig::rssi_window, "",
               "RSSI values per board the selection averages.", Range::atLeast(1))
          .add("aoa_vote_window", &AoaSelectorConfig::vote_window, "",
               "Epochs the board vote runs over.", Range::atLeast(1));
  return t;
}

const ParamTable<TdoaCalibrationConfig>& tdoaCalibrationTable() {
  static const ParamTable<TdoaCalibrationConfig> t =
      ParamTable<TdoaCalibrationConfig>()
          .add("tdoa_calibration", &TdoaCalibrationConfig::enabled, "",
               "Learn the TDoA anchors' offsets from the robot's own modules' blinks and fuse "
               "a pair's differences only once it has one.")
          .add("tdoa_calibration_window", &TdoaCalibrationConfig::window, "s",
               "Seconds of module blinks each pair's offset is the median of.",
               Range::aboveUpTo(0.0, 600.0))
          .add("tdoa_calibration_min_blinks", &TdoaCalibrationConfig::min_blinks, "",
               "Module differences a pair needs in its window before its offset is used.",
               Range::closed(1, 100000));
  return t;
}

// What only one estimator reads (estimation::Locator: the particle path returns before
// the solve and the Kalman filter; the solver path never feeds the particle tracker).
const std::vector<std::string>& solverOnlyKeys() {
  static const std::vector<std::string> keys{
      "range_loss",        "range_loss_scale", "tdoa_loss",
      "tdoa_loss_scale",   "bearing_loss",     "bearing_loss_scale",
      "ceres_covariance",  "motion_model",     "measurement_covariance",
      "measurement_noise", "gate_probability", "max_consecutive_rejections"};
  return keys;
}

const std::vector<std::string>& particleOnlyKeys() {
  static const std::vector<std::string> keys{"particles",
                                             "range_outlier_share",
                                             "range_outlier_length",
                                             "bearing_outlier_share",
                                             "elevation_outlier_share",
                                             "lost_sigma",
                                             "mirror_memory",
                                             "stand_time",
                                             "walk_time",
                                             "stand_noise",
                                             "range_decorrelation_time",
                                             "bearing_decorrelation_time"};
  return keys;
}

void validateLoss(const LossConfig& loss, const std::string& name) {
  require(loss.type == LossType::kNone || (std::isfinite(loss.scale) && loss.scale > 0.0),
          "~" + name + "_scale", loss.scale, "a positive loss scale (in sigmas)");
}

}  // namespace

std::vector<std::string> LocatorConfig::ignoredSettings() const {
  const bool particle = estimator == Estimator::kParticle;
  const LocatorConfig defaults;
  std::vector<std::string> lines;
  for (const std::string& key : particle ? solverOnlyKeys() : particleOnlyKeys()) {
    const auto* entry = table().find(key);
    if (entry != nullptr && !(entry->get(*this) == entry->get(defaults))) {
      lines.push_back("~" + key + " = " + paramValueText(entry->get(*this)) +
                      " has no effect with estimator " + (particle ? "particle" : "solver") +
                      " (only the " + (particle ? "solver" : "particle") + " estimator reads it)");
    }
  }
  return lines;
}

const ParamTable<LocatorConfig>& LocatorConfig::table() {
  using C = LocatorConfig;
  static const ParamTable<C> t =
      ParamTable<C>()
          .addChoice("estimator", &C::estimator,
                     std::vector<std::pair<std::string, Estimator>>{
                         {"particle", Estimator::kParticle}, {"solver", Estimator::kSolver}},
                     "particle: every measurement at its stamp into a particle filter with a "
                     "mirror hypothesis; solver: a Ceres solve per update and a Kalman filter.")
          .addChoice("mode", &C::planar,
                     std::vector<std::pair<std::string, bool>>{{"2d", true}, {"3d", false}},
                     "2d: the target on the plane z = target_height; 3d: z estimated.")
          .add("target_height", &C::height, "m", "Height of the target's tags (2d mode).",
               Range::open(-100.0, 100.0))
          .add("range_sigma", &C::range_sigma, "m", "TWR range standard deviation.",
               Range::above(0.0))
          .add("tdoa_sigma", &C::tdoa_sigma, "m",
               "TDoA difference standard deviation when a message carries none.", Range::above(0.0))
          .addScaled("azimuth_sigma_deg", &C::azimuth_sigma, kPi / 180.0, "deg",
                     "AoA azimuth standard deviation.", Range::above(0.0))
          .addScaled("elevation_sigma_deg", &C::elevation_sigma, kPi / 180.0, "deg",
                     "AoA elevation standard deviation.", Range::above(0.0))
          .add("use_elevation", &C::use_elevation, "", "Use the boards' elevation angles.")
          .include(lossTable(), &C::range_loss, "range_loss")
          .include(lossTable(), &C::tdoa_loss, "tdoa_loss")
          .include(lossTable(), &C::bearing_loss, "bearing_loss")
          .add("max_age", &C::max_age, "s", "Older measurements are dropped.", Range::above(0.0))
          .include(aoaTable(), &C::aoa)
          .include(tdoaCalibrationTable(), &C::tdoa_calibration)
          .addChoice("motion_model", &C::motion_model,
                     named({MotionModel::kConstantPosition, MotionModel::kConstantVelocity}),
                     "The Kalman filter's motion model.")
          .add("process_noise", &C::process_noise, "", "The filter's process noise.",
               Range::above(0.0))
          .addChoice("measurement_covariance", &C::filter_uses_solver_covariance,
                     std::vector<std::pair<std::string, bool>>{{"solver", true}, {"fixed", false}},
                     "solver: R = the solver's covariance; fixed: R = measurement_noise * I.")
          .add("measurement_noise", &C::measurement_noise, "m^2", "R with fixed covariance.",
               Range::above(0.0))
          .add("gate_probability", &C::gate_probability, "",
               "Chi-square gate of the filter; 0 = no gating.", Range::closed(0.0, 1.0))
          .add("max_consecutive_rejections", &C::max_consecutive_rejections, "",
               "Gated solves in a row before the filter restarts.", Range::atLeast(1))
          .add("ceres_covariance", &C::ceres_covariance, "",
               "Covariance from Ceres instead of the Gauss-Newton approximation.")
          .add("max_position_sigma", &C::max_position_sigma, "m",
               "Largest position sigma still OK.", Range::above(0.0))
          .add("max_relative_sigma", &C::max_relative_sigma, "",
               "... or this fraction of the distance; 0 disables.", Range::closed(0.0, 1.0))
          .add("ambiguity_margin", &C::ambiguity_margin, "",
               "Mirror test margin (0.5 chi-square units); 0 disables.", Range::atLeast(0.0))
          .add("default_range", &C::default_range, "m",
               "Distance assumed along a bearing without a range.", Range::above(0.0))
          .add("particles", &C::particles, "", "Particles of the main hypothesis (particle).",
               Range::closed(50, 100000))
          .add("range_outlier_share", &C::range_outlier_share, "",
               "Share of ranges that are outliers, mostly long (particle).", Range::open(0.0, 0.5))
          .add("range_outlier_length", &C::range_outlier_length, "m",
               "Mean excess of a long range outlier (particle).", Range::above(0.0))
          .add("bearing_outlier_share", &C::bearing_outlier_share, "",
               "Share of bearings that are reflections (particle).", Range::open(0.0, 0.5))
          .add("elevation_outlier_share", &C::elevation_outlier_share, "",
               "Share of elevations that are shadowed, read high (particle).",
               Range::open(0.0, 0.5))
          .add("lost_sigma", &C::lost_sigma, "m",
               "Worst-axis sigma beyond which the track is lost (particle).", Range::above(0.0))
          .add("mirror_memory", &C::mirror_memory, "s",
               "Time constant over which the mirror test's evidence fades (particle).",
               Range::above(0.0))
          .add("stand_time", &C::stand_time, "s",
               "Mean standing spell of the target; 0: no standing mode (particle).",
               Range::closed(0.0, 3600.0))
          .add("walk_time", &C::walk_time, "s", "Mean walking spell of the target (particle).",
               Range::open(0.0, 3600.0))
          .add("stand_noise", &C::stand_noise, "m^2/s",
               "A standing target's sway, random-walk PSD per axis (particle).", Range::above(0.0))
          .add("range_decorrelation_time", &C::range_decorrelation_time, "s",
               "A module's ranges closer than this count as a fraction of one (particle).",
               Range::closed(0.0, 10.0))
          .add("bearing_decorrelation_time", &C::bearing_decorrelation_time, "s",
               "A board's bearings closer than this count as a fraction of one (particle).",
               Range::closed(0.0, 10.0))
          .add("range_bias_sigma", &C::range_bias_sigma, "m",
               "Slowly varying part of the range error: covariance floor (particle).",
               Range::atLeast(0.0))
          .add("tdoa_bias_sigma", &C::tdoa_bias_sigma, "m",
               "Slowly varying part of the TDoA error: covariance floor (particle).",
               Range::atLeast(0.0))
          .addScaled("azimuth_bias_sigma_deg", &C::azimuth_bias_sigma, kPi / 180.0, "deg",
                     "Slowly varying part of the azimuth error: covariance floor (particle).",
                     Range::atLeast(0.0))
          .add("rss_direction", &C::rss_direction, "",
               "Weigh the RSSI difference of opposed AoA boards (seed 001; particle).")
          .add("rss_direction_gain_db", &C::rss_direction_gain, "dB",
               "RSSI difference with the target straight ahead of one board of a pair "
               "(particle).",
               Range::above(0.0))
          .add("rss_direction_sigma_db", &C::rss_direction_sigma, "dB",
               "Standard deviation of an opposed pair's RSSI difference (particle).",
               Range::above(0.0));
  return t;
}

void LocatorConfig::load(const ParamSource& source) {
  table().load(source, *this);
}

void LocatorConfig::validate() const {
  table().check(*this);
  // Beyond the table's bounds: a loss needs a scale, gating a probability above 1/2.
  validateLoss(range_loss, "range_loss");
  validateLoss(tdoa_loss, "tdoa_loss");
  validateLoss(bearing_loss, "bearing_loss");
  require(gate_probability == 0.0 || (gate_probability > 0.5 && gate_probability < 1.0),
          "~gate_probability", gate_probability, "0 (no gating) or a probability in (0.5, 1)");
  require(max_relative_sigma < 1.0, "~max_relative_sigma", max_relative_sigma,
          "a fraction of the distance in [0, 1)");
}

SolverEstimatorConfig LocatorConfig::solverEstimator() const {
  const LocatorConfig& c = *this;
  SolverEstimatorConfig e;
  e.solver.planar = c.planar;
  e.solver.height = c.height;
  e.solver.loss<RangeObservation>() = c.range_loss;
  e.solver.loss<TdoaObservation>() = c.tdoa_loss;
  e.solver.loss<BearingObservation>() = c.bearing_loss;
  e.solver.ceres_covariance = c.ceres_covariance;
  e.solver.prior_range = c.default_range;
  e.kalman.model = c.motion_model;
  e.kalman.dims = c.planar ? 2 : 3;
  e.kalman.process_noise = c.process_noise;
  e.kalman.gate_probability = c.gate_probability;
  e.kalman.max_consecutive_rejections = c.max_consecutive_rejections;
  e.initializer.planar = c.planar;
  e.initializer.height = c.height;
  e.initializer.default_range = c.default_range;
  e.aoa = c.aoa;
  e.azimuth_sigma = c.azimuth_sigma;
  e.elevation_sigma = c.elevation_sigma;
  e.use_elevation = c.use_elevation;
  e.max_position_sigma = c.max_position_sigma;
  e.max_relative_sigma = c.max_relative_sigma;
  e.ambiguity_margin = c.ambiguity_margin;
  e.filter_uses_solver_covariance = c.filter_uses_solver_covariance;
  e.measurement_noise = c.measurement_noise;
  return e;
}

ParticleTrackerConfig LocatorConfig::tracker() const {
  const LocatorConfig& c = *this;
  ParticleTrackerConfig t;
  t.filter.particles = static_cast<std::size_t>(c.particles);
  t.filter.planar = c.planar;
  t.filter.height = c.height;
  t.filter.process_noise = c.process_noise;
  t.filter.stand_time = c.stand_time;
  t.filter.walk_time = c.walk_time;
  t.filter.stand_noise = c.stand_noise;
  RangeReading::Tuning& range = t.of<RangeReading>();
  range.likelihood.sigma = c.range_sigma;
  range.likelihood.outlier_share = c.range_outlier_share;
  range.likelihood.outlier_length = c.range_outlier_length;
  range.decorrelation_time = c.range_decorrelation_time;
  range.bias_sigma = c.range_bias_sigma;
  TdoaReading::Tuning& tdoa = t.of<TdoaReading>();
  tdoa.likelihood.sigma = c.range_sigma;  // each difference weighs with its own sigma
  tdoa.likelihood.outlier_share = c.range_outlier_share;
  tdoa.likelihood.outlier_length = c.range_outlier_length;
  tdoa.bias_sigma = c.tdoa_bias_sigma;
  BearingReading::Tuning& bearing = t.of<BearingReading>();
  bearing.likelihood.azimuth_sigma = c.azimuth_sigma;
  bearing.likelihood.elevation_sigma = c.elevation_sigma;
  bearing.likelihood.use_elevation = c.use_elevation;
  bearing.likelihood.outlier_share = c.bearing_outlier_share;
  bearing.likelihood.elevation_outlier_share = c.elevation_outlier_share;
  bearing.decorrelation_time = c.bearing_decorrelation_time;
  bearing.bias_sigma = c.azimuth_bias_sigma;
  t.max_age = c.max_age;
  t.ambiguity_margin = c.ambiguity_margin;
  t.max_position_sigma = c.max_position_sigma;
  t.max_relative_sigma = c.max_relative_sigma;
  t.lost_sigma = c.lost_sigma;
  t.default_range = c.default_range;
  t.mirror_memory = c.mirror_memory;
  RssDirectionReading::Tuning& rss = t.of<RssDirectionReading>();
  rss.enabled = c.rss_direction;
  rss.likelihood.gain = c.rss_direction_gain;
  rss.likelihood.sigma = c.rss_direction_sigma;
  // A reflected reading's RSSI is as far off as its angle: the bearings' outlier share.
  rss.likelihood.outlier_share = c.bearing_outlier_share;
  return t;
}

}  // namespace estimation
}  // namespace radio_follow
