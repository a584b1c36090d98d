// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>
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

/// Everything one solve uses: one list per kind. The solver, its Fisher information and
/// the estimate's sources visit the lists through lists(), in its order (the order of the
/// residual blocks), and ask each kind's observation type for its cost, loss and source.
struct ObservationSet {
  std::vector<RangeObservation> ranges;
  std::vector<TdoaObservation> tdoas;
  std::vector<BearingObservation> bearings;

  auto lists() const { return std::tie(ranges, tdoas, bearings); }
  auto lists() { return std::tie(ranges, tdoas, bearings); }

  /// Calls `f` with each kind's list, in lists() order.
  template <typename F>
  void forEach(F&& f) const {
    std::apply([&](const auto&... list) { (f(list), ...); }, lists());
  }
  template <typename F>
  void forEach(F&& f) {
    std::apply([&](auto&... list) { (f(list), ...); }, lists());
  }

  std::size_t size() const {
    std::size_t n = 0;
    forEach([&](const auto& list) { n += list.size(); });
    return n;
  }
  bool empty() const { return size() == 0; }
  void clear() {
    forEach([](auto& list) { list.clear(); });
  }
  /// The source bits (target_status.hpp) of the kinds present.
  std::uint8_t sources() const {
    std::uint8_t bits = 0;
    forEach([&](const auto& list) {
      using Observation = typename std::decay_t<decltype(list)>::value_type;
      bits |= list.empty() ? 0 : Observation::kSource;
    });
    return bits;
  }
};

/// One value per solver kind, in ObservationSet::lists() order, and its index by kind.
template <typename T>
using PerObservationKind =
    std::array<T, std::tuple_size_v<decltype(std::declval<ObservationSet>().lists())>>;

namespace detail {
/// The position of T among Ts (sizeof...(Ts) when absent).
template <typename T, typename... Ts>
constexpr std::size_t indexOf() {
  constexpr bool match[] = {std::is_same_v<T, Ts>...};
  for (std::size_t i = 0; i < sizeof...(Ts); ++i) {
    if (match[i])
      return i;
  }
  return sizeof...(Ts);
}
template <typename Observation, typename Lists>
struct KindIndex;
template <typename Observation, typename... List>
struct KindIndex<Observation, std::tuple<List&...>> {
  static constexpr std::size_t value = indexOf<std::vector<Observation>, List...>();
};
}  // namespace detail

template <typename Observation>
constexpr std::size_t kindIndex() {
  constexpr std::size_t i =
      detail::KindIndex<Observation, decltype(std::declval<ObservationSet&>().lists())>::value;
  static_assert(i < std::tuple_size_v<decltype(std::declval<ObservationSet>().lists())>,
                "not a kind of ObservationSet");
  return i;
}

/// A calibrated reading of one kind, as the particle tracker takes it. The order is that
/// of the sensor keys (SensorKey's first element), by which cold starts and the
/// covariance floor visit the sensors: keep it when adding a kind at the end.
using TrackedReading = std::variant<RangeReading, BearingReading, TdoaReading, RssDirectionReading>;

namespace detail {
template <typename Variant>
struct ReadingTuple;
template <typename... Reading>
struct ReadingTuple<std::variant<Reading...>> {
  using Tunings = std::tuple<typename Reading::Tuning...>;
  template <typename R>
  static constexpr std::size_t index() {
    return indexOf<R, Reading...>();
  }
};
}  // namespace detail

/// Every kind's tuning in the particle tracker (its reading's Tuning), in TrackedReading
/// order: ParticleTrackerConfig::of<Reading>().
using ReadingTunings = detail::ReadingTuple<TrackedReading>::Tunings;

/// A reading type's index in TrackedReading.
template <typename Reading>
constexpr std::size_t readingIndex() {
  constexpr std::size_t i = detail::ReadingTuple<TrackedReading>::index<Reading>();
  static_assert(i < std::variant_size_v<TrackedReading>, "not a kind of TrackedReading");
  return i;
}

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
  template <typename F>
  static void forEach(F&& f) {
    (f(static_cast<const Reading*>(nullptr)), ...);
  }
};
}  // namespace detail

/// The locator node's topics parameters (kTopicsParam), one per kind that has one, in
/// TrackedReading order.
inline std::vector<std::string> topicsParams() {
  std::vector<std::string> names;
  detail::Kinds<TrackedReading>::forEach([&](const auto* kind) {
    using Reading = std::remove_cv_t<std::remove_pointer_t<decltype(kind)>>;
    if (Reading::kTopicsParam != nullptr) {
      names.emplace_back(Reading::kTopicsParam);
    }
  });
  return names;
}

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
