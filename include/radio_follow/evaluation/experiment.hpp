// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "radio_follow/evaluation/closed_loop.hpp"

namespace radio_follow {
namespace evaluation {

/// What an experiment asserts; absent thresholds are not checked (test/experiments.yaml).
struct ExperimentCheck {
  std::optional<double> min_gap_while_moving;       ///< m
  std::optional<double> min_gap_within_tolerance;   ///< share of the walk
  std::optional<double> max_estimate_error_median;  ///< m
  std::optional<double> max_path_deviation;         ///< m
  /// The path follower adds at most this to the estimate's own error: path deviation max
  /// <= estimate error p95 + this, m (a layout whose estimate wanders sideways, TWR only,
  /// cannot be held on the true path closer than its estimate is).
  std::optional<double> max_path_deviation_beyond_estimate;
  /// No forward command in [first, second] (simulator clock: scenario s + 1).
  std::optional<std::pair<double, double>> stop_window;
  /// A forward command above 0.1 m/s after this (simulator clock).
  std::optional<double> resume_after;
  /// The robot's footprint never closer than this to an obstacle, m (0: no collision).
  std::optional<double> min_clearance;
};

/// One closed-loop experiment: a scenario on a layout with a controller, sensor outages
/// (faults) and what it must show.
struct Experiment {
  std::string name;
  std::string layout;
  std::string scenario;
  FollowController controller = FollowController::kVelocity;
  std::vector<SensorOutage> outages;
  /// Controller parameters over the shipped files (a mapping, e.g. `{use_scan: true}`;
  /// null: none), as follower.launch's `controller_params` file would set them.
  YAML::Node controller_params;
  /// A locator override file in the config directory (e.g. "locator_standing.yaml"),
  /// loaded after config/locator.yaml as follower.launch's `locator_overrides`; empty: none.
  std::string locator_overrides;
  /// The simulator's sensor profile: the entry's `sensor_profile`, else the file's.
  sim::SensorProfile sensor_profile = sim::SensorProfile::kIdeal;
  ExperimentCheck check;
};

/// Reads the experiment definitions (format in test/experiments.yaml); throws ParamError
/// naming the bad entry. Unknown keys are refused. A top-level `sensor_profile: ideal |
/// realistic` (default ideal) is every experiment's profile unless it names its own.
std::vector<Experiment> loadExperiments(const std::string& path);

/// A forward command at a time, as a controller sent it.
struct CommandAt {
  double t;       ///< s, simulator clock
  double linear;  ///< m/s
};

/// The sentences saying which threshold of `check` the run broke (empty: it passed).
/// Used on lockstep runs and on the ROS runs' reports alike.
std::vector<std::string> checkRun(const ExperimentCheck& check, const control::FollowReport& report,
                                  const std::vector<CommandAt>& commands);

/// Whether a run still followed at its end: no collision, and the final gap within
/// `gap_tolerance` of `follow_distance` (every scenario ends with the person standing
/// for its settle time, long enough for a robot that kept up to arrive).
bool keptFollowing(const control::FollowReport& report, const control::FollowSettings& settings);

struct ExperimentResult {
  control::FollowReport report;
  std::vector<std::string> violations;  ///< checkRun's, plus the report's own failures
  bool kept_following = false;          ///< keptFollowing(report, the run's settings)
};

/// Runs `experiment` in the lockstep closed loop with the configuration under
/// `config_dir` and noise seed `seed` (the simulated hardware's too), and checks it.
/// The locator gets the layout the calibration run fitted on that hardware, on either
/// sensor profile (ClosedLoopConfig::locator_layout).
ExperimentResult runExperiment(const Experiment& experiment, const std::string& config_dir,
                               int seed);

}  // namespace evaluation
}  // namespace radio_follow
