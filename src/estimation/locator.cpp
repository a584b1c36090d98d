// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/estimation/locator.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <utility>

#include "radio_follow/common/param_error.hpp"
#include "radio_follow/common/plausibility.hpp"
#include "radio_follow/estimation/mirror_axis.hpp"

namespace radio_follow {
namespace estimation {

namespace {

/// A second solution closer than this to the first is the same answer, m.
constexpr double kMinMirrorSeparation = 0.5;
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

const LocatorConfig& validated(const LocatorConfig& config) {
  config.validate();
  return config;
}

}  // namespace

Locator::Locator(const Layout& layout, const LocatorConfig& config)
    : layout_(layout),
      config_(validated(config)),
      init_config_(config_.initializer()),
      solver_(std::make_unique<PositionSolver>(config_.solver())),
      selector_(layout.aoa_boards.size(), config_.aoa),
      filter_(config_.kalman()),
      tracker_(layout, config_.tracker()),
      rss_(layout.aoa_boards),
      tdoa_calibration_(layout, config_.tdoa_calibration),
      ranges_(layout.twr_modules.size()),
      bearings_(layout.aoa_boards.size()) {}

bool Locator::setConfig(const LocatorConfig& config) {
  config.validate();
  require(config.planar == config_.planar, "mode", std::string(config.planar ? "2d" : "3d"),
          std::string("the mode the locator started with (") + (config_.planar ? "2d" : "3d") +
              "): it sets the size of the filter's state");
  const bool selection_changed = config.aoa.mode != config_.aoa.mode ||
                                 config.aoa.rssi_window != config_.aoa.rssi_window ||
                                 config.aoa.vote_window != config_.aoa.vote_window;
  const bool estimator_changed = config.estimator != config_.estimator;
  auto solver = std::make_unique<PositionSolver>(config.solver());
  // Nothing below throws: the new tuning is applied entirely or not at all.
  config_ = config;
  solver_ = std::move(solver);
  if (selection_changed) {
    selector_ = AoaSelector(layout_.aoa_boards.size(), config_.aoa);
  }
  init_config_ = config_.initializer();
  tracker_.setConfig(config_.tracker());
  tdoa_calibration_.setConfig(config_.tdoa_calibration);
  if (estimator_changed) {
    tracker_.reset();
    filter_.reset();
    warm_.reset();
    return false;
  }
  return filter_.reconfigure(config_.kalman());
}

bool Locator::addRange(std::size_t module, double raw_range, double t,
                       const std::optional<Pose2>& pose) {
  // The drivers' bounds (plausibility.hpp), and 0 m is no range to solve with.
  if (module >= layout_.twr_modules.size() || !plausibleRange(raw_range) || raw_range <= 0.0 ||
      !std::isfinite(t)) {
    ++stats_.invalid_measurements;
    return false;
  }
  RangeSlot& slot = ranges_[module];
  slot.range = layout_.twr_modules[module].correctRange(raw_range);
  slot.t = t;
  slot.valid = slot.range > 0.0;
  if (slot.valid && config_.estimator == Estimator::kParticle) {
    TrackedMeasurement m;
    m.kind = TrackedMeasurement::Kind::kRange;
    m.t = t;
    m.pose = pose;
    m.sensor = module;
    m.value = slot.range;
    tracker_.add(m);
  }
  return slot.valid;
}

bool Locator::addBearing(std::size_t index, double azimuth, double elevation, double rssi,
                         double t, const std::optional<Pose2>& pose) {
  if (index >= layout_.aoa_boards.size() || !plausibleAngleRad(azimuth) ||
      !plausibleAngleRad(elevation) || !std::isfinite(t)) {
    ++stats_.invalid_measurements;
    return false;
  }
  // The board's calibrated elevation offset (a real board reads low): both estimators,
  // and the published bearing, see the corrected elevation.
  elevation =
      std::clamp(elevation - layout_.aoa_boards[index].elevation_offset, -0.5 * kPi, 0.5 * kPi);
  BearingSlot& slot = bearings_[index];
  slot.azimuth = azimuth;
  slot.elevation = elevation;
  slot.rssi = rssi;
  slot.t = t;
  slot.valid = true;
  selector_.recordRssi(index, rssi);
  if (config_.estimator == Estimator::kParticle) {
    TrackedMeasurement m;
    m.kind = TrackedMeasurement::Kind::kBearing;
    m.t = t;
    m.pose = pose;
    m.sensor = index;
    m.value = azimuth;
    m.elevation = elevation;
    tracker_.add(m);
    if (config_.rss_direction) {
      if (const std::optional<RssDifference> d = rss_.add(index, rssi, t)) {
        TrackedMeasurement r;
        r.kind = TrackedMeasurement::Kind::kRssDirection;
        r.t = d->t;
        r.pose = pose;  // the pair's readings are within 0.1 s of this one
        r.sensor = d->pair;
        r.value = d->difference;
        tracker_.add(r);
      }
    }
  }
  return true;
}

bool Locator::addTdoaCalibration(std::size_t module, std::size_t a, std::size_t b,
                                 double difference, double t) {
  // TdoaCalibration::add refuses an unknown module or anchor.
  if (!plausibleDistanceDifference(difference) ||
      !tdoa_calibration_.add(module, a, b, difference, t)) {
    ++stats_.invalid_measurements;
    return false;
  }
  ++stats_.tdoa_calibration_differences;
  return true;
}

bool Locator::addTdoa(std::size_t ia, std::size_t ib, double difference, double variance, double t,
                      const std::optional<Pose2>& pose) {
  const std::size_t anchors = layout_.tdoa_anchors.size();
  if (ia >= anchors || ib >= anchors || ia == ib || !plausibleDistanceDifference(difference) ||
      !std::isfinite(t)) {
    ++stats_.invalid_measurements;
    return false;
  }
  if (tdoa_calibration_.active()) {
    const std::optional<double> offset = tdoa_calibration_.offset(ia, ib);
    if (!offset) {
      ++stats_.tdoa_uncalibrated;  // an uncorrected offset would turn the heading
      return true;
    }
    difference -= *offset;
  }
  TdoaSlot* slot = nullptr;
  for (auto& s : tdoas_) {
    if (s.a == ia && s.b == ib)
      slot = &s;
  }
  if (slot == nullptr) {
    tdoas_.emplace_back();
    slot = &tdoas_.back();
    slot->a = ia;
    slot->b = ib;
  }
  slot->difference = difference;
  slot->sigma =
      variance > 0.0 && std::isfinite(variance) ? std::sqrt(variance) : config_.tdoa_sigma;
  slot->t = t;
  slot->valid = true;
  if (config_.estimator == Estimator::kParticle) {
    TrackedMeasurement m;
    m.kind = TrackedMeasurement::Kind::kTdoa;
    m.t = t;
    m.pose = pose;
    m.sensor = ia;
    m.sensor_b = ib;
    m.value = difference;
    m.sigma = slot->sigma;
    tracker_.add(m);
  }
  return true;
}

bool Locator::fresh(Stamped& slot, double now) {
  if (!slot.valid) {
    return false;
  }
  if (now - slot.t > config_.max_age) {
    slot.valid = false;
    ++stats_.stale_dropped;
    return false;
  }
  if (time_.check(slot.t, now) == TimePolicy::Verdict::kFuture) {
    // It would stay "fresh" for as long as it leads the clock (the estimate kept OK with
    // no input at all); a clock mismatch must show as lost data, not as a frozen target.
    slot.valid = false;
    ++stats_.future_dropped;
    return false;
  }
  return true;
}

LocatorEstimate Locator::lose(LocatorEstimate estimate) {
  estimate.status = TargetStatus::kLost;
  ++stats_.lost;
  warm_.reset();
  filter_.reset();
  selector_.reset();
  forgetSide();
  return estimate;
}

void Locator::forgetSide() {
  side_votes_ = 0;
  side_confirmed_ = false;
}

bool Locator::mirrorAmbiguous(const ObservationSet& obs, const SolveResult& solution,
                              double sigma) {
  if (config_.ambiguity_margin <= 0.0 || !config_.planar) {
    return false;
  }
  if (side_confirmed_ && (!obs.bearings.empty() || !obs.tdoas.empty())) {
    // A bearing (or a distance difference) of a confirmed track: the mirror's residual is
    // tens of sigmas, the test would only repeat what it found. Range-only epochs keep
    // testing, so that a track that drifts onto the wrong side is caught.
    return false;
  }
  const std::optional<Eigen::Vector3d> mirrored = mirrorImage(obs, solution.position);
  if (!mirrored || (*mirrored - solution.position).head<2>().norm() <= kMinMirrorSeparation) {
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
  if (!(separation > std::max(kMinMirrorSeparation, 3.0 * sigma))) {
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

LocatorEstimate Locator::update(double now) {
  ++stats_.updates;
  if (time_.jumpedBack(now)) {
    // Every slot and the filter's time are in the old clock's future: start over.
    for (auto& slot : ranges_) {
      slot.valid = false;
    }
    for (auto& slot : bearings_) {
      slot.valid = false;
    }
    tdoas_.clear();
    warm_.reset();
    filter_.reset();
    tracker_.reset();
    forgetSide();
  }
  LocatorEstimate out;
  out.solver_cost = std::numeric_limits<double>::quiet_NaN();
  ObservationSet obs;
  double newest = -std::numeric_limits<double>::infinity();

  for (std::size_t i = 0; i < ranges_.size(); ++i) {
    if (!fresh(ranges_[i], now))
      continue;
    RangeObservation z;
    z.module = layout_.twr_modules[i].position;
    z.range = ranges_[i].range;
    z.sigma = config_.range_sigma;
    obs.ranges.push_back(z);
    out.ranges_used.push_back(i);
    out.ranges_m.push_back(z.range);
    newest = std::max(newest, ranges_[i].t);
  }
  for (auto& slot : tdoas_) {
    if (!fresh(slot, now))
      continue;
    TdoaObservation z;
    z.anchor_a = layout_.tdoa_anchors[slot.a].position;
    z.anchor_b = layout_.tdoa_anchors[slot.b].position;
    z.difference = slot.difference;
    z.sigma = slot.sigma;
    obs.tdoas.push_back(z);
    newest = std::max(newest, slot.t);
  }

  // Bearings: which boards may speak depends on where the target is believed to be.
  std::vector<AoaCandidate> candidates;
  for (std::size_t i = 0; i < bearings_.size(); ++i) {
    if (!fresh(bearings_[i], now))
      continue;
    const AoaBoard& board = layout_.aoa_boards[i];
    AoaCandidate c;
    c.board = i;
    c.position = board.position;
    c.rotation = board.orientation.toRotationMatrix();
    c.field_of_view = board.field_of_view;
    c.rssi = bearings_[i].rssi;
    candidates.push_back(c);
    out.bearings_fresh.push_back(i);
    out.bearing_angles.emplace_back(bearings_[i].azimuth, bearings_[i].elevation);
  }
  if (config_.estimator == Estimator::kParticle) {
    return updateParticle(now, out);
  }
  std::optional<Eigen::Vector3d> believed;
  if (warm_ && warm_ranged_) {
    believed = warm_;
  } else {
    believed = trilaterate(obs.ranges, init_config_);
  }
  const std::vector<std::size_t> chosen = selector_.select(candidates, believed);
  stats_.bearings_rejected_fov += candidates.size() - chosen.size();
  for (std::size_t k : chosen) {
    const std::size_t i = candidates[k].board;
    BearingObservation z;
    z.board = candidates[k].position;
    z.rotation = candidates[k].rotation;
    z.azimuth = bearings_[i].azimuth;
    z.elevation = bearings_[i].elevation;
    z.sigma_azimuth = config_.azimuth_sigma;
    z.sigma_elevation = config_.elevation_sigma;
    z.use_elevation = config_.use_elevation;
    obs.bearings.push_back(z);
    out.bearings_used.push_back(i);
    newest = std::max(newest, bearings_[i].t);
  }
  out.sources = (obs.ranges.empty() ? 0 : kSourceTwr) | (obs.tdoas.empty() ? 0 : kSourceTdoa) |
                (obs.bearings.empty() ? 0 : kSourceAoa);
  out.stamp = std::isfinite(newest) ? newest : now;

  // Is the position determined at all by what is fresh?
  const bool ranged = !obs.ranges.empty();
  const bool helpers = !obs.bearings.empty() || !obs.tdoas.empty();
  const std::size_t full_ranges = config_.planar ? 3 : 4;
  const bool warm_usable = warm_.has_value() && warm_ranged_ == ranged;
  if (obs.empty() || (ranged && !helpers && obs.ranges.size() < full_ranges - 1) ||
      (ranged && !helpers && obs.ranges.size() < full_ranges && !warm_usable)) {
    return lose(out);
  }

  const auto start = std::chrono::steady_clock::now();
  SolveResult result;
  if (warm_usable) {
    result = solver_->solve(obs, *warm_);
  } else if (const auto guess = trilaterate(obs.ranges, init_config_)) {
    result = solver_->solveCold(obs, *guess);
  } else {
    result = solver_->solveMultiStart(obs, multiStartCandidates(obs, init_config_));
  }
  stats_.last_solve_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ++stats_.solves;
  if (!result.success || !result.position.allFinite()) {
    ++stats_.solver_failures;
    return lose(out);
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
    ++stats_.ambiguous;
  }

  const int d = config_.planar ? 2 : 3;
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
  if (config_.planar) {
    out.position.z() = config_.height;
  }
  if (!out.position.allFinite() || !out.velocity.allFinite() || !out.covariance.allFinite()) {
    ++stats_.non_finite;  // never hand a NaN to a controller; the next epoch starts cold
    return lose(out);
  }
  return out;
}

LocatorEstimate Locator::updateParticle(double now, LocatorEstimate out) {
  const auto start = std::chrono::steady_clock::now();
  const TrackerOutput track = tracker_.update(now);
  stats_.last_solve_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ++stats_.solves;
  // The filter weighs every bearing; those of boards whose field of view does not contain
  // the estimate count at a sixth of their weight (particle_filter.hpp): "not used" for the
  // markers and diagnostics, as the solver's selection would say.
  out.bearings_used.clear();
  out.sources = track.sources;
  out.in_odom = track.in_odom;
  if (track.status == TargetStatus::kLost) {
    out.status = TargetStatus::kLost;
    ++stats_.lost;
    return out;
  }
  out.stamp = track.stamp;
  out.robot_pose = track.pose;
  out.tracking_position = track.position;
  out.tracking_velocity.head<2>() = track.velocity;
  out.tracking_covariance = track.covariance;
  const Eigen::Matrix3d rotation =
      Eigen::AngleAxisd(track.pose.yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  out.position = track.pose.fromFixed(track.position);
  out.velocity = rotation.transpose() * out.tracking_velocity;
  out.covariance = rotation.transpose() * track.covariance * rotation;
  out.alternative = track.pose.fromFixed(track.alternative);
  out.hypotheses = track.hypotheses;
  out.hypothesis_weight = track.hypothesis_weight;
  out.status = track.status;
  for (const std::size_t i : out.bearings_fresh) {
    const AoaBoard& board = layout_.aoa_boards[i];
    const Eigen::Vector3d local = board.orientation.conjugate() * (out.position - board.position);
    if (local.x() > std::cos(board.field_of_view) * local.head<2>().norm()) {
      out.bearings_used.push_back(i);
    }
  }
  stats_.bearings_rejected_fov += out.bearings_fresh.size() - out.bearings_used.size();
  if (config_.planar) {
    out.position.z() = config_.height;
    out.alternative.z() = config_.height;
  }
  if (!out.position.allFinite() || !out.velocity.allFinite() || !out.covariance.allFinite()) {
    ++stats_.non_finite;
    tracker_.reset();
    out.status = TargetStatus::kLost;
    ++stats_.lost;
    return out;
  }
  if (out.status == TargetStatus::kAmbiguous) {
    ++stats_.ambiguous;
  }
  return out;
}

}  // namespace estimation
}  // namespace radio_follow
