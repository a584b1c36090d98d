// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <random>
#include <string>
#include <vector>

#include "radio_follow/common/angles.hpp"
#include "radio_follow/common/param_table.hpp"
#include "radio_follow/sim/robot.hpp"

namespace radio_follow {
namespace sim {

/// A round obstacle (a post, a tree, a person standing by) in the world frame.
struct CircleObstacle {
  double x = 0.0;
  double y = 0.0;
  double radius = 0.1;  ///< m
};

/// A wall segment in the world frame.
struct WallObstacle {
  double x1 = 0.0, y1 = 0.0, x2 = 0.0, y2 = 0.0;  ///< m
};

struct Obstacles {
  std::vector<CircleObstacle> circles;
  std::vector<WallObstacle> walls;

  bool empty() const { return circles.empty() && walls.empty(); }
};

/// Parameters of a simulated planar laser scanner mounted at the robot's origin.
struct ScanConfig {
  double angle_min = deg2rad(-135.0);  ///< rad
  double angle_max = deg2rad(135.0);   ///< rad
  int beams = 271;
  double range_min = 0.05;  ///< m
  double range_max = 10.0;  ///< m
  double sigma = 0.01;      ///< m, range noise
  double rate = 10.0;       ///< Hz; a scan is published only when the scenario has obstacles

  /// `scan/rate`, `scan/angle_min_deg`, `scan/angle_max_deg`, `scan/beams`,
  /// `scan/range_min`, `scan/range_max`, `scan/sigma` (config/simulator.yaml).
  static const ParamTable<ScanConfig>& table();
  void load(const ParamSource& source);
  void validate() const;
  /// Angle between neighbouring beams, rad.
  double angleIncrement() const { return (angle_max - angle_min) / (beams - 1); }
};

/// Distance along the ray from (x, y) in direction `angle` (world) to the first obstacle,
/// or +infinity when nothing is hit.
double castRay(const Obstacles& obstacles, double x, double y, double angle);

/// Noise-free ranges of every beam for a robot at `pose` (beams beyond range_max are
/// +infinity, as REP-117 asks for "no return").
std::vector<double> scanRanges(const Obstacles& obstacles, const ScanConfig& config,
                               const Pose2& pose);

/// What the scanner reports at `pose`: scanRanges plus a draw of `noise` (normal, sd
/// `config.sigma`; the caller keeps it, so its state carries over as the caller decides)
/// on every return, never below 0; no return stays +infinity.
std::vector<float> noisyScan(const Obstacles& obstacles, const ScanConfig& config,
                             const Pose2& pose, std::normal_distribution<double>& noise,
                             std::mt19937_64& rng);

/// Distance from (x, y) to the nearest obstacle surface (negative inside a circle).
double clearance(const Obstacles& obstacles, double x, double y);

}  // namespace sim
}  // namespace radio_follow
