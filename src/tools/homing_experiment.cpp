// SPDX-License-Identifier: BSD-3-Clause
// Reproduces seed 000's Tables 2-3 with the homing_controller node's law
// (control::HomingController, config/homing_controller.yaml's defaults, the distance as a
// UWB range) on the simulator's unicycle robot: the robot starts at the
// origin facing +x, 10 random beacons per quadrant of the -10..10 m square, the five
// uniform-noise configurations of Table 2. Prints a Markdown table beside the paper's.
//   homing_experiment [--per-quadrant N] [--seed S] [--max-linear V] [--arrival D] [--tau T]
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

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

}  // namespace

int main(int argc, char** argv) {
  int per_quadrant = 10;
  unsigned long seed = 1;
  double max_linear = 1.0;
  radio_follow::control::HomingControllerParams params;
  params.distance_source = "uwb";
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string flag = argv[i];
    if (flag == "--per-quadrant") {
      per_quadrant = std::atoi(argv[i + 1]);
    } else if (flag == "--seed") {
      seed = std::strtoul(argv[i + 1], nullptr, 10);
    } else if (flag == "--max-linear") {
      max_linear = std::atof(argv[i + 1]);
    } else if (flag == "--arrival") {
      params.homing.arrival_distance = std::atof(argv[i + 1]);
    } else if (flag == "--tau") {
      params.homing.tau = std::atof(argv[i + 1]);
    } else {
      std::fprintf(stderr, "unknown option %s\n", flag.c_str());
      return 2;
    }
  }
  if (per_quadrant < 1 || !(max_linear > 0.0)) {
    std::fprintf(stderr, "--per-quadrant must be >= 1 and --max-linear > 0\n");
    return 2;
  }
  params.homing.max_linear = max_linear;
  params.validate();
  radio_follow::evaluation::HomingTrialConfig config;
  config.robot.max_linear = max_linear;
  const auto targets = radio_follow::evaluation::homingTargets(per_quadrant, 10.0, 1.0, seed);

  std::printf(
      "| config | success %% | time s | net vel. m/s | goal err. m | final err. m | path eff. |\n");
  std::printf("| --- | --- | --- | --- | --- | --- | --- |\n");
  const auto configurations = radio_follow::evaluation::seed000NoiseConfigurations();
  for (std::size_t c = 0; c < configurations.size(); ++c) {
    std::vector<radio_follow::evaluation::HomingResult> results;
    for (std::size_t t = 0; t < targets.size(); ++t) {
      results.push_back(radio_follow::evaluation::runHomingTrial(
          radio_follow::evaluation::homingControllerStep(params), targets[t].first, targets[t].second,
          configurations[c], config, seed * 1000 + c * 100 + t));
    }
    const auto s = radio_follow::evaluation::summarize(results);
    std::printf("| %s | %.0f | %.2f | %.2f | %.2f | %.2f | %.2f |\n",
                configurations[c].name.c_str(), 100.0 * s.success_rate, s.time, s.net_velocity,
                s.goal_error, s.final_error, s.path_efficiency);
    std::printf("| seed 000 | %.0f | %.2f | %.2f | %.2f | %.2f | %.2f |\n", kPaper[c][0],
                kPaper[c][1], kPaper[c][2], kPaper[c][3], kPaper[c][4], kPaper[c][5]);
  }
  return 0;
}
