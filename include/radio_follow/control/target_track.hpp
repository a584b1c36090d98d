// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <Eigen/Core>
#include <deque>
#include <optional>

#include "radio_follow/common/plausibility.hpp"

namespace radio_follow {
namespace control {

/// A point of the target's track: the locator's estimate in the odometry frame, as the
/// locator tracks it (no TF lookup and no differentiation in the controller).
struct TrackPoint {
  Eigen::Vector2d robot = Eigen::Vector2d::Zero();   ///< the robot at the estimate's stamp, m
  Eigen::Vector2d target = Eigen::Vector2d::Zero();  ///< the target, m
  /// The target's velocity over ground, m/s; nullopt while the locator has none (the
  /// solver estimator's first positions).
  std::optional<Eigen::Vector2d> velocity;
};

/// A track point from the fields of an estimate: nullopt when the robot or the target is
/// not a plausible odometry position (non-finite, beyond kMaxOdometryCoordinate); a
/// velocity that is not finite (the message's NaN) or not a person's
/// (plausibleTargetSpeed) is unknown.
std::optional<TrackPoint> trackPoint(const Eigen::Vector2d& robot, const Eigen::Vector2d& target,
                                     const std::optional<Eigen::Vector2d>& velocity);

/// Whether an estimate's odometry-frame part is one to act on: the robot and the target at
/// plausible odometry positions, the velocity unknown (NaN on any axis) or a person's
/// (plausibleTargetSpeed). An estimate whose part is not counts as LOST, and the robot
/// stops: the nodes (estimateQuality) and the lockstep loop decide it here alike. Inline:
/// the ROS layer's common library checks messages with it without linking the control law.
inline bool plausibleOdometryPart(const Eigen::Vector3d& robot, const Eigen::Vector3d& target,
                                  const Eigen::Vector3d& velocity) {
  const auto plausible = [](const Eigen::Vector3d& p) {
    return plausibleOdometryCoordinate(p.x()) && plausibleOdometryCoordinate(p.y()) &&
           plausibleOdometryCoordinate(p.z());
  };
  return plausible(robot) && plausible(target) &&
         (velocity.hasNaN() || plausibleTargetSpeed(velocity.norm()));
}

/// The target as the speed feed-forward needs it: the locator's ground velocity, averaged
/// over the track points of the last second, and the line of sight from the robot to the
/// target at the newest one.
///
/// Why over ground: a feed-forward built from the velocity relative to the moving robot
/// feeds the robot's acceleration back into its own command through the filter's lag; in
/// closed loop that oscillated. The velocity the locator tracks in the odometry frame does
/// not contain the robot's motion. Why averaged: one epoch's filter velocity jitters by
/// some 0.1 m/s; fed forward as it is, the commands jittered too and the robot held the
/// follow gap less often in the lockstep experiments (5 broken thresholds in 200 runs).
class TargetTrack {
 public:
  /// Seconds of track points the velocity is averaged over; older ones give none.
  static constexpr double kWindow = 1.0;

  /// A track point stamped t (s). False, and nothing kept, when t is not finite or older
  /// than the newest point kept.
  bool add(double t, const TrackPoint& point);
  /// Ground speed, m/s: that of the mean velocity; nullopt without a velocity from the
  /// last kWindow s.
  std::optional<double> speed(double now) const;
  /// The mean ground velocity along the line robot -> target of the newest point, m/s
  /// (negative: walking towards the robot); nullopt as speed().
  std::optional<double> recedingSpeed(double now) const;
  void reset() { points_.clear(); }

 private:
  struct Stamped {
    double t;
    TrackPoint point;
  };
  std::optional<Eigen::Vector2d> velocity(double now) const;

  std::deque<Stamped> points_;  ///< oldest first, within kWindow of the newest
};

}  // namespace control
}  // namespace radio_follow
