// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstddef>
#include <limits>
#include <utility>

namespace radio_follow {
namespace estimation {

// What the particle tracker asks of a measurement kind. Each kind's reading type
// (RangeReading, BearingReading, TdoaReading, RssDirectionReading) answers in its own
// file, next to its likelihood, so that the tracker's files name no kind:
//   - `static constexpr std::uint8_t kSource`: its bit of TargetEstimate.sources;
//   - `static constexpr bool kFixesDistance`: whether it places the target at a distance
//     (a range, a distance difference) or only in a direction;
//   - `static constexpr ColdSeed kColdSeed`: what a cold start samples from it;
//   - `static std::size_t expectedSensors(const Layout&)`: how many of its sensors a cold
//     start waits to hear;
//   - `SensorPair sensors() const`: the sensors it comes from;
//   - `std::optional<SensorPair> heardAs() const`: the sensor a cold start counts as heard;
//   - `static constexpr const char* kTopicsParam`: the locator node's parameter listing its
//     input topics (nullptr: it has none);
//   - free functions taking the reading first: `weigh()` (its likelihood of the
//     particles), `informing()` (its part of the covariance floor), `decorrelation()`,
//     `usable()` (an optional input switched off), and `seedRing()` or `seedRay()` for
//     its ColdSeed.
// The readings are listed once, in measurement_models.hpp's TrackedReading.
//
// The Locator (locator.hpp) asks two more, so that it names no kind either:
//   - `Intake accept(Reading& raw, const LocatorIntake&)`: checks a raw reading against
//     the layout and the plausible bounds and calibrates it in place;
//   - `void observe(const Reading&, double t, const LocatorIntake&, FreshMeasurements&,
//     LocatorEstimate&)`: puts a fresh reading into what the estimators get at an update
//     (the solver's observations) and into the estimate's record of what was used.

struct TrackerContext;     // particle_tracker.hpp: the layout, the tuning, the robot's pose
struct LocatorIntake;      // locator.hpp: the layout, the tuning, the TDoA calibration
struct FreshMeasurements;  // position_estimator.hpp
struct LocatorEstimate;    // locator_types.hpp

/// What the Locator does with a raw reading its kind has checked.
enum class Intake {
  kAccepted,  ///< calibrated: kept as its sensor's newest and handed to the estimator
  kHeld,      ///< valid but not usable yet (a TDoA pair without its offset): counted by the kind
  kRefused,   ///< unknown sensor or implausible value: counted as invalid
};

/// Layout indices of the sensors a reading comes from (the second: a TDoA pair's b).
using SensorPair = std::pair<std::size_t, std::size_t>;

/// What a cold start samples from a reading. The tracker prefers a ring (the smallest),
/// then a disc, then rays: the tighter the shape, the fewer particles are wasted.
enum class ColdSeed {
  kNone,  ///< it weighs the cloud but places nothing (an RSS direction)
  kRing,  ///< a ring around a sensor (a range)
  kDisc,  ///< a disc around the robot (distance differences: hyperbolae, no distance)
  kRay,   ///< a ray along a direction (a bearing)
};

/// A ring a cold start samples: around `centre` (robot frame) at distance `radius`.
struct SeedRing {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  double radius = 0.0;  ///< m
};

/// A ray a cold start samples: from `origin` (robot frame), along (azimuth, elevation) in
/// the frame that `orientation` turns into the robot's.
struct SeedRay {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
  double azimuth = 0.0;    ///< rad
  double elevation = 0.0;  ///< rad
};

/// How fast a sensor's errors decorrelate: its readings closer in time than `time` count
/// as a fraction of one (the tracker scales their sigma by sqrt(time / dt), at most
/// `max_scale`).
struct Decorrelation {
  double time = 0.0;  ///< s; 0: every reading counts fully
  double max_scale = std::numeric_limits<double>::infinity();
};

}  // namespace estimation
}  // namespace radio_follow
