// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <Eigen/Core>
#include <deque>
#include <functional>
#include <optional>

#include "radio_follow/common/pose2.hpp"
#include "radio_follow/estimation/locator_types.hpp"

namespace radio_follow {
namespace estimation {

/// The locator's estimate in the odometry frame, where the robot's own motion is not in
/// it: what the controllers track the target with (TargetEstimate's odom_* fields).
struct OdometryEstimate {
  Eigen::Vector2d robot = Eigen::Vector2d::Zero();     ///< the robot at the estimate's stamp, m
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  ///< the target, m
  /// The target's velocity over ground, m/s; nullopt when the estimator does not track it
  /// (the solver estimator: its Kalman filter's velocity is relative to the moving robot;
  /// OdometryTrack fits one).
  std::optional<Eigen::Vector3d> velocity;
};

/// The robot's odometry pose at a time (s), or nothing (no odometry, none at that time).
using PoseAt = std::function<std::optional<Pose2>(double)>;

/// `estimate` in the odometry frame: the particle estimator's own state when it tracks
/// there (LocatorEstimate::in_odom), else the robot-frame position placed with
/// `pose_at(estimate.stamp)` (asked only then), without a velocity. nullopt for a LOST
/// estimate, without a pose, or when a value is not finite.
std::optional<OdometryEstimate> inOdometry(const LocatorEstimate& estimate, const PoseAt& pose_at);

/// The locator's estimates in the odometry frame, one call per published estimate:
/// inOdometry(), and where the estimator tracks no ground velocity (the solver) one from
/// the target's recent odometry positions, a least-squares line through those of the
/// last kWindow seconds (the robot's motion is not in them).
class OdometryTrack {
 public:
  static constexpr double kWindow = 1.0;  ///< s of positions the line goes through
  static constexpr int kMinSamples = 5;   ///< fewer: no velocity
  /// The positions must span at least this share of the window.
  static constexpr double kMinSpanFraction = 0.5;

  /// inOdometry(estimate, pose_at), its velocity fitted when the estimator gives none.
  /// An estimate stamped before the newest position kept (the clock went back) starts
  /// the line anew; one with the same stamp adds nothing.
  std::optional<OdometryEstimate> update(const LocatorEstimate& estimate, const PoseAt& pose_at);
  void reset() { samples_.clear(); }

 private:
  struct Sample {
    double t;
    Eigen::Vector2d p;
  };
  std::optional<Eigen::Vector2d> fittedVelocity(double now) const;

  std::deque<Sample> samples_;  ///< oldest first, within kWindow of the newest
};

}  // namespace estimation
}  // namespace radio_follow
