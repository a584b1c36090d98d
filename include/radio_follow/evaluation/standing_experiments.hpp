// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "radio_follow/config/layout.hpp"
#include "radio_follow/estimation/locator.hpp"
#include "radio_follow/sim/target_path.hpp"
#include "radio_follow/sim/world.hpp"

namespace radio_follow {
namespace evaluation {

/// The thesis's Experiment 1 (Section 5.3): the robot stands, the person stands at points
/// around it for a minute each; the locator's estimates at each point are averaged.
struct StaticAccuracyParams {
  std::vector<double> distances{1.5, 2.5, 4.0, 6.0};  ///< m from the robot's origin
  int directions = 16;                                ///< evenly spaced, from straight ahead
  double duration = 60.0;                             ///< s per point (the thesis: one minute)
  double settle = 2.0;      ///< s from the locator's start before estimates count
  std::uint64_t robot = 1;  ///< hardware seed: which simulated robot (calibrated first)
  std::uint64_t seed = 1;   ///< the noise

  void validate() const;
};

/// One point of Experiment 1.
struct StaticPoint {
  double distance = 0.0;   ///< m
  double direction = 0.0;  ///< rad, counter-clockwise from the robot's x axis
  /// |mean of the estimates - true position| in the plane, m (the thesis's Figures 5.10,
  /// 5.13, 5.16, 5.19, 5.22).
  double mean_error = 0.0;
  /// Spread of the estimates about their mean, sqrt(var x + var y), m (Figures 5.11,
  /// 5.14, 5.17, 5.20, 5.23).
  double spread = 0.0;
  /// Share of the locator's updates after `settle` with a position (OK or DEGRADED).
  double usable = 0.0;
};

std::vector<StaticPoint> runStaticAccuracy(const Layout& layout, sim::WorldConfig world,
                                           const estimation::LocatorConfig& locator,
                                           const StaticAccuracyParams& params);

/// The thesis's Experiment 2 (Section 5.4): the robot stands, the person walks a path
/// around it (`path`, in the robot frame).
struct WalkAroundParams {
  double settle = 2.0;  ///< s before errors count (the locator starts with the walk)
  std::uint64_t robot = 1;
  std::uint64_t seed = 1;
};

/// One locator update of Experiment 2.
struct WalkSample {
  double t = 0.0;
  double direction = 0.0;  ///< of the true position, rad
  double distance = 0.0;   ///< of the true position, m
  bool usable = false;     ///< OK or DEGRADED
  double error = 0.0;      ///< |estimate - truth| in the plane when usable, m
  /// |direction of the estimate - direction of the truth| when the estimate has one
  /// (usable or HEADING_ONLY: the TDoA heading mode), rad; NaN otherwise.
  double heading_error = 0.0;
};

std::vector<WalkSample> runWalkAround(const Layout& layout, sim::WorldConfig world,
                                      const estimation::LocatorConfig& locator,
                                      const sim::TargetPath& path, double duration,
                                      const WalkAroundParams& params);

/// Figures by direction, as the thesis's histograms: `sectors` equal sectors, the first
/// centred on straight ahead.
struct DirectionSector {
  double centre_deg = 0.0;
  std::size_t count = 0;  ///< points or usable samples in it
  double max_mean_error = 0.0;
  double max_spread = 0.0;
  double median_error = 0.0;  ///< Experiment 2
  double p95_error = 0.0;     ///< Experiment 2
  double usable = 0.0;        ///< share
  /// Experiment 2: heading error of the samples with a direction, deg (NaN without).
  double heading_median_deg = 0.0;
  double heading_p95_deg = 0.0;
};

/// Index of the sector of `direction` (rad) among `sectors`.
std::size_t sectorOf(double direction, int sectors);
std::vector<DirectionSector> bySector(const std::vector<StaticPoint>& points, int sectors);
std::vector<DirectionSector> bySector(const std::vector<WalkSample>& samples, int sectors);

/// Experiment 1's points by distance from the robot, in the order of `distances`.
struct DistanceRow {
  double distance = 0.0;
  double median_mean_error = 0.0;  ///< over the directions, m
  double max_mean_error = 0.0;
  double max_spread = 0.0;
};
std::vector<DistanceRow> byDistance(const std::vector<StaticPoint>& points,
                                    const std::vector<double>& distances);

/// `layout` without its AoA boards: the thesis's "TWR only" configuration.
Layout twrOnly(const Layout& layout);

}  // namespace evaluation
}  // namespace radio_follow
