// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <array>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "radio_follow/common/param_table.hpp"
#include "radio_follow/control/safety_monitor.hpp"
#include "radio_follow/control/velocity_law.hpp"

namespace radio_follow {
namespace control {

/// One moment of a follow run, as the evaluator samples it (world = odometry frame).
struct FollowSample {
  double t = 0.0;             ///< s
  double robot_x = 0.0;       ///< m, world
  double robot_y = 0.0;       ///< m, world
  double robot_yaw = 0.0;     ///< rad, world
  double robot_speed = 0.0;   ///< m/s, measured (odometry)
  double cmd_linear = 0.0;    ///< m/s, last command
  double cmd_angular = 0.0;   ///< rad/s, last command
  double target_x = 0.0;      ///< m, world (ground truth)
  double target_y = 0.0;      ///< m, world (ground truth)
  double target_speed = 0.0;  ///< m/s (ground truth)
  /// The locator's estimate in the robot frame, when one was valid (status OK/DEGRADED).
  std::optional<double> estimate_x;
  std::optional<double> estimate_y;
  /// Its covariance in the robot frame (xx, xy, yy), m^2, when the estimator gave one.
  std::optional<std::array<double, 3>> estimate_covariance;
  /// Ground truth in the robot frame (x forward, y left), m: at the estimate's stamp when
  /// there is an estimate (so the error is the locator's, not transport latency), else now.
  double truth_x = 0.0;
  double truth_y = 0.0;
  /// Status of the newest estimate heard ("OK", "AMBIGUOUS", ...; "none" before the first).
  std::string estimate_status = "none";
};

/// An estimate older than this (s) counts as missing in a FollowSample (the follow
/// evaluator node and the lockstep loop sample alike).
constexpr double kSampleEstimateMaxAge = 1.0;

/// What the experiments assert and the demo reports.
struct FollowSettings {
  /// The velocity controller's and the safety layer's defaults (their parameter tables).
  double follow_distance = control::VelocityLawParams().follow_distance;  ///< m
  double safe_distance = control::SafetyParams().safe_distance;           ///< m
  double gap_tolerance = 0.3;                                             ///< m
  double robot_max_speed = 1.5;  ///< m/s; the gap is judged while the person walks slower
  /// Gap statistics start once this time has passed and the gap has first come within
  /// gap_tolerance of follow_distance: the robot catching up from its start position is
  /// not following yet. s.
  double settle_time = 5.0;
  /// Path deviation is judged over the same window as the gap.
  /// A turn: the person's heading changes by more than this over `turn_window` metres
  /// of path; path-deviation stats exclude robot positions near such places.
  double turn_heading_change = 0.35;  ///< rad (20 deg)
  double turn_window = 2.0;           ///< m
  double moving_command = 0.02;       ///< |cmd| above this counts as "commanded to move", m/s
  /// The run fails when the robot drove less than this although it had to move (the
  /// person walked more than a metre, or started farther than follow_distance +
  /// gap_tolerance away), m.
  double min_robot_distance = 0.3;
  /// The demo's verdict on how well the robot followed (follow_evaluator; the experiments
  /// assert thresholds of their own, test/experiments.yaml). With it the run also fails
  /// when the robot held the gap less than `min_gap_held` of the walk (once it had caught
  /// up while the person walked), when the median estimate error exceeds `gap_tolerance`
  /// (an estimate that far off cannot hold the gap within it), or when it came closer
  /// than `safe_distance` while commanded to move.
  bool judge_following = false;
  double min_gap_held = 0.5;  ///< share of the walk
};

/// The follow evaluator node's parameters (doc/simulator.md): where and how often it
/// writes, and the settings it judges a run by.
struct FollowEvaluatorParams {
  std::string report_dir;     ///< empty: only log the metrics
  double rate = 20.0;         ///< Hz
  double write_period = 5.0;  ///< s between report rewrites (also written at shutdown)
  /// When the scenario ends, end the roslaunch that started this node (demo.launch;
  /// false under rostest, whose test node ends the run).
  bool end_launch = false;
  /// The controller node whose follow_distance and safe_distance the run is judged by
  /// (read from its private namespace); empty: `~follow_distance`, `~safe_distance`.
  std::string controller;
  /// The evaluator judges how well the robot followed unless told not to.
  FollowSettings settings = [] {
    FollowSettings judged;
    judged.judge_following = true;
    return judged;
  }();

