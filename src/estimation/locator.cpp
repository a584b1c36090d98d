// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/estimation/locator.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <variant>

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
      tdoa_calibration_(layout, config_.tdoa_calibration) {}

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

bool Locator::add(double t, TrackedReading reading, const std::optional<Pose2>& pose) {
  const LocatorIntake context = intake();
  const Intake verdict = std::isfinite(t)
                             ? std::visit([&](auto& r) { return accept(r, context); }, reading)
                             : Intake::kRefused;
  if (verdict == Intake::kRefused) {
    ++stats_.invalid_measurements;
    return false;
  }
  if (verdict == Intake::kHeld) {
    return true;
  }
  const TrackedMeasurement m{t, pose, std::move(reading)};
  Slot& slot = slots_[sensorKey(m)];
  slot.t = t;
  slot.valid = true;
  slot.reading = m.reading;
  // History an estimator needs when a live switch makes it the active one (the solver's
  // board selection keeps its RSSI history), then the active one's own use.
  solver_.record(m);
  active().add(m);
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

bool Locator::fresh(Slot& slot, double now) {
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
    slots_.clear();
    solver_.reset();
    particle_.reset();
  }
  LocatorEstimate out;
  out.solver_cost = std::numeric_limits<double>::quiet_NaN();
  FreshMeasurements current;
  const LocatorIntake context = intake();
  for (auto& [key, slot] : slots_) {
    if (fresh(slot, now)) {
      std::visit([&](const auto& r) { observe(r, slot.t, context, current, out); }, slot.reading);
    }
  }
  return active().estimate(now, current, out, stats_);
}

}  // namespace estimation
}  // namespace radio_follow
