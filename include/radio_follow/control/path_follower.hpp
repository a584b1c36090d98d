// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <Eigen/Core>
#include <deque>
#include <optional>

#include "radio_follow/common/param_source.hpp"
#include "radio_follow/common/pose2.hpp"
#include "radio_follow/control/follow_law.hpp"
#include "radio_follow/control/follower_state.hpp"
#include "radio_follow/control/pid.hpp"
#include "radio_follow/control/velocity_law.hpp"

namespace radio_follow {
namespace control {

using radio_follow::Pose2;  ///< in the odometry frame here

/// The human's path in a fixed (odometry) frame (thesis Section 4.7): points at least
/// `min_spacing` apart, oldest first, pruned as the robot passes them.
class PathBuffer {
 public:
  PathBuffer(double min_spacing, std::size_t max_points);

  /// Appends the target's position unless it is closer than min_spacing to the newest
  /// point (a standing person then does not fill the buffer with noise).
  /// Returns true when the point was stored.
  bool add(const Eigen::Vector2d& point);

  /// Drops the points the robot has passed: everything before the stored point nearest
  /// to the robot, and that point too once it is within `reached_radius`.
  void prune(const Eigen::Vector2d& robot, double reached_radius);

  /// Distance from the robot along the stored path to its newest point, metres:
  /// straight to the first point, then along the segments.
  double lengthFrom(const Eigen::Vector2d& robot) const;

  const std::deque<Eigen::Vector2d>& points() const { return points_; }
  bool empty() const { return points_.empty(); }
  void clear() { points_.clear(); }

 private:
  double min_spacing_;
  std::size_t max_points_;
  std::deque<Eigen::Vector2d> points_;
};

/// Pure pursuit's output: the goal point and the curvature of the arc through it.
struct PursuitTarget {
  Eigen::Vector2d point = Eigen::Vector2d::Zero();
  /// Goal in the robot frame (x forward, y left), metres.
  Eigen::Vector2d local = Eigen::Vector2d::Zero();
  /// Signed curvature 2 y / L^2 of the arc from the robot through the goal, 1/m.
  double curvature = 0.0;
  bool valid = false;
};

/// Picks the first path point at least `lookahead` from the robot (else the newest
/// point) and returns the pure-pursuit arc to it.
PursuitTarget purePursuit(const std::deque<Eigen::Vector2d>& path, const Pose2& robot,
                          double lookahead);

/// The path follower's own parameters (doc/nodes/path_follower.md; the follow distance and
/// speed law are VelocityLawParams).
struct PathFollowParams {
  double path_spacing = 0.1;  ///< m
  int max_path_points = 2000;
  double lookahead = 1.5;       ///< m (shorter chases the noise of a path built from estimates)
  double reached_radius = 0.3;  ///< m
  double turn_gain = 1.5;       ///< 1/s, turning in place towards a goal behind

  static const ParamTable<PathFollowParams>& table();
  /// Reads the fields from their parameter names; absent keys keep their value.
  void load(const ParamSource& source);
  /// Throws ParamError naming the first unusable field.
  void validate() const;
};

/// The path follower's law (thesis Section 4.7): the person's path in the odometry frame,
/// pure pursuit along it, the follow distance held along the path (or along the straight
/// line when that is shorter), the person's ground speed as feed-forward, turning in
/// place when the goal is behind. Without the robot's pose (no odometry) or with a
/// direction-only estimate it drives straight at the target with the velocity law.
class PathFollowLaw : public FollowLaw {
 public:
  /// Both validated by the caller.
  PathFollowLaw(const PathFollowParams& params, const VelocityLawParams& law);

  /// A full position of the target (OK or DEGRADED estimate) in the odometry frame;
  /// true when it extended the path.
  bool addTarget(const Eigen::Vector2d& point) { return path_.add(point); }
  /// One tick: `target` as the velocity law sees it (its receding speed is not used),
  /// `robot` the pose in the odometry frame (nullopt: unknown), `walking_speed` the
  /// person's ground speed (nullopt: unknown, taken as 0).
  LawOutput step(const TargetPolar& target, const std::optional<Pose2>& robot,
                 std::optional<double> walking_speed, double dt);
  /// FollowLaw: step() with the input's robot pose and walking speed; waiting without an
  /// estimate.
  LawOutput step(const FollowInput& input, double dt) override;
  void onStopped() override { reset(); }
  bool addTrackPoint(const Eigen::Vector2d& point) override { return addTarget(point); }
  /// The common speed caps and stop distance through lawWithCommon (throws ParamError).
  void setCommon(const CommandPipelineParams& next) override;
  /// New law parameters (live tuning; validated by the caller): the PIDs keep their state.
  void setLawParams(const VelocityLawParams& law);
  /// The safety layer took over: integrators and the arrived state start afresh.
  void reset();

  const PathBuffer& path() const { return path_; }
  const VelocityLawParams& lawParams() const { return law_; }

 private:
  PathFollowParams params_;
  VelocityLawParams law_;
  VelocityLaw fallback_;
  Pid speed_pid_;
  PathBuffer path_;
  bool arrived_ = false;  ///< for the status only (with hysteresis)
};

}  // namespace control
}  // namespace radio_follow
