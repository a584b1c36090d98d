// SPDX-License-Identifier: BSD-3-Clause
// The lab program: `lab <command> [options]` runs one of the lab's experiment and figure
// tools (src/lab/<command>.cpp). Built with RADIO_FOLLOW_BUILD_LAB, never installed.
#include <cstdio>
#include <string>

#include "lab_commands.hpp"

namespace {

namespace lab = radio_follow::lab;

struct Command {
  const char* name;
  const char* summary;
  int (*run)(int argc, char** argv);
};

const Command kCommands[] = {
    {"closed_loop", "one follow scenario in the lockstep closed loop; prints its report",
     lab::closedLoopMain},
    {"experiments", "test/experiments.yaml's closed-loop experiments over seeds 1..N",
     lab::experimentsMain},
    {"homing_experiment", "seed 000's homing Tables 2-3 (and Table 4's analogue)",
     lab::homingExperimentMain},
    {"layout_calibration", "a layout calibrated by the simulated calibration run",
     lab::layoutCalibrationMain},
    {"locator_cold_starts", "the locator started from nothing, many times (mirror locks)",
     lab::locatorColdStartsMain},
    {"locator_montecarlo", "the solver's accuracy against the Cramer-Rao bound, NLOS test",
     lab::locatorMontecarloMain},
    {"locator_pcrb", "a walking person: the locator against the posterior Cramer-Rao bound",
     lab::locatorPcrbMain},
    {"rssi_calibration_fit", "the log-distance RSSI model fitted to a distance,rssi CSV",
     lab::rssiCalibrationFitMain},
    {"rssi_filter_compare", "RSSI filters on simulated readings (seed 002's Table 2)",
     lab::rssiFilterCompareMain},
    {"standing_experiments", "the thesis's Experiments 1-2 and the single-board heading",
     lab::standingExperimentsMain},
    {"trilateration_compare", "the locator's initial guess against seed 002's QR trilateration",
     lab::trilaterationCompareMain},
};

void listCommands(std::FILE* out) {
  std::fprintf(out,
               "usage: lab COMMAND [options]   (lab COMMAND --help: the command's options)\n"
               "The lab's experiment and figure tools (doc/results.md has each figure's "
               "command).\n\ncommands:\n");
  for (const Command& c : kCommands) {
    std::fprintf(out, "  %-23s%s\n", c.name, c.summary);
  }
}

}  // namespace

int main(int argc, char** argv) {
  const std::string name = argc > 1 ? argv[1] : "";
  if (name == "-h" || name == "--help") {
    listCommands(stdout);
    return 0;
  }
  for (const Command& c : kCommands) {
    if (name == c.name) {
      return c.run(argc - 1, argv + 1);
    }
  }
  if (name.empty()) {
    std::fprintf(stderr, "lab: no command\n");
  } else {
    std::fprintf(stderr, "lab: unknown command '%s'\n", name.c_str());
  }
  listCommands(stderr);
  return 2;
}
