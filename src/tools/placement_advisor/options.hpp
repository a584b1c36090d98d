// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// placement_advisor's command line (boost::program_options, common/command_line.hpp):
// what the tool is asked to map or search.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "radio_follow/estimation/placement_advisor.hpp"
#include "radio_follow/estimation/placement_search.hpp"

namespace radio_follow {
namespace placement_advisor {

/// --optimise: the search to run and what to change in the region file.
struct OptimiseOptions {
  std::string region;
  std::vector<std::string> methods{"greedy"};
  std::vector<std::string> objectives;  ///< empty: the region's
  std::optional<int> modules;
  std::optional<int> boards;
  int restarts = 20;
  int samples = 2000;
  int runs = 1;
  std::uint64_t seed = 1;
  double max_combinations = 2e6;
  std::optional<double> limit;  ///< m: find the fewest sensors reaching it
  estimation::GrowSensors grow = estimation::GrowSensors::kBoth;
  std::string grow_text = "both";
};

struct Options {
  std::string layout;
  std::optional<OptimiseOptions> optimise;
  std::optional<std::string> compare;
  std::string out;
  std::optional<std::string> plot_script;
  estimation::AdvisorConfig config;
};

/// The command line as options; prints the help and exits 0 on -h/--help, prints the
/// problem and the usage and exits 2 on a bad line (an unknown option, a value that is not
/// what the option expects, no layout or no --out).
Options parse(int argc, char** argv);

}  // namespace placement_advisor
}  // namespace radio_follow
