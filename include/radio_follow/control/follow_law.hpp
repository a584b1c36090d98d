// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The interface between the follower core (control/follower.hpp) and a control law: what
// a law gets each tick and what it must answer. A law includes this, not the core.

#include <Eigen/Core>
#include <limits>
#include <optional>

#include "radio_follow/common/pose2.hpp"
#include "radio_follow/control/follower_state.hpp"

namespace radio_follow {
namespace control {

struct CommandPipelineParams;

/// Target as the law sees it: range and bearing in the robot frame.
struct TargetPolar {
  double range = 0.0;    ///< m
  double bearing = 0.0;  ///< rad, CCW from the robot's x axis
  /// false for HEADING_ONLY estimates: turn towards the target, never drive forward.
  bool range_valid = true;
  /// The estimate is DEGRADED: too wide to be OK where it is (see caution()).
  bool degraded = false;
  /// 1-sigma spread of the position along the line of sight, m, and of the bearing, rad
  /// (common/geometry.hpp polarSpread); +inf when unknown.
  double range_sigma = 0.0;
  double bearing_sigma = 0.0;
  /// The locator holds a second hypothesis: the person may be at the mirror image.
  bool mirror = false;
  /// The target's ground speed away from the robot along the line of sight, m/s
  /// (negative: walking towards it); 0 when unknown (no odometry, no velocity yet).
  double receding_speed = 0.0;
  /// Smallest fresh (calibrated) module range minus safe_distance, m; +inf when no
  /// range is watched.
  double module_gap = std::numeric_limits<double>::infinity();
};

/// What a follow law gets at a tick in which the safety layer lets the robot move.
struct FollowInput {
  double now = 0.0;  ///< s, the controller's clock
  /// The newest estimate as the velocity law reads it (receding speed and module gap
  /// filled in); nullopt when the controller hears no estimates (homing: bearings only).
  std::optional<TargetPolar> target;
  /// The robot in the odometry frame; nullopt when the controller does not know it.
  std::optional<Pose2> robot;
  /// The target's ground speed, the locator's in the odometry frame (TargetTrack), m/s;
  /// nullopt when unknown (no odometry, no velocity in the last second's track points).
  std::optional<double> walking_speed;
};

/// A control law behind the follower's command pipeline: the velocity law, the path
/// follower, the homing law. A new law is one class deriving from this plus its
/// parameters (doc/architecture.md); the controller nodes and the lockstep closed loop
/// run it through Follower.
class FollowLaw {
 public:
  virtual ~FollowLaw() = default;
  /// The command, the state and the sentence for this tick (`dt` s since the previous).
  virtual LawOutput step(const FollowInput& input, double dt) = 0;
  /// The safety layer took over (the robot is held): integrators and arrival state start
  /// afresh. Default: nothing to forget.
  virtual void onStopped() {}
  /// A point of the target's track (TrackGate) in the odometry frame; true when the law
  /// kept it (the path follower's path grew). Default: not used.
  virtual bool addTrackPoint(const Eigen::Vector2d& /*target*/) { return false; }
  /// Live tuning is about to install `next` common parameters: a law that depends on them
  /// (safe_distance, max_linear) takes them, or throws ParamError to refuse the change.
  virtual void setCommon(const CommandPipelineParams& /*next*/) {}
};

}  // namespace control
}  // namespace radio_follow
