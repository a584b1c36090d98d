// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "radio_follow/config/layout.hpp"
#include "radio_follow/estimation/locator.hpp"
#include "radio_follow/evaluation/standing_robot.hpp"
#include "radio_follow/sim/world.hpp"

namespace radio_follow {
namespace evaluation {

/// Issue 14's cold-start benchmark: a robot standing still, a person standing somewhere,
/// the locator started from nothing on the simulator's sensors. How long does an estimate
/// that the controllers would drive to (OK or DEGRADED) sit on the mirror image?
struct ColdStartParams {
  /// Trials first_trial .. first_trial + trials - 1. Each draws from its own generator,
  /// seeded by (seed, its index), so one trial can be run again alone.
  std::size_t first_trial = 0;
  std::size_t trials = 10000;
  double duration = 3.0;      ///< s of sensor data per trial
  double min_distance = 1.5;  ///< m, the person's distance from the robot, uniform
  double max_distance = 8.0;
  /// Hardware seeds cycled over the trials (realistic profile: each its own calibrated
  /// robot).
  int robots = 8;
  std::uint64_t seed = 1;
  /// Called after every update of every trial (trial index, time, estimate, the person);
  /// for tracing one trial. Empty: not called.
  std::function<void(std::size_t, double, const estimation::LocatorEstimate&,
                     const Eigen::Vector3d&)>
      observer;
  /// Called with every range and bearing fed to the locator (trial index, reading, the
  /// person), before the update that applies it; for tracing one trial. Empty: not called.
  std::function<void(std::size_t, const SensorReading&, const Eigen::Vector3d&)> reading_observer;
};

/// A trial whose usable estimate sat on the mirror side for more than 1 s in a row.
struct MirrorLock {
  std::size_t trial = 0;
  std::uint64_t robot = 0;  ///< index into the robots (hardware seed - 1)
  Eigen::Vector3d target = Eigen::Vector3d::Zero();
  double start_s = 0.0;  ///< when its longest run on the mirror began, s into the trial
  double longest_s = 0.0;
};

struct ColdStartResult {
  std::size_t trials = 0;
  /// Every trial whose estimate was on the mirror side (closer to the mirror image than to
  /// the person, the two more than 1 m apart) while OK or DEGRADED for more than 1 s in a
  /// row: the mirror locks.
  std::vector<MirrorLock> locks;
  /// Trials on the mirror side for any time at all.
  std::size_t mirror_any = 0;
  double longest_mirror_s = 0.0;
  /// Trials that reached OK or DEGRADED within the duration; median time to it, s.
  std::size_t usable = 0;
  double median_time_to_usable = 0.0;
  /// Median and 95th percentile of the error of usable estimates after 1 s, m.
  double error_median = 0.0;
  double error_p95 = 0.0;
  /// Mean normalised estimation error squared of those (2D: consistent = 2).
  double nees_mean = 0.0;
  /// Its median (2D: consistent = 1.39, chi-square with 2 degrees of freedom; the mean is
  /// dominated by the few estimates on the mirror) and the share of errors inside the 95 %
  /// ellipse (consistent = 0.95).
  double nees_median = 0.0;
  /// Its 99th percentile and largest value: whether the mean is the bulk's or a few
  /// confident estimates in the wrong place (2D, consistent: p99 9.2).
  double nees_p99 = 0.0;
  double nees_max = 0.0;
  double within_95 = 0.0;
  std::size_t nees_samples = 0;
  std::size_t ambiguous_updates = 0;
  std::size_t updates = 0;
};

/// Runs the trials on `layout` (the sensors as designed) with the sensor profile and
/// noise of `world`; the locator gets locatorLayoutFor()'s calibrated layout per robot.
ColdStartResult runColdStarts(const Layout& layout, sim::WorldConfig world,
                              const estimation::LocatorConfig& locator,
                              const ColdStartParams& params);

}  // namespace evaluation
}  // namespace radio_follow
