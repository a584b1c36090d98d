// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/estimation/locator.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "radio_follow/common/param_error.hpp"
#include "radio_follow/common/plausibility.hpp"

namespace radio_follow {
namespace estimation {

namespace {

const LocatorConfig& validated(const LocatorConfig& config) {
  config.validate();
  return config;
}

}  // namespace

Locator::Locator(const Layout& layout, const LocatorConfig& config)
    : layout_(layout),
      config_(validated(config)),
      solver_(layout.aoa_boards.size(), config_.solverEstimator()),
      particle_(layout, config_.tracker()),
      tdoa_calibration_(layout, config_.tdoa_calibration),
      ranges_(layout.twr_modules.size()),
      bearings_(layout.aoa_boards.size()) {}

PositionEstimator& Locator::active() {
  if (config_.estimator == Estimator::kParticle) {
    return particle_;
  }
  return solver_;
}

bool Locator::setConfig(const LocatorConfig& config) {
  config.validate();
  require(config.planar == config_.planar, "mode", std::string(config.planar ? "2d" : "3d"),
          std::string("the mode the locator started with (") + (config_.planar ? "2d" : "3d") +
              "): it sets the size of the filter's state");
  const bool estimator_changed = config.estimator != config_.estimator;
  // The solver estimator builds its new solver first and may throw; nothing after it does:
  // the new tuning is applied entirely or not at all.
  const bool kept = solver_.setConfig(config.solverEstimator());
  particle_.setConfig(config.tracker());
  config_ = config;
  tdoa_calibration_.setConfig(config_.tdoa_calibration);
  if (estimator_changed) {
    solver_.reset();
    particle_.reset();
    return false;
  }
  return kept;
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
  if (slot.valid) {
    active().add({t, pose, RangeReading{module, slot.range}}, 0.0);
  }
  return slot.valid;
}

bool Locator::addBearing(std::size_t index, double azimuth, double elevation, double rssi, double t,
                         const std::optional<Pose2>& pose) {
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
  // The solver's board selection keeps its RSSI history whichever estimator is active.
  solver_.recordRssi(index, rssi);
  active().add({t, pose, BearingReading{index, azimuth, elevation}}, rssi);
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
  active().add({t, pose, TdoaReading{ia, ib, difference, slot->sigma}}, 0.0);
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

LocatorEstimate Locator::update(double now) {
  ++stats_.updates;
  if (time_.jumpedBack(now)) {
    // Every slot and the estimators' time are in the old clock's future: start over.
    for (auto& slot : ranges_) {
      slot.valid = false;
    }
    for (auto& slot : bearings_) {
      slot.valid = false;
    }
    tdoas_.clear();
    solver_.reset();
    particle_.reset();
  }
  LocatorEstimate out;
  out.solver_cost = std::numeric_limits<double>::quiet_NaN();
  FreshMeasurements current;
  for (std::size_t i = 0; i < ranges_.size(); ++i) {
    if (!fresh(ranges_[i], now))
      continue;
    RangeObservation z;
    z.module = layout_.twr_modules[i].position;
    z.range = ranges_[i].range;
    z.sigma = config_.range_sigma;
    current.obs.ranges.push_back(z);
    out.ranges_used.push_back(i);
    out.ranges_m.push_back(z.range);
    current.newest = std::max(current.newest, ranges_[i].t);
  }
  for (auto& slot : tdoas_) {
    if (!fresh(slot, now))
      continue;
    TdoaObservation z;
    z.anchor_a = layout_.tdoa_anchors[slot.a].position;
    z.anchor_b = layout_.tdoa_anchors[slot.b].position;
    z.difference = slot.difference;
    z.sigma = slot.sigma;
    current.obs.tdoas.push_back(z);
    current.newest = std::max(current.newest, slot.t);
  }
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
    current.boards.push_back(c);
    current.angles.emplace_back(bearings_[i].azimuth, bearings_[i].elevation);
    current.bearing_stamps.push_back(bearings_[i].t);
    out.bearings_fresh.push_back(i);
    out.bearing_angles.emplace_back(bearings_[i].azimuth, bearings_[i].elevation);
  }
  return active().estimate(now, current, out, stats_);
}

}  // namespace estimation
}  // namespace radio_follow
