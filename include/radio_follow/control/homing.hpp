// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <deque>
#include <optional>

#include "radio_follow/control/path_follower.hpp"
#include "radio_follow/control/rate_limiter.hpp"
#include "radio_follow/control/standing_goal.hpp"

namespace radio_follow {
namespace control {

/// Homing to a static target of unknown position from bearings and odometry
/// (seed 000, Section 5; equation numbers refer to that paper, doc/control/homing.md).
/// Every angle here is in the odometry frame: `bearing` = robot heading theta_r plus
/// the sensor's angle of arrival theta_s (plus the board's mounting yaw).

/// Vector estimate, eqs 1-5: goal = robot + d (cos, sin)(bearing), averaged over the
/// last `window` goals with weights w_k = exp(-(k-1)/tau), k = 1 the newest.
class VectorEstimator {
 public:
  VectorEstimator(double tau, std::size_t window);

  /// The raw goal of eqs 1-2 for one reading (not stored).
  static Eigen::Vector2d rawGoal(const Eigen::Vector2d& robot, double bearing, double distance);

  /// z-test of `raw` against the stored raw goals: outlier when |z| > z_threshold on
  /// either axis. Needs at least three stored goals; fewer means "not an outlier".
  bool isOutlier(const Eigen::Vector2d& raw, double z_threshold) const;

  void add(const Eigen::Vector2d& raw);
  /// Weighted average (eqs 4-5); nullopt before the first reading.
  std::optional<Eigen::Vector2d> estimate() const;
  std::size_t size() const { return goals_.size(); }

 private:
  double tau_;
  std::size_t window_;
  std::deque<Eigen::Vector2d> goals_;  // newest first
};

/// Parallax estimate: intersection of the first two bearing rays (eqs 6-9), then
/// Kohonen-style steps moving the goal towards each new bearing line (eqs 10-13).
class ParallaxEstimator {
 public:
  /// `k` = step towards the new line (0.8 in seed 000); `min_baseline` = robot travel
  /// between the two initial readings, metres; `min_angle` = smallest angle between
  /// the two rays, rad (nearly parallel rays give a wild intersection).
  ParallaxEstimator(double k, double min_baseline, double min_angle);

  /// Feeds one reading; returns the goal once initialised.
  std::optional<Eigen::Vector2d> update(const Eigen::Vector2d& robot, double bearing);
  /// Overrides the goal (the hybrid rule's averaging step).
  void set(const Eigen::Vector2d& goal) { goal_ = goal; }
  const std::optional<Eigen::Vector2d>& goal() const { return goal_; }

  /// Eqs 6-9: intersection of the ray from r1 at bearing b1 with the ray from r2 at b2;
  /// nullopt when the rays are parallel or meet behind r1.
  static std::optional<Eigen::Vector2d> intersect(const Eigen::Vector2d& r1, double b1,
                                                  const Eigen::Vector2d& r2, double b2,
                                                  double min_angle);
  /// Eqs 10-13: moves `old_goal` by k times its signed distance to the bearing line.
  static Eigen::Vector2d kohonenStep(const Eigen::Vector2d& old_goal, const Eigen::Vector2d& robot,
                                     double bearing, double k);

 private:
  double k_;
  double min_baseline_;
  double min_angle_;
  std::optional<std::pair<Eigen::Vector2d, double>> first_;
  std::optional<Eigen::Vector2d> goal_;
};

/// Parameters of the hybrid homing estimator and its velocity law.
struct HomingParams {
  /// "all_readings": the goal is StandingGoalEstimator's fit of every reading, once the
  /// hybrid rule below has given it a first goal; "seed000": the hybrid rule's goal.
  std::string goal_estimator = "all_readings";
  double tau = 5.0;                  ///< eq 3 decay, in readings
  int window = 20;                   ///< vector goals kept
  double k = 0.8;                    ///< Kohonen step
  double min_baseline = 0.2;         ///< m
  double min_parallax_angle = 0.05;  ///< rad
  double error_threshold = 0.3;      ///< eq 14
  double range_step = 0.5;           ///< along the line of sight, per reading (rangeStep)
  double z_threshold = 1.645;        ///< 90 % one-sided
  double arrival_distance = 0.3;     ///< m
  double agreement_distance = 0.3;   ///< m, parallax vs vector at arrival
  double max_linear = 0.5;           ///< m/s, v_max of eq 15
  double linear_gain = 0.5;          ///< 1/s, speed = min(v_max, gain * distance)
  double angular_gain = 1.0;         ///< 1/s
  double max_angular = MotionLimits().max_angular;  ///< rad/s (the pipeline's, set by the node)

