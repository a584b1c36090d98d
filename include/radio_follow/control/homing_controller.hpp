// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <string>

#include "radio_follow/common/param_source.hpp"
#include "radio_follow/common/pose2.hpp"
#include "radio_follow/common/time_policy.hpp"
#include "radio_follow/config/layout.hpp"
#include "radio_follow/control/follow_law.hpp"
#include "radio_follow/control/follower_state.hpp"
#include "radio_follow/control/homing.hpp"
#include "radio_follow/control/rssi_filter.hpp"
#include "radio_follow/control/rssi_model.hpp"

namespace radio_follow {
namespace control {

/// Parameters of the homing controller's law. The names in ParamError messages are the
/// homing_controller node's private parameters (config/homing_controller.yaml).
struct HomingControllerParams {
  /// AoA board mounting in base_link: position (m) and yaw of its boresight (rad).
  double board_x = 0.0;
  double board_y = 0.0;
  double board_yaw = 0.0;
  /// "rssi" (log-distance model on each bearing's RSSI) or "uwb" (the newest onRange()).
  std::string distance_source = "rssi";
  /// A UWB range older than this is not used as the vector estimate's distance, s.
  double distance_max_age = 0.5;
  /// Odometry older than this (at a bearing or a tick) is not used, s.
  double odom_timeout = 0.5;
  /// Forward speed while no goal exists yet (building the parallax baseline), m/s.
  double search_speed = 0.15;
  /// Height of the target's UWB antenna in base_link, m: turns a UWB range whose
  /// antenna position is known (onRange's `antenna`) into a horizontal distance.
  double target_height = kDefaultTargetHeight;
  RssiModel rssi;
  /// Smoother of the RSSI before `rssi` turns it into a distance (`rssi_filter/...`).
  RssiFilterParams rssi_filter;
  /// The estimator and eq 15; a node copies its common max_linear and max_angular here.
  HomingParams homing;

  bool usesUwb() const { return distance_source == "uwb"; }
  /// Reads the law's parameters by their names (doc/nodes/homing_controller.md); the
  /// speed caps come from the controller's common `limits`. Absent keys keep their value.
  void load(const ParamSource& source, const MotionLimits& limits);
  /// The node's law parameters (config/homing_controller.yaml), rssi_*, rssi_filter/* and
  /// the estimator's (HomingParams) included.
  static const ParamTable<HomingControllerParams>& table();
  void validate() const;
};

/// What the law wants this tick (the fields of a controller's output).
using HomingOutput = LawOutput;  ///< command, state and the sentence to report

/// The homing_controller's law (seed 000 Section 5), clock-free: odometry, bearings and
/// UWB ranges go in with their times (seconds on one clock), and each tick returns the
/// command, the follower state and the sentence to report. The ROS node and the homing
/// benchmark (evaluation::runHomingTrial) both run this class.
///
/// Before a goal exists it creeps along the newest bearing at search_speed, so that the
/// parallax estimate gets its baseline; then it drives to the hybrid goal with eq 15 and
/// stops once HybridHoming::arrived().
class HomingController : public FollowLaw {
 public:
  /// Validates `params` (throws ParamError).
  explicit HomingController(const HomingControllerParams& params);

  /// What became of an odometry pose.
  struct OdometryResult {
    bool accepted = false;
    /// `now` ran back beyond kClockJumpTolerance: the track was forgotten (reset()).
    bool clock_jumped = false;
  };
  /// Robot pose in the odometry frame, stamped `stamp`, received at `now`. A non-finite
  /// pose, a position beyond kMaxOdometryCoordinate (plausibility.hpp) or a stamp from
  /// the future (TimePolicy) is refused and counted: one NaN pose would otherwise enter
  /// every later goal through the parallax estimate, and one of 1.8e308 m made it inf.
  OdometryResult onOdometry(const Pose2& pose, double stamp, double now);

  /// A range to the target, m (used with distance_source "uwb"), measured by an antenna
  /// at `antenna` in base_link (the layout's module position): the vector estimate then
  /// takes the point on the bearing ray at that slant range from the antenna, with the
  /// target at target_height (distanceAlongBearing). Without `antenna` the range counts
  /// as a horizontal distance from the AoA board. Non-finite or negative ranges are
  /// ignored.
  void onRange(double range, double stamp,
               const std::optional<Eigen::Vector3d>& antenna = std::nullopt);

  enum class BearingResult {
    kUsed,
    kNoOdometry,  ///< no pose within odom_timeout of the bearing's stamp
    kNotFinite,   ///< the azimuth is no angle: NaN, infinite or beyond +-pi
  };
  /// One angle of arrival in the board frame (rad, CCW) with its RSSI (dBm; NaN when
  /// none), stamped `stamp`: feeds the hybrid estimate with the board's pose in the
  /// odometry frame and the distance of distance_source. With distance_source "rssi"
  /// every finite RSSI enters the rssi_filter, also when the bearing itself is not used.
  BearingResult onBearing(double azimuth, double rssi, double stamp);

  /// The command at `now`: waiting without fresh odometry, searching before a goal,
  /// homing with eq 15, zero once arrived.
  HomingOutput compute(double now) const;
  /// FollowLaw: compute() at the input's time (the homing law keeps its own target from
  /// the bearings; a safety stop does not make it forget them).
  LawOutput step(const FollowInput& input, double /*dt*/) override { return compute(input.now); }

  /// Forgets the pose, the distance, the bearing and the estimate (homing starts over).
  void reset();

  const std::optional<Eigen::Vector2d>& goal() const { return homing_.goal(); }
  /// The goal facing the target from where the robot is now (what a planner should aim
  /// for); nullopt without a goal or a pose.
  std::optional<Pose2> goalPose() const;
  const HybridHoming& homing() const { return homing_; }
  const HomingControllerParams& params() const { return params_; }
  /// Odometry poses refused (non-finite or from the future).
  std::uint64_t odometryRefused() const { return odom_refused_; }

 private:
  /// The vector estimate's distance for a bearing at `stamp` whose smoothed RSSI is
  /// `filtered`; NaN when none.
  double distanceAt(double stamp, std::optional<double> filtered) const;

  HomingControllerParams params_;
  HybridHoming homing_;
  RssiFilter rssi_filter_;
  TimePolicy time_;
  std::optional<Pose2> robot_;
  double odom_stamp_ = 0.0;
  std::optional<double> last_bearing_;  ///< odometry frame, rad
  std::optional<double> range_stamp_;
  double range_ = 0.0;
  std::optional<Eigen::Vector3d> range_antenna_;  ///< base_link, of the newest range
  std::uint64_t odom_refused_ = 0;
};

}  // namespace control
}  // namespace radio_follow
