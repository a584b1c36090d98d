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
/// `corridor`: the nearest return inside the strip the robot sweeps driving straight on,
/// as its distance ahead (x) of the scanner, the strip `corridor_half_width` to each side
/// (side_threshold): an obstacle at 40 deg and 0.4 m, outside the centre sector, is
/// 0.3 m ahead in it.
struct SectorRanges {
  double left;
  double centre;
  double centre_narrow;
  double right;
  double corridor;
};

/// Sectors from a planar scan whose angles are in the robot frame (x forward, CCW).
/// Returns outside [range_min, range_max] and non-finite ones are ignored.
SectorRanges scanSectors(const std::vector<float>& ranges, double angle_min, double angle_increment,
                         double range_min, double range_max, double corridor_half_width);

/// Bends or stops `command`; it only ever lowers the forward speed.
/// Rules (the paper's flowchart rebuilt from its text, doc/control/homing.md, "Obstacle
/// avoidance"):
///  1. centre or centre 2 below stop_threshold: no forward motion, turn in place to
///     the freer side;
///  2. centre below obstacle_threshold: forward speed scaled by how far the obstacle is
///     between the two thresholds, turn to the freer side;
///  3. a side below side_threshold: turn away from it (keeps the speed of rules 1-2).
/// Rules 1-2 take the nearer of the centre sector and the corridor: the paper's sectors
/// alone let the robot drive on, turning away at its rate limits, into an obstacle at
/// 30-60 deg within side_threshold (a wall's corner it follows the person round).
VelocityCommand avoidObstacles(const VelocityCommand& command, const SectorRanges& sectors,
                               const AvoidanceParams& params);

}  // namespace control
}  // namespace radio_follow
