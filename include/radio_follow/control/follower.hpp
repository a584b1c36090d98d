// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <Eigen/Core>
#include <optional>

#include "radio_follow/common/geometry.hpp"
#include "radio_follow/common/pose2.hpp"
#include "radio_follow/common/target_status.hpp"
#include "radio_follow/control/command_pipeline.hpp"
#include "radio_follow/control/follow_inputs.hpp"
#include "radio_follow/control/follow_law.hpp"
#include "radio_follow/control/follower_state.hpp"
#include "radio_follow/control/target_track.hpp"
#include "radio_follow/control/velocity_law.hpp"

namespace radio_follow {
namespace control {

/// What became of an estimate handed to Follower::onEstimate.
enum class EstimateUse {
  kRefused,     ///< stamped in the future: the robot stops, nothing else is kept
  kHeard,       ///< the newest estimate, not a track point
  kTrackPoint,  ///< also a track point: hand its odometry-frame part to addTrackPoint()
};

/// The follower core that every controller node and the lockstep closed loop run: the
/// command pipeline (safety stop, scan gate, limits), the newest estimate, the target's
/// track in the odometry frame (the locator's own, TargetTrack) and the tick (the verdict,
/// the law, the verdict again at sending, the limits). Clock-free: every call carries its
/// times (s, one clock). Not thread-safe: a node with a separate safety thread holds one
/// lock around it.
class Follower {
 public:
  /// `params` validated by the caller. The law is set before the first tick.
  explicit Follower(const CommandPipelineParams& params);

  void setLaw(FollowLaw& law) { law_ = &law; }
  bool hasLaw() const { return law_ != nullptr; }

  /// The locator's estimate stamped `stamp`, received at `now`, in the robot frame: its
  /// quality goes to the safety monitor, the rest is kept for the law.
  EstimateUse onEstimate(double stamp, double now, TargetStatus status, double range,
                         double bearing, const PolarSpread& spread, int hypotheses);
  /// An input that says only that the target is (not) usable (homing's bearings): false
  /// when refused (from the future).
  bool onEstimate(double stamp, double now, EstimateQuality quality) {
    return pipeline_.onEstimate(stamp, now, quality);
  }
  /// The track point of the newest estimate, stamped `stamp`: the locator's estimate in the
  /// odometry frame (trackPoint()). Its velocity is the speed feed-forward's, its position
  /// goes to the law. True when the law kept it; false, and nothing kept, for a point
  /// older than the track's newest.
  bool addTrackPoint(double stamp, const TrackPoint& point);

  /// One controller tick at `now`, `dt` s after the previous: the safety verdict, the law
  /// (only when the robot may move) and the pipeline. `robot` is the robot's odometry
  /// pose when the controller knows it.
  PipelineResult tick(double now, double dt, const std::optional<Pose2>& robot = std::nullopt);
  /// Holds the robot for `reason` at once (disabled, a range too close, a fault): the law
  /// forgets its integrators; zero command and the reason's status.
  PipelineResult stop(StopReason reason);

  /// New common parameters (live tuning; validated by the caller): the law checks them
  /// first, then the pipeline. Throws ParamError and changes nothing when refused.
  void setCommon(const CommandPipelineParams& params);

  CommandPipeline& pipeline() { return pipeline_; }
  const CommandPipeline& pipeline() const { return pipeline_; }
  /// The target's ground speed at `now` from its track, m/s.
  std::optional<double> walkingSpeed(double now) const { return track_.speed(now); }

 private:
  CommandPipeline pipeline_;
  FollowLaw* law_ = nullptr;
  std::optional<TargetPolar> target_;  ///< the newest estimate, without speed and gap
  TrackGate gate_;
  TargetTrack track_;
};

}  // namespace control
}  // namespace radio_follow
