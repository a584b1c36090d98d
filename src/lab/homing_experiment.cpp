// SPDX-License-Identifier: BSD-3-Clause
// lab homing_experiment: seed 000's Tables 2-3 (and Table 4's analogue) with the
// homing_controller node's law on the simulator's unicycle robot.
#include <cmath>
#include <cstdio>
#include <exception>
#include <optional>
#include <string>
#include <vector>

#include "lab_commands.hpp"
#include "radio_follow/common/param_error.hpp"
#include "radio_follow/control/homing_controller.hpp"
#include "radio_follow/evaluation/homing_trial.hpp"

namespace {

/// Seed 000 Table 3, per configuration: success %, time s, net velocity m/s, goal error m,
/// final error m, path efficiency.
constexpr double kPaper[5][6] = {{100, 14.24, 0.62, 0.05, 0.25, 0.90},
                                 {100, 12.68, 0.57, 0.05, 0.24, 0.88},
                                 {100, 12.10, 0.60, 0.06, 0.25, 0.90},
                                 {100, 12.85, 0.60, 0.06, 0.25, 0.89},
                                 {100, 12.27, 0.57, 0.11, 0.15, 0.91}};

radio_follow::cli::CommandLine homingCommandLine() {
  namespace lab = radio_follow::lab;
  radio_follow::cli::CommandLine cli(
      "lab homing_experiment",
      "usage: lab homing_experiment [--per-quadrant N] [--seed S] [--max-linear V] [--arrival D]\n"
      "         [--tau T] [--config-dir DIR] [--params FILE] [--obstacles N] "
      "[--robot-radius R]\n",
      "Reproduces seed 000's Tables 2-3 with the homing_controller node's law\n"
      "(control::HomingController with the node's shipped config/controller_common.yaml and\n"
      "config/homing_controller.yaml, the distance as a UWB range) on the simulator's unicycle\n"
      "robot: the robot starts at the origin facing +x, random beacons in each quadrant of the\n"
      "-10..10 m square, the five uniform-noise configurations of Table 2. Prints a Markdown\n"
      "table beside the paper's. With --obstacles: Table 4's analogue (configuration 5).\n");
  cli.options()("per-quadrant", lab::value("N", "10"), "beacons per quadrant, >= 1")(
      "seed", lab::value("S", "1"), "the targets' and the noise's seed")(
      "max-linear", lab::value("V", "1.0"), "the robot's top speed, m/s (the paper's)")(
      "arrival", lab::value("D"), "the law's arrival_distance, m; default: the shipped one")(
      "tau", lab::value("T"), "the law's tau, s; default: the shipped one")(
      "config-dir", lab::value("DIR", RF_CONFIG_DIR), "the shipped configuration's folder")(
      "params", lab::value("FILE"), "YAML overlay on the node's shipped files")(
      "obstacles", lab::value("N", "0"),
      "Table 4's analogue: configuration 5 with N obstacles per run, with and without the "
      "scan avoidance")("robot-radius", lab::value("R", "0.2"),
                        "the robot's footprint with --obstacles, m");
  return cli;
}

struct HomingOptions {
  int per_quadrant = 10;
  unsigned long seed = 1;
  int obstacles = 0;
  double max_linear = 1.0;
  double robot_radius = 0.2;
  std::optional<double> arrival;
  std::optional<double> tau;
  std::string config_dir;
  std::string params;
};

HomingOptions readHomingOptions(const radio_follow::lab::po::variables_map& values) {
  namespace cli = radio_follow::cli;
  namespace lab = radio_follow::lab;
  HomingOptions o;
  o.per_quadrant = static_cast<int>(lab::count(values, "per-quadrant", 1));
  o.seed = static_cast<unsigned long>(lab::count(values, "seed", 0));
  o.obstacles = static_cast<int>(lab::count(values, "obstacles", 0));
  o.max_linear =
      lab::number(values, "max-linear", "a speed > 0 in m/s", [](double v) { return v > 0.0; });
  o.robot_radius =
      lab::number(values, "robot-radius", "a radius >= 0 in m", [](double r) { return r >= 0.0; });
  // Their range is the law's to check (validate()).
  if (values.count("arrival")) {
    o.arrival = cli::number("--arrival", values["arrival"].as<std::string>(), "a distance in m");
  }
  if (values.count("tau")) {
    o.tau = cli::number("--tau", values["tau"].as<std::string>(), "a time in s");
  }
  o.config_dir = values["config-dir"].as<std::string>();
  o.params = cli::CommandLine::text(values, "params");
  return o;
}

}  // namespace

