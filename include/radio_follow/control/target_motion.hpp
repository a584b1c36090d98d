// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <Eigen/Core>
#include <deque>
#include <optional>

namespace radio_follow {
namespace control {

/// The target's ground velocity from its recent positions in a world-fixed frame
/// (odometry): a least-squares line through the positions of the last `window` seconds.
///
/// Why a world frame: the locator's own velocity is relative to the moving robot, and a
/// feed-forward built from it (relative velocity + the robot's command) feeds the robot's
/// acceleration back into its own command through the filter's lag; in closed loop that
/// oscillated. In a world frame the robot's motion does not enter the estimate.
class TargetMotion {
 public:
  struct Config {
    double window = 1.0;  ///< s of positions the fit uses
    int min_samples = 5;  ///< fewer: no velocity
    /// The samples must span at least this fraction of the window.
    double min_span_fraction = 0.5;
  };

  TargetMotion() : TargetMotion(Config{}) {}
  explicit TargetMotion(const Config& config) : config_(config) {}

  /// A target position (world frame, m) at time t (s). Out-of-order samples are ignored.
  void add(double t, const Eigen::Vector2d& position);
  /// Velocity (m/s, world frame) from the samples within `window` before `now`, or
  /// nullopt when there are too few or they span too short a time.
  std::optional<Eigen::Vector2d> velocity(double now) const;
  void reset() { samples_.clear(); }

 private:
  struct Sample {
    double t;
    Eigen::Vector2d p;
  };
  Config config_;
  std::deque<Sample> samples_;
};

/// The target as the speed feed-forward needs it: its positions placed in the odometry
/// frame (with the robot's pose at each estimate's stamp), its ground speed and its speed
/// away from the robot along the line of sight.
class TargetTrack {
 public:
  TargetTrack() = default;
  explicit TargetTrack(const TargetMotion::Config& config) : motion_(config) {}

  /// The target at `target` and the robot at `robot` (odometry frame, m) at time t (s).
  void add(double t, const Eigen::Vector2d& robot, const Eigen::Vector2d& target);
  /// Ground speed, m/s; nullopt while TargetMotion has no velocity.
  std::optional<double> speed(double now) const;
  /// Ground velocity along the line robot -> target at the newest estimate, m/s
  /// (negative: walking towards the robot).
  std::optional<double> recedingSpeed(double now) const;
  void reset() { motion_.reset(); }

 private:
  TargetMotion motion_;
  Eigen::Vector2d robot_ = Eigen::Vector2d::Zero();
  Eigen::Vector2d target_ = Eigen::Vector2d::Zero();
};

}  // namespace control
}  // namespace radio_follow
