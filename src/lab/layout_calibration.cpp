// SPDX-License-Identifier: BSD-3-Clause
// lab layout_calibration: a layout calibrated by the simulated calibration run
// (evaluation/calibration_run.hpp) on the simulated robot of a hardware seed.
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "lab_commands.hpp"
#include "radio_follow/common/angles.hpp"
#include "radio_follow/common/param_error.hpp"
#include "radio_follow/common/yaml_keys.hpp"
#include "radio_follow/common/yaml_params.hpp"
#include "radio_follow/evaluation/calibration_run.hpp"

namespace {

radio_follow::cli::CommandLine layoutCalibrationCommandLine() {
  namespace lab = radio_follow::lab;
  radio_follow::cli::CommandLine cli(
      "lab layout_calibration",
      "usage: lab layout_calibration [--layout L] [--hardware-seed N] [--seed N] "
      "[--config-dir DIR]\n",
      "Runs the simulated calibration run (evaluation/calibration_run.hpp) for a layout on the\n"
      "simulated robot of a hardware seed and prints the calibrated layout (only the modules'\n"
      "calibration and the boards' yaw change), each fit's figures in its header comment: how\n"
      "the shipped layouts' calibrations for the simulator's default hardware are made\n"
      "(doc/simulator.md, \"Calibration run\"). The sensors are config/simulator.yaml's with the\n"
      "realistic profile.\n");
  cli.options()("layout", lab::value("L", "spot"), "config/layouts/<L>.yaml")(
      "hardware-seed", lab::value("N", "1"), "the simulated robot")(
      "seed", lab::value("N", "1"), "the calibration run's noise seed")(
      "config-dir", lab::value("DIR", RF_CONFIG_DIR), "the shipped configuration's folder");
  return cli;
}

struct LayoutCalibrationOptions {
  std::string layout;
  int hardware_seed = 1;
  int seed = 1;
  std::string config_dir;
};

LayoutCalibrationOptions readLayoutCalibrationOptions(
    const radio_follow::lab::po::variables_map& values) {
  LayoutCalibrationOptions o;
  o.layout = values["layout"].as<std::string>();
  o.hardware_seed = static_cast<int>(radio_follow::lab::count(values, "hardware-seed", 0));
  o.seed = static_cast<int>(radio_follow::lab::count(values, "seed", 0));
  o.config_dir = values["config-dir"].as<std::string>();
  return o;
}

}  // namespace

int radio_follow::lab::layoutCalibrationMain(int argc, char** argv) {
  namespace rf = radio_follow;
  const LayoutCalibrationOptions o =
      layoutCalibrationCommandLine().parse(argc, argv, readLayoutCalibrationOptions);
  const std::string& layout_name = o.layout;
  const std::string& config_dir = o.config_dir;
  const int hardware_seed = o.hardware_seed;
  const int seed = o.seed;
  try {
    const std::string path = config_dir + "/layouts/" + layout_name + ".yaml";
    const rf::Layout layout = rf::loadLayoutFile(path, "--layout");
    rf::sim::WorldConfig world;
    world.load(rf::YamlParams::fromFile(config_dir + "/simulator.yaml"));
    world.profile = rf::sim::SensorProfile::kRealistic;
    world.hardware_seed = static_cast<std::uint64_t>(hardware_seed);
    world.seed = static_cast<std::uint64_t>(seed);
    const rf::evaluation::CalibrationResult result = rf::evaluation::runCalibration(layout, world);
    std::vector<std::string> header{"lab layout_calibration --layout " + layout_name +
                                    " --hardware-seed " + std::to_string(hardware_seed) +
                                    " --seed " + std::to_string(seed) +
                                    ": the simulated calibration run (doc/simulator.md)"};
    char line[200];
    for (const auto& m : result.modules) {
      std::snprintf(line, sizeof(line),
                    "%s: %zu samples (%zu refused), RMS error %.3f m raw, %.3f m calibrated",
                    m.id.c_str(), m.fit.used + m.fit.rejected, m.fit.rejected, m.fit.rms_before,
                    m.fit.rms_after);
      header.push_back(line);
    }
    for (const auto& b : result.boards) {
      std::snprintf(line, sizeof(line),
                    "%s: yaw offset %+.2f deg from %zu samples (%zu refused), sigma %.2f deg",
                    b.id.c_str(), rf::rad2deg(b.fit.yaw_offset), b.fit.used + b.fit.rejected,
                    b.fit.rejected, rf::rad2deg(b.fit.residual_sigma));
      header.push_back(line);
    }
    std::printf("%s", rf::writeCalibratedLayout(
                          rf::readConfigFile(path, "--layout", "a readable layout YAML file"), path,
                          result.update(), header)
                          .c_str());
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "lab layout_calibration: %s\n", e.what());
    return 2;
  }
}
