// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "radio_follow/config/layout.hpp"
#include "radio_follow/sim/obstacles.hpp"
#include "radio_follow/sim/robot.hpp"

namespace radio_follow {
namespace sim {

/// One sample of the target's scripted motion.
struct TargetSample {
  double t = 0.0;      ///< seconds since the scenario start
  Pose2 pose;          ///< position (m) and walking direction (rad) in the world frame
  double speed = 0.0;  ///< m/s
};

/// The target's (person's) motion as a dense, time-stamped polyline, built from a
/// scenario's legs. Queries interpolate; after the last sample the target stands still.
class TargetPath {
 public:
  /// A path that stands at `start` forever (homing to a static beacon).
  explicit TargetPath(const Pose2& start);

  /// Walk in a straight line to (x, y) at `speed` m/s.
  void walkTo(double x, double y, double speed);
  /// Walk an arc of `radius` metres turning by `angle` radians (positive = left) at `speed`.
  void arc(double radius, double angle, double speed);
  /// Stand still for `duration` seconds.
  void wait(double duration);
  /// `steps` straight segments of `step_length` m, each turning by a uniform random
  /// angle within +-`max_turn` rad, at `speed`; deterministic for a given `seed`.
  void randomWalk(int steps, double step_length, double max_turn, double speed, std::uint64_t seed);

  /// Re-times the path so the speed changes at no more than `accel` m/s^2: the person
  /// speeds up from every stand (start, waits) and slows down into every stand (waits,
  /// end) instead of switching between standing and walking speed at once. Positions
  /// are unchanged; call once, after the last leg.
  void limitAcceleration(double accel);

  /// The target at time t (clamped to [0, duration()]).
  TargetSample at(double t) const;
  /// Time the last leg ends, seconds.
  double duration() const { return samples_.back().t; }
  /// Length walked, metres.
  double length() const { return length_; }
  const std::vector<TargetSample>& samples() const { return samples_; }

 private:
  /// Appends a sample reached after walking `distance` metres (default: the chord).
  void append(const Pose2& pose, double speed, double distance = -1.0);

  std::vector<TargetSample> samples_;
  double length_ = 0.0;
};

/// A scenario: where the robot starts, how the target moves, how long it runs.
struct Scenario {
  std::string name;
  Pose2 robot_start;
  TargetPath target{Pose2{}};
  /// The person's acceleration and deceleration, m/s^2 (0: instant speed changes).
  double target_accel = 1.0;
  /// Height of the target's tags above the ground, metres.
  double target_height = kDefaultTargetHeight;
  /// Seconds to simulate; defaults to the target path's end plus `settle_time`.
  double duration = 0.0;
  double settle_time = 10.0;
  /// Obstacles the simulated laser scanner sees (none: no scan is published).
  Obstacles obstacles;
};

/// Reads a scenario from YAML (format in config/scenarios/*.yaml and doc/simulator.md).
/// Throws ParamError naming the bad field. `seed` drives random legs.
Scenario parseScenario(const std::string& yaml_text, const std::string& origin, std::uint64_t seed);
Scenario loadScenarioFile(const std::string& path, std::uint64_t seed);

}  // namespace sim
}  // namespace radio_follow
