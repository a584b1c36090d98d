// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <tuple>
#include <type_traits>
#include <variant>
#include <vector>

#include "radio_follow/common/pose2.hpp"
#include "radio_follow/config/layout.hpp"
#include "radio_follow/estimation/bearing_measurement.hpp"
#include "radio_follow/estimation/range_measurement.hpp"
#include "radio_follow/estimation/rss_direction.hpp"
#include "radio_follow/estimation/tdoa_measurement.hpp"

namespace radio_follow {
namespace estimation {

// The measurement kinds the locator fuses, each in its own file with its observation,
// model, Ceres cost, particle likelihood and answers to the particle tracker:
// range_measurement.hpp, tdoa_measurement.hpp, bearing_measurement.hpp (and
// rss_direction.hpp, which only weighs the particle estimator's hypotheses). This file
// lists them: the solver's ObservationSet and the tracker's TrackedReading.

/// Distance assumed along a bearing when no range exists, m: the one default of the
/// locator's `default_range` (initializer, particle tracker).
constexpr double kDefaultRange = 3.0;

/// Everything one solve uses.
struct ObservationSet {
  std::vector<RangeObservation> ranges;
  std::vector<TdoaObservation> tdoas;
  std::vector<BearingObservation> bearings;

  bool empty() const { return ranges.empty() && tdoas.empty() && bearings.empty(); }
  void clear() {
    ranges.clear();
    tdoas.clear();
    bearings.clear();
  }
};

/// A calibrated reading of one kind, as the particle tracker takes it. The order is that
/// of the sensor keys (SensorKey's first element), by which cold starts and the
/// covariance floor visit the sensors: keep it when adding a kind at the end.
using TrackedReading = std::variant<RangeReading, BearingReading, TdoaReading, RssDirectionReading>;

/// One calibrated reading at its own stamp, with the robot's pose in the tracking frame at
/// that stamp (none: the robot's own frame is the tracking frame).
struct TrackedMeasurement {
  double t = 0.0;
  std::optional<Pose2> pose;
  TrackedReading reading;
};

/// A sensor's identity across kinds: the kind (its TrackedReading index) and its sensors.
using SensorKey = std::tuple<std::size_t, std::size_t, std::size_t>;

inline SensorKey sensorKey(const TrackedMeasurement& m) {
  const SensorPair s = std::visit([](const auto& r) { return r.sensors(); }, m.reading);
  return {m.reading.index(), s.first, s.second};
}

/// The sensor a cold start counts as heard (tracked_reading.hpp), as a key.
inline std::optional<SensorKey> heardKey(const TrackedMeasurement& m) {
  const std::optional<SensorPair> s =
      std::visit([](const auto& r) { return r.heardAs(); }, m.reading);
  return s ? std::optional<SensorKey>(SensorKey{m.reading.index(), s->first, s->second})
           : std::nullopt;
}

inline std::uint8_t sourceOf(const TrackedMeasurement& m) {
  return std::visit([](const auto& r) { return std::decay_t<decltype(r)>::kSource; }, m.reading);
}

inline bool fixesDistance(const TrackedMeasurement& m) {
  return std::visit([](const auto& r) { return std::decay_t<decltype(r)>::kFixesDistance; },
                    m.reading);
}

inline ColdSeed coldSeedOf(const TrackedMeasurement& m) {
  return std::visit([](const auto& r) { return std::decay_t<decltype(r)>::kColdSeed; }, m.reading);
}

namespace detail {
template <typename Variant>
struct Kinds;
template <typename... Reading>
struct Kinds<std::variant<Reading...>> {
  static std::size_t expectedSensors(const Layout& layout, bool distance_only) {
    return ((!distance_only || Reading::kFixesDistance ? Reading::expectedSensors(layout) : 0) +
            ...);
  }
};
}  // namespace detail

/// The sensors of `layout` a cold start waits to hear, over every kind.
inline std::size_t expectedSensors(const Layout& layout) {
  return detail::Kinds<TrackedReading>::expectedSensors(layout, false);
}

/// Whether `layout` has a sensor whose readings fix the distance.
inline bool rangingLayout(const Layout& layout) {
  return detail::Kinds<TrackedReading>::expectedSensors(layout, true) > 0;
}

}  // namespace estimation
}  // namespace radio_follow