  void validate() const;
};

/// Which estimate the hybrid rule reported.
enum class HomingSource { kNone, kVector, kParallax, kAverage, kAllReadings };

/// The hybrid rule of seed 000 Section 5.3, and (goal_estimator "all_readings") the fit
/// of every reading that takes over from it once it has a goal.
class HybridHoming {
 public:
  explicit HybridHoming(const HomingParams& params);

  /// One reading at robot position `robot` with world bearing `bearing` and an
  /// estimated distance >= 0 (NaN or negative when none: the vector estimate then skips
  /// this reading; zero is kept, see update()'s comment).
  /// A non-finite position or bearing is refused (counted) and changes nothing.
  void update(const Eigen::Vector2d& robot, double bearing, double distance);
  std::size_t refused() const { return refused_; }

  const std::optional<Eigen::Vector2d>& goal() const { return goal_; }
  HomingSource source() const { return source_; }
  std::optional<Eigen::Vector2d> vectorGoal() const { return vector_.estimate(); }
  const std::optional<Eigen::Vector2d>& parallaxGoal() const { return parallax_.goal(); }

  /// Arrived: within arrival_distance of the goal and both estimates within
  /// agreement_distance of each other (the parallax goal, or the fit of all readings
  /// when it is the goal, against the vector goal). With bearings only (no vector
  /// estimate) the distance condition alone decides.
  bool arrived(const Eigen::Vector2d& robot) const;

 private:
  /// Seed 000's hybrid rule (Section 5.3) on one reading.
  void updateHybrid(const Eigen::Vector2d& robot, double bearing, double distance);

  HomingParams params_;
  VectorEstimator vector_;
  ParallaxEstimator parallax_;
  StandingGoalEstimator all_readings_;
  std::optional<Eigen::Vector2d> fit_;  ///< the newest fit of all readings
  std::optional<Eigen::Vector2d> goal_;
  HomingSource source_ = HomingSource::kNone;
  std::size_t refused_ = 0;
};

/// The Kohonen step's counterpart along the line of sight (not in seed 000): moves
/// `goal` along the robot-goal line by `k` times the difference between `distance` (the
/// vector goal's distance from the robot) and the goal's own. Bearings from a robot that
/// drives straight at the target all run along its path, so eqs 10-13 never correct the
/// parallax goal's error along it; the range does (doc/control/homing.md, "Range step").
Eigen::Vector2d rangeStep(const Eigen::Vector2d& goal, const Eigen::Vector2d& robot,
                          double distance, double k);

/// Where a range puts the target along a bearing ray (the vector estimate's distance,
/// eqs 1-2, from a range taken somewhere else): the distance t >= 0 from `sensor` along
/// `bearing` to the point whose slant range from an antenna at horizontal position
/// `origin`, `height_difference` below or above the target, is `range`. A UWB module
/// measures from its own antenna and in 3-D, not from the AoA board on the plane; near
/// the target both differences are a large share of the distance. A range too short to
/// reach the ray gives the ray's closest point to the antenna; NaN for a bad range.
double distanceAlongBearing(const Eigen::Vector2d& sensor, double bearing,
                            const Eigen::Vector2d& origin, double height_difference, double range);

/// Eq 14: distance between the parallax and vector goals over the mean of their
/// distances to the robot.
double homingErrorMetric(const Eigen::Vector2d& parallax, const Eigen::Vector2d& vector,
                         const Eigen::Vector2d& robot);

/// Eq 15 with proportional turning: v = (2/pi) v (pi/2 - |theta_g|), zero beyond
/// +-pi/2, where v = min(max_linear, linear_gain * distance); w = angular_gain * theta_g.
VelocityCommand homingVelocity(const Pose2& robot, const Eigen::Vector2d& goal,
                               const HomingParams& params);

}  // namespace control
}  // namespace radio_follow
