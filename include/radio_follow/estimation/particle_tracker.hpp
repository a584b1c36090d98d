// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <map>
#include <optional>
#include <vector>

#include "radio_follow/common/angles.hpp"
#include "radio_follow/common/pose2.hpp"
#include "radio_follow/common/target_status.hpp"
#include "radio_follow/config/layout.hpp"
#include "radio_follow/estimation/measurement_models.hpp"
#include "radio_follow/estimation/mirror_axis.hpp"
#include "radio_follow/estimation/particle_filter.hpp"
#include "radio_follow/estimation/rss_direction.hpp"

namespace radio_follow {
namespace estimation {

/// The particle backend's tuning (filled from LocatorConfig).
struct ParticleTrackerConfig {
  ParticleFilter::Config filter;
  /// Each kind's tuning: its likelihood, decorrelation and bias (of<Reading>()).
  ReadingTunings kinds;
  double max_age = 0.5;             ///< s; measurements older than this are dropped
  double ambiguity_margin = 2.0;    ///< nats; see ParticleTracker
  /// s, time constant of the mirror evidence's fading: two of the bearings' correlation
  /// times, so that one spell of correlated errors cannot decide the side.
  double mirror_memory = 2.0;
  double max_position_sigma = 0.5;  ///< m, worst axis for OK
  double max_relative_sigma = 0.1;  ///< ... or this fraction of the distance
  double lost_sigma = 1.0;          ///< m, worst axis beyond which the track is LOST
  double default_range = kDefaultRange;  ///< m, distance reported along a bearing alone

  template <typename Reading>
  typename Reading::Tuning& of() {
    return std::get<readingIndex<Reading>()>(kinds);
  }
  template <typename Reading>
  const typename Reading::Tuning& of() const {
    return std::get<readingIndex<Reading>()>(kinds);
  }
};

/// What a reading needs from the tracker to answer its questions (tracked_reading.hpp):
/// the layout, the tuning, and where the robot was.
struct TrackerContext {
  const Layout& layout;
  const ParticleTrackerConfig& config;
  const std::vector<RssPair>& rss_pairs;  ///< the layout's opposed board pairs
  /// Every AoA board faces the same way: the field of view's prior
  /// (BearingLikelihood::behind_weight) decides the side until the data do.
  bool boards_one_way = false;
  Pose2 pose;           ///< the robot in the tracking frame at the reading's stamp
  bool ranged = false;  ///< a reading fixed the distance within max_age before this one
  /// Weighing a cold start's sampler: a cloud spread around the robot, whose mean says
  /// nothing about where the target is.
  bool cold_start = false;
  double sigma_scale = 1.0;  ///< the reading's decorrelation factor (its sigma grows by it)
};

/// What the tracker reports, in the tracking frame and in the robot frame at `stamp`.
struct TrackerOutput {
  TargetStatus status = TargetStatus::kLost;
  double stamp = 0.0;  ///< time of the newest measurement processed, s
  bool in_odom = false;
  Pose2 pose;                                          ///< robot in the tracking frame at `stamp`
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  ///< tracking frame
  Eigen::Vector2d velocity = Eigen::Vector2d::Zero();  ///< tracking frame
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  int hypotheses = 0;              ///< 1, or 2 when the mirror hypothesis holds mass
  double hypothesis_weight = 0.0;  ///< probability of `position`'s hypothesis
  Eigen::Vector3d alternative = Eigen::Vector3d::Zero();  ///< tracking frame
  std::uint8_t sources = 0;                               ///< kinds processed within max_age
};

struct TrackerStats {
  std::size_t processed = 0;
  std::size_t late = 0;           ///< older than the filter's clock: applied at its time
  std::size_t stale_dropped = 0;  ///< older than max_age when their turn came
  std::size_t future_dropped = 0;
  std::size_t cold_starts = 0;
  std::size_t frame_switches = 0;  ///< odometry appeared or vanished: track restarted
  std::size_t mirror_swaps = 0;    ///< the mirror hypothesis overtook the main one
  /// The main hypothesis jumped (> 1 m and 3 sigma in one update): mirror drawn again.
  std::size_t mirror_redraws_after_jump = 0;
  std::size_t divergences = 0;  ///< the track stopped explaining its inputs: restarted
  std::size_t resamples = 0;
};

/// Multi-hypothesis target tracker (issue 14, after seed 001's particle filter).
///
/// Every measurement is applied at its own stamp, in stamp order, to a constant-velocity
/// particle filter in the tracking frame (odometry when poses are given), with
/// heavy-tailed likelihoods. Nearly collinear ranging modules (Spot's three) allow a
/// mirror solution across their axis that ranges alone cannot rule out, and a single
/// filter that settled on the wrong side has no particle left on the right one. So a
/// second, smaller filter tracks the mirror image of the first, the two accumulate the
/// evidence of every measurement (log marginal likelihoods; a log Bayes factor D that
/// fades with the time constant `mirror_memory`), and
///   - the mirror replaces the main hypothesis as soon as the data prefer it by more than
///     `ambiguity_margin` nats (D > margin): no lock on a wrong mirror;
///   - while neither is preferred by that margin, the status is AMBIGUOUS;
///   - when the mirror falls onto the main one (target on the modules' axis) it is
///     re-seeded as the main one's mirror image, and so it is when the main one jumps
///     (a young cloud settling elsewhere) and leaves its old image behind.
/// The report is the mixture of the two, weighted by the evidence: its covariance holds
/// the spread between them (so a mirror a few decimetres away, a target near the
/// modules' axis, is one wider estimate, not a reason to stop), plus the floor that
/// errors correlated over seconds leave (correlated_error.hpp). Only when that mixture is
/// too wide to act on and the data do not prefer one side is the status AMBIGUOUS.
/// Cold starts sample the whole set of positions the fresh data allow (a ring around a
/// module, rays along bearings) and split it by side.
class ParticleTracker {
 public:
  ParticleTracker(const Layout& layout, const ParticleTrackerConfig& config);

