// SPDX-License-Identifier: BSD-3-Clause
// Runs one follow scenario in the lockstep closed loop (sim/closed_loop.hpp) with the
// shipped configuration, as demo.launch runs it through ROS, and prints the follow
// evaluator's report (the same metrics.json keys). Deterministic: the same arguments
// print the same report.
//   closed_loop [--layout spot] [--scenario outdoor_loop] [--controller velocity_controller]
//               [--seed 1] [--config-dir DIR] [--controller-params FILE]
//               [--locator-overrides FILE] [--outage SENSOR:AT:DURATION]... [--csv FILE]
//               [--sensor-profile ideal|realistic] [--hardware-seed N]
// --sensor-profile replaces config/simulator.yaml's; --hardware-seed (default: the seed)
// picks the simulated robot, which the realistic profile calibrates before the run.
#include "radio_follow/evaluation/closed_loop.hpp"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <optional>
#include <string>

#include "radio_follow/common/param_error.hpp"

namespace {

int usage(const std::string& problem) {
  std::fprintf(stderr,
               "closed_loop: %s\nusage: closed_loop [--layout L] [--scenario S] [--controller "
               "velocity_controller|path_follower] [--seed N] [--config-dir DIR] "
               "[--controller-params FILE] [--locator-overrides FILE] "
               "[--outage SENSOR:AT:DURATION]... [--csv FILE] "
               "[--sensor-profile ideal|realistic] [--hardware-seed N]\n",
               problem.c_str());
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  using radio_follow::evaluation::FollowController;
  std::string layout = "spot";
  std::string scenario = "outdoor_loop";
  std::string controller = "velocity_controller";
  std::string config_dir = RF_CONFIG_DIR;
  std::string controller_params;
  std::string locator_overrides;
  std::string csv;
  std::string profile;
  int seed = 1;
  std::optional<int> hardware_seed;
  std::vector<radio_follow::evaluation::SensorOutage> outages;
  for (int i = 1; i < argc; i += 2) {
    const std::string flag = argv[i];
    if (i + 1 >= argc) {
      return usage("missing value after " + flag);
    }
    const std::string value = argv[i + 1];
    if (flag == "--layout") {
      layout = value;
    } else if (flag == "--scenario") {
      scenario = value;
    } else if (flag == "--controller") {
      controller = value;
    } else if (flag == "--seed") {
      seed = std::atoi(value.c_str());
    } else if (flag == "--config-dir") {
      config_dir = value;
    } else if (flag == "--controller-params") {
      controller_params = value;
    } else if (flag == "--locator-overrides") {
      locator_overrides = value;
    } else if (flag == "--sensor-profile") {
      profile = value;
    } else if (flag == "--hardware-seed") {
      hardware_seed = std::atoi(value.c_str());
    } else if (flag == "--csv") {
      csv = value;
    } else if (flag == "--outage") {
      const std::size_t a = value.find(':');
      const std::size_t b = value.find(':', a == std::string::npos ? a : a + 1);
      if (a == std::string::npos || b == std::string::npos) {
        return usage("--outage wants SENSOR:AT:DURATION, got " + value);
      }
      outages.push_back({value.substr(0, a), std::atof(value.substr(a + 1, b - a - 1).c_str()),
                         std::atof(value.substr(b + 1).c_str())});
    } else {
      return usage("unknown option " + flag);
    }
  }
  if (controller != "velocity_controller" && controller != "path_follower") {
    return usage("--controller must be velocity_controller or path_follower");
  }
  try {
    radio_follow::evaluation::ClosedLoopConfig config =
        radio_follow::evaluation::loadClosedLoopConfig(
            config_dir, layout, scenario,
            controller == "path_follower" ? FollowController::kPathFollower
                                          : FollowController::kVelocity,
            seed, controller_params, locator_overrides,
            profile.empty() ? std::nullopt
                            : std::optional(radio_follow::sim::parseSensorProfile(
                                  profile, "--sensor-profile")));
    config.outages = outages;
    if (hardware_seed) {
      radio_follow::require(*hardware_seed >= 0, "--hardware-seed", *hardware_seed,
                            "an integer >= 0");
      config.world.hardware_seed = static_cast<std::uint64_t>(*hardware_seed);
    }
    radio_follow::evaluation::ClosedLoop loop(config);
    const radio_follow::control::FollowReport report = loop.run();
    std::printf("%s\n", report.toJson().c_str());
    if (!csv.empty()) {
      std::ofstream(csv) << loop.metrics().toCsv();
    }
    return report.failures.empty() ? 0 : 1;
  } catch (const radio_follow::ParamError& e) {
    std::fprintf(stderr, "closed_loop: %s\n", e.what());
    return 2;
  }
}
