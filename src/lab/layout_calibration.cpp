// SPDX-License-Identifier: BSD-3-Clause
// Runs the simulated calibration run (evaluation/calibration_run.hpp) for a layout on the
// simulated robot of a hardware seed and prints the calibrated layout (writeCalibratedLayout:
// only the modules' calibration and the boards' yaw change), each fit's figures in its
// header comment: how the shipped layouts' calibrations for
// the simulator's default hardware are made (doc/simulator.md, "Calibration run").
//   layout_calibration [--layout spot] [--hardware-seed 1] [--seed 1] [--config-dir DIR]
// The sensors are config/simulator.yaml's with the realistic profile.
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <map>
#include <string>
#include <vector>

#include "radio_follow/common/angles.hpp"
#include "radio_follow/common/param_error.hpp"
#include "radio_follow/common/tool_options.hpp"
#include "radio_follow/common/yaml_keys.hpp"
#include "radio_follow/common/yaml_params.hpp"
#include "radio_follow/evaluation/calibration_run.hpp"

namespace {

int usage(const std::string& problem) {
  std::fprintf(stderr,
               "layout_calibration: %s\nusage: layout_calibration [--layout L] "
               "[--hardware-seed N] [--seed N] [--config-dir DIR]\n",
               problem.c_str());
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  namespace rf = radio_follow;
  // Every option takes a value; the map holds the defaults.
  std::map<std::string, std::string> options{{"--layout", "spot"},
                                             {"--hardware-seed", "1"},
                                             {"--seed", "1"},
                                             {"--config-dir", RF_CONFIG_DIR}};
  if (const auto problem = rf::readToolOptions(argc, argv, options)) {
    return usage(*problem);
  }
  const std::string layout_name = options["--layout"];
  const std::string config_dir = options["--config-dir"];
  try {
    const auto hardware_seed =
        static_cast<int>(rf::toolCount("--hardware-seed", options["--hardware-seed"]));
    const auto seed = static_cast<int>(rf::toolCount("--seed", options["--seed"]));
    const std::string path = config_dir + "/layouts/" + layout_name + ".yaml";
    const rf::Layout layout = rf::loadLayoutFile(path, "--layout");
    rf::sim::WorldConfig world;
    world.load(rf::YamlParams::fromFile(config_dir + "/simulator.yaml"));
    world.profile = rf::sim::SensorProfile::kRealistic;
    world.hardware_seed = static_cast<std::uint64_t>(hardware_seed);
    world.seed = static_cast<std::uint64_t>(seed);
    const rf::evaluation::CalibrationResult result = rf::evaluation::runCalibration(layout, world);
    std::vector<std::string> header{"layout_calibration --layout " + layout_name +
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
    std::fprintf(stderr, "layout_calibration: %s\n", e.what());
    return 2;
  }
}
