// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "radio_follow/config/layout.hpp"
#include "radio_follow/estimation/locator.hpp"
#include "radio_follow/sim/world.hpp"

namespace radio_follow {
namespace evaluation {

/// Issue 35's bench: the kit as a user buys it. A parked robot whose only sensor is one
/// AoA board (no range, so the locator gives HEADING_ONLY), the board as designed (no yaw
/// calibration), and a person who stays in front of it: each walk goes from waypoint to
/// waypoint in the board's front sector and stands still between some of them. Is the
/// locator's heading better than the board's newest raw reading, and does it ever end on
/// the behind hypothesis?
struct HeadingWalkParams {
  int walks = 1000;
  double duration = 60.0;                  ///< s per walk
  double settle = 2.0;                     ///< s from the walk's start before errors count
  double min_distance = 1.5;               ///< m from the board
  double max_distance = 6.0;               ///< m
  double max_direction = 0.87;             ///< rad (50 deg) either side of the boresight
  double speed = 1.0;                      ///< m/s while walking
  double stand_probability = 0.4;          ///< chance the person stands at a waypoint
  double min_stand = 5.0;                  ///< s
  double max_stand = 30.0;                 ///< s
  int robots = 8;                          ///< walk k uses hardware seed 1 + k % robots
  std::uint64_t seed = 1;                  ///< the walks and the noise

  void validate() const;
};

struct HeadingWalkResult {
  /// Absolute heading errors at every locator update after `settle`, deg, pooled over the
  /// walks: the locator's direction (HEADING_ONLY, OK or DEGRADED) and the newest raw
  /// reading's (the board's yaw plus its azimuth) at the same update.
  std::vector<double> locator_deg;
  std::vector<double> raw_deg;
  std::size_t updates = 0;            ///< after settle, over all walks
  std::size_t without_direction = 0;  ///< updates with no direction from the locator
  int walks = 0;
  /// Walks whose last estimate pointed more than 90 deg away from the person: the
  /// locator ended on the behind hypothesis (the person never left the front).
  int ended_behind = 0;
};

/// Runs the walks with `layout`'s first AoA board alone (placed as the layout has it) and
/// the locator configuration `locator`; with `world`'s realistic profile the board errs as
/// real XPLR-AOA-1 boards do (sim::RealisticFigures).
HeadingWalkResult runHeadingWalks(const Layout& layout, sim::WorldConfig world,
                                  const estimation::LocatorConfig& locator,
                                  const HeadingWalkParams& params);

}  // namespace evaluation
}  // namespace radio_follow