  /// follow_distance and safe_distance are read only without `controller`.
  static const ParamTable<FollowEvaluatorParams>& table();
  void validate() const;
};

struct FollowReport {
  double duration = 0.0;               ///< s
  double robot_distance = 0.0;         ///< m driven
  double target_distance = 0.0;        ///< m walked
  double min_gap_while_moving = 0.0;   ///< m; +inf when never commanded to move
  double min_gap = 0.0;                ///< m
  double final_gap = 0.0;              ///< m, robot to target at the last sample (homing)
  double gap_within_tolerance = 0.0;   ///< fraction of gap samples
  int gap_samples = 0;                 ///< samples the gap fraction is over
  double gap_window_start = 0.0;       ///< s after the first sample; NaN if never caught up
  double gap_mean = 0.0;               ///< m
  double estimate_error_median = 0.0;  ///< m
  double estimate_error_p95 = 0.0;     ///< m
  double estimate_error_mean = 0.0;    ///< m
  /// Consistency of the reported covariance over the samples that carry one: median NEES
  /// (2D: 1.39 when consistent) and the share of errors inside the 95 % ellipse (0.95).
  double estimate_nees_median = 0.0;
  double estimate_within_95 = 0.0;
  double estimate_availability = 0.0;  ///< fraction of samples with an estimate
  /// Fraction of samples by the newest estimate's status (OK, DEGRADED, AMBIGUOUS, ...).
  std::map<std::string, double> estimate_status_share;
  double path_deviation_median = 0.0;  ///< m, outside turns
  double path_deviation_max = 0.0;     ///< m, outside turns
  int path_samples = 0;
  /// Obstacles (FollowMetrics::addClearance): the smallest distance between the robot's
  /// footprint and an obstacle surface, m. +inf when the world has no obstacles (JSON:
  /// null); negative after a collision.
  double min_clearance = std::numeric_limits<double>::infinity();
  /// The footprint touched an obstacle (clearance < 0). The lockstep loop ends the run
  /// there: the simulated base has no contact model and would drive on through it.
  bool collided = false;
  /// When it first did, on the clock of the samples (simulator clock), s; NaN if never.
  double collision_time = std::numeric_limits<double>::quiet_NaN();
  /// Why the run failed as a closed loop, one sentence each (empty: it passed): the robot
  /// never moved, the estimate was never usable. Not a quality threshold: a wiring check.
  std::vector<std::string> failures;

  std::string toJson() const;
};

/// Accumulates FollowSamples and computes the run's metrics.
class FollowMetrics {
 public:
  explicit FollowMetrics(const FollowSettings& settings) : settings_(settings) {}

  void add(const FollowSample& sample);
  /// The robot footprint's clearance to the nearest obstacle at time t (clock of the
  /// samples), m; negative = touching. Called as often as the world steps, not only at the
  /// sample rate: a collision between two samples still counts. Never called: no obstacles.
  void addClearance(double t, double clearance);
  FollowReport report() const;
  const std::vector<FollowSample>& samples() const { return samples_; }
  /// The samples as CSV with a header row (for plots and offline analysis).
  std::string toCsv() const;

 private:
  /// Adds the judge_following failures to `r` (a run in which the robot had to move).
  void judgeFollowing(FollowReport& r) const;

  FollowSettings settings_;
  std::vector<FollowSample> samples_;
  double min_clearance_ = std::numeric_limits<double>::infinity();
  double collision_time_ = std::numeric_limits<double>::quiet_NaN();
};

}  // namespace control
}  // namespace radio_follow