int radio_follow::lab::homingExperimentMain(int argc, char** argv) {
  namespace ev = radio_follow::evaluation;
  const HomingOptions o = homingCommandLine().parse(argc, argv, readHomingOptions);
  const int per_quadrant = o.per_quadrant;
  const unsigned long seed = o.seed;
  const int obstacles = o.obstacles;
  const double max_linear = o.max_linear;
  ev::HomingNodeParams node;
  try {
    // The node's shipped files, as a user starts it; only the benchmark's conditions
    // differ: the distance is a UWB range and the robot's top speed is the paper's.
    std::vector<std::string> overlays;
    if (!o.params.empty()) {
      overlays.push_back(o.params);
    }
    node = ev::loadHomingNodeParams(o.config_dir, overlays);
    node.law.distance_source = "uwb";
    node.law.homing.max_linear = max_linear;
    if (o.arrival) {
      node.law.homing.arrival_distance = *o.arrival;
    }
    if (o.tau) {
      node.law.homing.tau = *o.tau;
    }
    node.law.validate();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "lab homing_experiment: %s\n", e.what());
    return 2;
  }
  const radio_follow::control::HomingControllerParams& params = node.law;
  ev::HomingTrialConfig config;
  config.robot.max_linear = max_linear;
  const auto targets = ev::homingTargets(per_quadrant, 10.0, 1.0, seed);
  const auto configurations = ev::seed000NoiseConfigurations();

  if (obstacles > 0) {
    // Seed 000 Table 4's analogue: noise configuration 5, an obstacle course per run,
    // with the pipeline's scan avoidance (the node's avoidance/* parameters) and without.
    const ev::HomingNoise& noise = configurations.back();
    config.avoidance = node.pipeline.avoidance;
    config.robot_radius = o.robot_radius;
    std::printf(
        "| %s, %d obstacles per run | success %% | time s | net vel. m/s | goal err. m | final "
        "err. m | path eff. | min clearance m | collisions |\n",
        noise.name.c_str(), obstacles);
    std::printf("| --- | --- | --- | --- | --- | --- | --- | --- | --- |\n");
    for (const bool use_scan : {true, false}) {
      config.use_scan = use_scan;
      std::vector<ev::HomingResult> results;
      for (std::size_t t = 0; t < targets.size(); ++t) {
        config.obstacles = ev::homingObstacleCourse(0.0, 0.0, targets[t].first, targets[t].second,
                                                    obstacles, 10.0, 1.0, seed * 1000 + t);
        results.push_back(ev::runHomingTrial(ev::homingControllerStep(params), targets[t].first,
                                             targets[t].second, noise, config,
                                             seed * 1000 + 400 + t));
      }
      const auto s = ev::summarize(results);
      std::printf("| %s | %.0f | %.2f | %.2f | %.2f | %.2f | %.2f | %.2f | %d |\n",
                  use_scan ? "scan avoidance (use_scan)" : "no avoidance", 100.0 * s.success_rate,
                  s.time, s.net_velocity, s.goal_error, s.final_error, s.path_efficiency,
                  s.min_clearance, s.collisions);
    }
    std::printf(
        "| seed 000 Table 4 (house world) | 96 | 44.91 | 0.22 | 0.12 | 0.23 | 0.69 | - | 3 "
        "|\n");
    return 0;
  }

  std::printf(
      "| config | success %% | time s | net vel. m/s | goal err. m | final err. m | path eff. |\n");
  std::printf("| --- | --- | --- | --- | --- | --- | --- |\n");
  for (std::size_t c = 0; c < configurations.size(); ++c) {
    std::vector<ev::HomingResult> results;
    for (std::size_t t = 0; t < targets.size(); ++t) {
      results.push_back(ev::runHomingTrial(ev::homingControllerStep(params), targets[t].first,
                                           targets[t].second, configurations[c], config,
                                           seed * 1000 + c * 100 + t));
    }
    const auto s = ev::summarize(results);
    std::printf("| %s | %.0f | %.2f | %.2f | %.2f | %.2f | %.2f |\n",
                configurations[c].name.c_str(), 100.0 * s.success_rate, s.time, s.net_velocity,
                s.goal_error, s.final_error, s.path_efficiency);
    std::printf("| seed 000 | %.0f | %.2f | %.2f | %.2f | %.2f | %.2f |\n", kPaper[c][0],
                kPaper[c][1], kPaper[c][2], kPaper[c][3], kPaper[c][4], kPaper[c][5]);
  }
  return 0;
}
