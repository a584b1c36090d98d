// SPDX-License-Identifier: BSD-3-Clause
// lab closed_loop: one follow scenario in the lockstep closed loop.
#include "radio_follow/evaluation/closed_loop.hpp"

#include <cstdio>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include "lab_commands.hpp"
#include "radio_follow/common/param_error.hpp"

namespace {

namespace ev = radio_follow::evaluation;

struct ClosedLoopOptions {
  std::string layout;
  std::string scenario;
  ev::FollowController controller = ev::FollowController::kVelocity;
  int seed = 1;
  std::string config_dir;
  std::string controller_params;
  std::string locator_overrides;
  std::string csv;
  std::optional<radio_follow::sim::SensorProfile> profile;
  std::optional<int> hardware_seed;
  std::vector<ev::SensorOutage> outages;
};

radio_follow::cli::CommandLine closedLoopCommandLine() {
  namespace lab = radio_follow::lab;
  radio_follow::cli::CommandLine cli(
      "lab closed_loop",
      "usage: lab closed_loop [--layout L] [--scenario S] [--controller "
      "velocity_controller|path_follower]\n"
      "         [--seed N] [--config-dir DIR] [--controller-params FILE] "
      "[--locator-overrides FILE]\n"
      "         [--outage SENSOR:AT:DURATION]... [--csv FILE] "
      "[--sensor-profile ideal|realistic]\n"
      "         [--hardware-seed N]\n",
      "Runs one follow scenario in the lockstep closed loop (evaluation/closed_loop.hpp) with\n"
      "the shipped configuration, as demo.launch runs it through ROS, and prints the follow\n"
      "evaluator's report (the same metrics.json keys). Deterministic: the same arguments\n"
      "print the same report. Exit 1 when the report has failures, 2 on a bad option or\n"
      "configuration.\n");
  cli.options()("layout", lab::value("L", "spot"), "config/layouts/<L>.yaml")(
      "scenario", lab::value("S", "outdoor_loop"), "config/scenarios/<S>.yaml")(
      "controller", lab::value("C", "velocity_controller"), "velocity_controller or path_follower")(
      "seed", lab::value("N", "1"), "the noise seed (and the simulated robot's), >= 0")(
      "config-dir", lab::value("DIR", RF_CONFIG_DIR), "the shipped configuration's folder")(
      "controller-params", lab::value("FILE"), "YAML over the shipped controller files")(
      "locator-overrides", lab::value("FILE"), "YAML over config/locator.yaml")(
      "outage", lab::po::value<std::vector<std::string>>()->value_name("SENSOR:AT:DURATION"),
      "the sensor (a module or board ID) silent from AT for DURATION s; repeatable")(
      "csv", lab::value("FILE"), "also write the run's metrics per step to FILE")(
      "sensor-profile", lab::value("P"),
      "ideal or realistic; replaces config/simulator.yaml's (realistic: the simulated robot "
      "is calibrated before the run)")("hardware-seed", lab::value("N"),
                                       "the simulated robot, >= 0; default: the seed");
  return cli;
}

ev::SensorOutage outage(const std::string& text) {
  const radio_follow::cli::UsageError bad("--outage '" + text +
                                          "': expected SENSOR:AT:DURATION (AT and DURATION in s)");
  const std::size_t a = text.find(':');
  const std::size_t b = a == std::string::npos ? a : text.find(':', a + 1);
  if (b == std::string::npos) {
    throw bad;
  }
  const auto seconds = [&](const std::string& part) {
    try {
      return radio_follow::cli::number("--outage", part, "seconds");
    } catch (const radio_follow::cli::UsageError&) {
      throw bad;
    }
  };
  return {text.substr(0, a), seconds(text.substr(a + 1, b - a - 1)), seconds(text.substr(b + 1))};
}

ClosedLoopOptions readClosedLoopOptions(const radio_follow::lab::po::variables_map& values) {
  namespace cli = radio_follow::cli;
  ClosedLoopOptions o;
  o.layout = values["layout"].as<std::string>();
  o.scenario = values["scenario"].as<std::string>();
  o.controller = cli::choice("--controller", values["controller"].as<std::string>(),
                             {"velocity_controller", "path_follower"}) == "path_follower"
                     ? ev::FollowController::kPathFollower
                     : ev::FollowController::kVelocity;
  o.seed = static_cast<int>(radio_follow::lab::count(values, "seed", 0));
  o.config_dir = values["config-dir"].as<std::string>();
  o.controller_params = cli::CommandLine::text(values, "controller-params");
  o.locator_overrides = cli::CommandLine::text(values, "locator-overrides");
  o.csv = cli::CommandLine::text(values, "csv");
  if (values.count("sensor-profile")) {
    o.profile = radio_follow::sim::parseSensorProfile(values["sensor-profile"].as<std::string>(),
                                                      "--sensor-profile");
  }
  if (values.count("hardware-seed")) {
    o.hardware_seed = static_cast<int>(radio_follow::lab::count(values, "hardware-seed", 0));
  }
  for (const std::string& text : cli::CommandLine::texts(values, "outage")) {
    o.outages.push_back(outage(text));
  }
  return o;
}

}  // namespace

int radio_follow::lab::closedLoopMain(int argc, char** argv) {
  const ClosedLoopOptions o = closedLoopCommandLine().parse(argc, argv, readClosedLoopOptions);
  try {
    ev::ClosedLoopConfig config =
        ev::loadClosedLoopConfig(o.config_dir, o.layout, o.scenario, o.controller, o.seed,
                                 o.controller_params, o.locator_overrides, o.profile);
    config.outages = o.outages;
    if (o.hardware_seed) {
      config.world.hardware_seed = static_cast<std::uint64_t>(*o.hardware_seed);
    }
    ev::ClosedLoop loop(config);
    const control::FollowReport report = loop.run();
    std::printf("%s\n", report.toJson().c_str());
    if (!o.csv.empty()) {
      std::ofstream(o.csv) << loop.metrics().toCsv();
    }
    return report.failures.empty() ? 0 : 1;
  } catch (const ParamError& e) {
    std::fprintf(stderr, "lab closed_loop: %s\n", e.what());
    return 2;
  }
}