  /// Queues a measurement (applied by the next update in stamp order).
  void add(const TrackedMeasurement& measurement);
  /// Applies what is queued up to `now` and reports.
  TrackerOutput update(double now);
  void reset();
  /// New tuning; keeps the track unless the particle count or mode changes.
  void setConfig(const ParticleTrackerConfig& config);

  bool tracking() const { return main_.initialized(); }
  const TrackerStats& stats() const { return stats_; }
  const ParticleFilter& mainFilter() const { return main_; }
  /// log Bayes factor mirror : main (see the class comment).
  double mirrorEvidence() const { return evidence_; }

 private:
  void apply(const TrackedMeasurement& m);
  /// The context of a reading stamped `t` taken at `pose` (tracked_reading.hpp).
  TrackerContext context(const Pose2& pose, double t) const;
  /// `filter`'s particles weighed by `m`'s likelihood (its kind's weigh()).
  MeasurementFit weigh(ParticleFilter& filter, const TrackedMeasurement& m, const Pose2& pose,
                       bool cold_start = false, double sigma_scale = 1.0) const;
  /// Whether `m` is an input the tuning uses (an optional one may be off).
  bool usable(const TrackedMeasurement& m) const;
  /// `m`'s sigma factor by the time since its sensor's previous reading (its kind's
  /// decorrelation()); records the reading's stamp.
  double sigmaScale(const TrackedMeasurement& m);
  /// A reading that fixes the distance came within max_age before `t`.
  bool rangedAt(double t) const;
  bool coldStart(double now);
  void seedMirror();
  void maintainMirror();
  bool mirrorDistinct() const;
  /// Folds the particles of `filter` that crossed the boards' plane back to the side
  /// `left` (onMainSide); a resample, when more than a trace of weight crossed.
  void keepSide(ParticleFilter& filter, bool left) const;
  /// Whether `pose` differs from the newest processed measurement's (kStill).
  bool moved(const Pose2& pose) const;
  /// Whether `p` (tracking frame) is in front of the first AoA board's plane.
  bool inFront(const Eigen::Vector3d& p, const Pose2& pose) const;
  Eigen::Vector3d mirrored(const Eigen::Vector3d& p, const Pose2& pose) const;
  Eigen::Vector2d mirroredVelocity(const Eigen::Vector2d& v, const Pose2& pose) const;
  bool onMainSide(const Eigen::Vector3d& p, const Pose2& pose) const;
  /// The covariance floor of correlated errors at `position` from the sensors processed
  /// within max_age.
  Eigen::Matrix3d correlatedFloor(const Eigen::Vector3d& position) const;

  Layout layout_;
  ParticleTrackerConfig config_;
  ParticleFilter main_;
  ParticleFilter mirror_;
  bool mirror_active_ = false;
  /// The main hypothesis's mean at the previous update (jumps re-draw the mirror).
  std::optional<Eigen::Vector3d> last_main_mean_;
  double evidence_ = 0.0;
  double evidence_time_ = 0.0;  ///< stamp of the newest measurement in evidence_
  /// The modules' main axis in the robot frame, when they are nearly collinear; or,
  /// when the modules cannot fix a position (at most one) and every AoA board faces the
  /// same way, the boards' plane: the side they cannot tell.
  std::optional<MirrorAxis> axis_;
  bool board_axis_ = false;
  /// Every AoA board faces the same way: none of them sees behind the others' plane, so
  /// the field of view's prior (BearingLikelihood::behind_weight) decides the side until
  /// the data do.
  bool boards_one_way_ = false;
  /// Where the bearings are taken, robot frame: the boards' mean position (the origin
  /// without boards). A direction alone is a ray from here.
  Eigen::Vector2d bearing_origin_ = Eigen::Vector2d::Zero();
  /// One epoch cannot place the target (at most one TWR module and no AoA board: one
  /// ring, plus TDoA hyperbolae that only give a direction): a cloud too wide to report
  /// is kept converging (reported LOST) instead of restarting from the newest epoch,
  /// which would throw the evidence away each time.
  bool accumulates_ = false;
  /// The layout's opposed board pairs (RssDirectionReading::pair indexes them).
  std::vector<RssPair> rss_pairs_;
  std::vector<TrackedMeasurement> queue_;
  std::deque<TrackedMeasurement> recent_;  ///< processed within max_age (cold starts)
  bool in_odom_ = false;
  Pose2 pose_;                                      ///< of the newest processed measurement
  double last_position_fix_ = -1.0;  ///< newest reading that fixes the distance, applied
  /// Stamp of the newest reading applied, by source bit (TargetEstimate.sources).
  std::map<std::uint8_t, double> last_source_;
  /// Stamp of each sensor's newest reading (the decorrelation times).
  std::map<SensorKey, double> last_reading_;
  /// Running mean of the inlier probability of the applied measurements (see apply()).
  double fit_ = 1.0;
  TrackerStats stats_;
};

}  // namespace estimation
}  // namespace radio_follow
