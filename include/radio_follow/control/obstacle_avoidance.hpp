// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <vector>

#include "radio_follow/control/rate_limiter.hpp"

namespace radio_follow {
namespace control {

/// Thresholds of seed 000's rule-based avoidance (Appendix B, Table A1).
struct AvoidanceParams {
  double obstacle_threshold = 1.5;  ///< obsThreshold1, m: start slowing and bending
  double stop_threshold = 0.35;     ///< obsThreshold2, m: no forward motion
  double side_threshold = 0.4;      ///< sideObsThreshold, m: turn away from a side
  double turn_rate = 0.6;           ///< rad/s used when bending around an obstacle

  /// Names with their `avoidance/` namespace, as the controllers read them.
  static const ParamTable<AvoidanceParams>& table();
  void validate() const;
};

/// Shortest return in each sector of the front half-plane (seed 000 Figure A5):
/// left (30..90 deg), centre (-30..30 deg), right (-90..-30 deg) and the narrow
/// "centre 2" (the middle 20 %, -18..18 deg). Infinity where nothing was seen.
struct SectorRanges {
  double left;
  double centre;
  double centre_narrow;
  double right;
};

/// Sectors from a planar scan whose angles are in the robot frame (x forward, CCW).
/// Returns outside [range_min, range_max] and non-finite ones are ignored.
SectorRanges scanSectors(const std::vector<float>& ranges, double angle_min, double angle_increment,
                         double range_min, double range_max);

/// Bends or stops `command`; it only ever lowers the forward speed.
/// Rules (the paper's flowchart rebuilt from its text, doc/control/homing.md, "Obstacle
/// avoidance"):
///  1. centre or centre 2 below stop_threshold: no forward motion, turn in place to
///     the freer side;
///  2. centre below obstacle_threshold: forward speed scaled by how far the obstacle is
///     between the two thresholds, turn to the freer side;
///  3. a side below side_threshold: turn away from it (keeps the speed of rules 1-2).
VelocityCommand avoidObstacles(const VelocityCommand& command, const SectorRanges& sectors,
                               const AvoidanceParams& params);

}  // namespace control
}  // namespace radio_follow
