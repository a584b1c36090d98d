// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "radio_follow/config/layout.hpp"
#include "radio_follow/estimation/locator.hpp"
#include "radio_follow/sim/world.hpp"

namespace radio_follow {
namespace evaluation {

/// The person's path relative to the standing robot.
enum class WalkShape {
  /// A straight line past the robot: 12 m long, 1.5-4 m from the robot at its closest.
  kStraight,
  /// An arc of 240 deg around the robot, radius 2.5-5 m.
  kArc,
  /// 10 s of the locator's own motion model: starting like kStraight, the velocity driven
  /// by white acceleration of spectral density `process_noise`. The one walk for which the
  /// bound is a bound (the others are smoother than the model: doc/locator_accuracy.md).
  kModel,
};

/// "straight" / "arc" / "model"; throws ParamError naming `name` otherwise.
WalkShape parseWalkShape(const std::string& text, const std::string& name);
std::string toString(WalkShape shape);

/// Issue 14's Gaussian tracking benchmark: a person walks past a standing robot, every
/// sensor reports at its rate with white Gaussian noise of the ideal profile's sigma (the
/// thesis's tables, no bias), and the locator's error is compared with the posterior
/// Cramer-Rao bound of the same measurements (estimation/posterior_crb.hpp).
struct WalkingPcrbParams {
  std::size_t runs = 100;
  WalkShape shape = WalkShape::kStraight;
  double min_speed = 1.0;  ///< m/s, uniform per run
  double max_speed = 1.4;
  /// Seconds at the start of every run left out of the statistics (cold start; the
  /// bound's prior forgotten).
  double warm_up = 2.0;
  /// The bound's prior: position and velocity standard deviations per axis.
  double prior_position_sigma = 3.0;  ///< m
  double prior_velocity_sigma = 1.5;  ///< m/s
  std::uint64_t seed = 1;
};

struct WalkingPcrbResult {
  std::size_t runs = 0;
  std::size_t samples = 0;           ///< updates after the warm-up with a position
  std::size_t without_position = 0;  ///< ... and without one (LOST, SEARCHING)
  double rmse = 0.0;                 ///< sqrt(mean squared planar error), m
  /// sqrt(mean trace of the position bound) over the same samples, m: every measurement
  /// counted (every range and every bearing, behind-the-board ones included).
  double pcrb = 0.0;
  /// The same, counting only bearings of boards whose field of view contains the person
  /// (what the locator weighs fully), m.
  double pcrb_in_fov = 0.0;
  /// Mean signed error along the walking direction (positive: ahead of the person), m.
  double along_mean = 0.0;
  /// Mean signed error across it (positive: to the person's left), m.
  double across_mean = 0.0;
  /// Runs whose error exceeded 1 m after the warm-up (a mirror or a lost track).
  std::size_t runs_over_1m = 0;
  double median_error = 0.0;  ///< m
};

/// Runs the benchmark on `layout` (the robot standing at the origin of its frame, the
/// layout's frame) with the sensor rates and sigma scales of `world` (its biases are
/// turned off: a Gaussian case) and the locator tuned by `locator`, updating at
/// `locator_rate` Hz; the locator's layout has identity range calibrations (the ranges
/// are unbiased). The bound uses the locator's own motion model: constant velocity,
/// white acceleration of spectral density `locator.process_noise`.
WalkingPcrbResult runWalkingPcrb(const Layout& layout, sim::WorldConfig world,
                                 const estimation::LocatorConfig& locator, double locator_rate,
                                 const WalkingPcrbParams& params);

}  // namespace evaluation
}  // namespace radio_follow
