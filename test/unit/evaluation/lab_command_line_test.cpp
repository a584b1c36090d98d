// SPDX-License-Identifier: BSD-3-Clause
// The lab program's command lines (src/lab/lab.cpp and its commands), run as a user runs
// them: the list of commands, each command's help, and a bad value refused with exit 2 and
// a message naming the option, the value and what is expected.
#include <gtest/gtest.h>

#include <string>

#include "../../support/run_tool.hpp"

namespace radio_follow {
namespace {

int runLab(const std::string& args, std::string& output) {
  return test::runTool("lab", args, output);
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

const char* const kCommands[] = {
    "closed_loop",         "experiments",          "homing_experiment",    "layout_calibration",
    "locator_cold_starts", "locator_montecarlo",   "locator_pcrb",         "rssi_calibration_fit",
    "rssi_filter_compare", "standing_experiments", "trilateration_compare"};

TEST(LabCommandLine, ListsEveryCommandAndPrintsEachOnesHelp) {
  std::string output;
  ASSERT_EQ(runLab("--help", output), 0) << output;
  for (const char* command : kCommands) {
    EXPECT_TRUE(contains(output, command)) << command << " missing from\n" << output;
    std::string help;
    EXPECT_EQ(runLab(std::string(command) + " --help", help), 0) << help;
    EXPECT_TRUE(contains(help, std::string("usage: lab ") + command)) << help;
  }
  EXPECT_EQ(runLab("", output), 2);
  EXPECT_EQ(runLab("frobnicate", output), 2);
  EXPECT_TRUE(contains(output, "unknown command 'frobnicate'")) << output;
}

TEST(LabCommandLine, RefusesABadValueNamingTheOptionAndWhatIsExpected) {
  struct Case {
    const char* args;
    const char* message;
  };
  const Case cases[] = {
      {"experiments --seeds 0", "--seeds '0': expected a whole number in [1, "},
      {"closed_loop --controller drone", "--controller 'drone': expected one of"},
      {"closed_loop --outage 5722:soon:3", "--outage '5722:soon:3': expected SENSOR:AT:DURATION"},
      {"locator_cold_starts --trials 2 --trace 5", "--trace '5': expected a trial index"},
      {"standing_experiments --experiment walk --sectors 37", "--sectors '37': expected"},
      {"locator_montecarlo --outliers 2", "--outliers '2': expected one of 0, 1"},
      {"homing_experiment --max-linear 0", "--max-linear '0': expected a speed > 0"},
      {"rssi_filter_compare --readings 12x", "--readings '12x': expected"},
      {"locator_pcrb --frobnicate 1", "frobnicate"},
      {"rssi_calibration_fit", "SAMPLES.csv"},
  };
  for (const Case& c : cases) {
    std::string output;
    EXPECT_EQ(runLab(c.args, output), 2) << c.args << "\n" << output;
    EXPECT_TRUE(contains(output, c.message)) << c.args << "\n" << output;
  }
}

}  // namespace
}  // namespace radio_follow
