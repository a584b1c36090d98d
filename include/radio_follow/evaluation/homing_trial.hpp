// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "radio_follow/control/command_pipeline.hpp"
#include "radio_follow/control/homing_controller.hpp"
#include "radio_follow/sim/obstacles.hpp"
#include "radio_follow/sim/robot.hpp"

namespace radio_follow {
namespace evaluation {

/// Seed 000 Table 2: uniform noise within +-angle on the bearing and
/// +-(distance_fraction * d + distance_offset) on the distance.
struct HomingNoise {
  std::string name;
  double angle = 0.0;              ///< rad
  double distance_fraction = 0.0;  ///< of the true distance
  double distance_offset = 0.0;    ///< m
};

/// The five configurations of seed 000 Table 2.
std::vector<HomingNoise> seed000NoiseConfigurations();

/// What a homing controller gets each cycle: a bearing and a distance to the beacon,
/// in the robot frame, with the odometry pose at that moment.
struct HomingMeasurement {
  double t = 0.0;         ///< s
  Pose2 odom;             ///< robot pose in the odometry (= world) frame
  double bearing = 0.0;   ///< rad, counter-clockwise from the robot's heading
  double distance = 0.0;  ///< m
};

/// What it answers.
struct HomingCommand {
  double linear = 0.0;   ///< m/s
  double angular = 0.0;  ///< rad/s
  /// Current goal (estimated beacon position) in the odometry frame, when it has one.
  std::optional<double> goal_x;
  std::optional<double> goal_y;
  bool arrived = false;  ///< the controller believes it has reached the beacon
};

/// One cycle of a homing controller under test: a measurement in, its command out.
using HomingStep = std::function<HomingCommand(const HomingMeasurement&)>;

struct HomingTrialConfig {
  sim::RobotLimits robot;
  double rate = 10.0;           ///< controller and measurement rate, Hz
  double time_limit = 120.0;    ///< s
  double success_radius = 1.0;  ///< m (seed 000: "< 1 m from the actual target")
  /// Obstacles in the world frame (seed 000 Table 4); none: the obstacle-free Table 3.
  sim::Obstacles obstacles;
  /// With obstacles: the robot's laser scan (at its origin, each cycle) and the command
  /// pipeline's avoidance (`use_scan`, `avoidance/*`), applied to the law's command as the
  /// node's pipeline applies it. Without `use_scan` the robot drives blind.
  sim::ScanConfig scan;
  bool use_scan = false;
  control::AvoidanceParams avoidance;
  /// The robot's footprint as a circle, m: closer to an obstacle is a collision, which
  /// ends the run as a failure (seed 000's failures: "the robot hitting an obstacle").
  double robot_radius = 0.2;
};

/// One run, with seed 000 Table 3's metrics.
struct HomingResult {
  bool success = false;          ///< arrived within success_radius before the time limit
  double time = 0.0;             ///< s until the controller said "arrived"
  double net_velocity = 0.0;     ///< straight start-end distance / time, m/s
  double goal_error = 0.0;       ///< final goal estimate vs beacon, m
  double final_error = 0.0;      ///< robot at rest after arriving vs beacon, m
  double path_efficiency = 0.0;  ///< straight start-end distance / distance driven
  /// Smallest distance between the robot's footprint and an obstacle, m (+inf without
  /// obstacles); a collision ends the run.
  double min_clearance = 0.0;
  bool collided = false;
};

/// Drives a robot from the origin (facing +x) with `controller` towards a static beacon
/// at (target_x, target_y), feeding it noisy bearings and distances. Deterministic per seed.
HomingResult runHomingTrial(const HomingStep& controller, double target_x, double target_y,
                            const HomingNoise& noise, const HomingTrialConfig& config,
                            std::uint64_t seed);

/// The homing_controller node's parameters as it loads them.
struct HomingNodeParams {
  control::CommandPipelineParams pipeline;  ///< limits, safety, use_scan, avoidance/*
  control::HomingControllerParams law;
};

/// The homing_controller node's parameters as the node loads them from the shipped files
/// (`config_dir`/controller_common.yaml, then homing_controller.yaml, then each of
/// `overlays` on top), strictly: an unknown key or a bad value throws ParamError naming
/// it. The node-only keys (topics, rate, tag filter) are accepted and not used.
HomingNodeParams loadHomingNodeParams(const std::string& config_dir,
                                      const std::vector<std::string>& overlays = {});

/// Seed 000 Table 4's kind of world for one run: `count` obstacles (posts of radius
/// 0.15-0.5 m and wall segments of 1-3 m) uniformly in the (-half_size, half_size)
/// square, one of them across the straight line from `start` to `target`, none within
/// `keep_clear` of either. Deterministic per seed.
sim::Obstacles homingObstacleCourse(double start_x, double start_y, double target_x,
                                    double target_y, int count, double half_size, double keep_clear,
                                    std::uint64_t seed);

/// A fresh control::HomingController (the homing_controller node's law) as a HomingStep.
/// Each cycle feeds it the odometry pose, the distance as a UWB range and the bearing as
/// the azimuth of a board at the robot's centre facing forward, all stamped with the
/// measurement's time, then ticks it at that time. The command is its command, `arrived`
/// its ARRIVED state. `params.distance_source` should be "uwb": the measurement carries
/// no RSSI.
HomingStep homingControllerStep(const control::HomingControllerParams& params);

/// Seed 000's target set: `per_quadrant` uniform random targets in each quadrant of the
/// (-half_size, half_size) square, at least `min_distance` from the origin.
std::vector<std::pair<double, double>> homingTargets(int per_quadrant, double half_size,
                                                     double min_distance, std::uint64_t seed);

/// Means over the successful runs (success rate over all), as in Table 3.
struct HomingSummary {
  int runs = 0;
  double success_rate = 0.0;
  double time = 0.0;
  double net_velocity = 0.0;
  double goal_error = 0.0;
  double final_error = 0.0;
  double path_efficiency = 0.0;
  double min_clearance = 0.0;  ///< smallest over all runs, m
  int collisions = 0;
};
HomingSummary summarize(const std::vector<HomingResult>& results);

}  // namespace evaluation
}  // namespace radio_follow
