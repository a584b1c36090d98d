// SPDX-License-Identifier: BSD-3-Clause
#include "placement_advisor/options.hpp"

#include <cstdio>

#include "radio_follow/common/command_line.hpp"
#include "radio_follow/common/param_error.hpp"

namespace radio_follow {
namespace placement_advisor {
namespace {

namespace rf = radio_follow;
namespace est = radio_follow::estimation;

std::string csvNumber(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof(buffer), "%g", value);
  return buffer;
}

rf::cli::CommandLine commandLine() {
  rf::cli::CommandLine cli(
      "placement_advisor",
      "usage: placement_advisor LAYOUT.yaml [--compare OTHER.yaml] [--extent M]\n"
      "         [--resolution M] [--height M] [--3d] [--sectors N] [--weak-factor K]\n"
      "         [--plot PLOT_SCRIPT.py] --out DIR\n"
      "       placement_advisor --optimise REGION.yaml [--method exhaustive|greedy|random|all]\n"
      "         [--objective mean|p90|max|all] [--modules N] [--boards N] [--restarts N]\n"
      "         [--samples N] [--runs N] [--seed S] [--max-combinations N] [--limit M]\n"
      "         [--grow modules|boards|both] [--compare REFERENCE.yaml] [--3d]\n"
      "         [--plot PLOT_SCRIPT.py] --out DIR\n",
      "The Cramer-Rao bound of the target position over a grid around the robot for a\n"
      "layout (the locator's YAML format, LAYOUT.yaml), summarised per distance ring and\n"
      "direction, with the weak directions and the thesis's placement guidelines\n"
      "(doc/placement_advisor.md). With --optimise, the search for the best layout in a\n"
      "mounting region instead: the best layout is written as DIR/<region>_optimised.yaml\n"
      "and mapped. No ROS master needed.\n");
  namespace po = rf::cli::po;
  const auto text = [](const char* name) { return po::value<std::string>()->value_name(name); };
  const auto fallback = [](const std::string& value) { return " (default " + value + ")"; };
  const est::AdvisorConfig map;
  const OptimiseOptions search;
  cli.options()("compare", text("OTHER.yaml"), "map a second layout beside it")(
      "extent", text("M"),
      ("half-width of the square grid, m" + fallback(csvNumber(map.extent))).c_str())(
      "resolution", text("M"), ("grid spacing, m" + fallback(csvNumber(map.resolution))).c_str())(
      "height", text("M"),
      ("the tag's height, m" + fallback(csvNumber(map.target_height))).c_str())(
      "3d", po::bool_switch(), "bound the 3D position (default: planar)")(
      "sectors", text("N"),
      ("directions of the summary" + fallback(std::to_string(map.sectors))).c_str())(
      "weak-factor", text("K"),
      ("a direction is weak beyond K x the median bound" + fallback(csvNumber(map.weak_factor)))
          .c_str())("plot", text("SCRIPT.py"),
                    "draw DIR/<layout>.png with scripts/plot_placement.py")(
      "out", text("DIR"), "write <layout>_map.csv and <layout>_summary.json here")(
      "optimise", text("REGION.yaml"), "search the best layout in a mounting region")(
      "method", text("NAME"),
      ("the search: exhaustive, greedy, random or all" + fallback(search.methods.front())).c_str())(
      "objective", text("NAME"),
      "what it minimises: mean, p90, max or all (default: the region's)")(
      "modules", text("N"), "UWB modules to place, 0 to 16 (default: the region's)")(
      "boards", text("N"), "AoA boards to place, 0 to 16 (default: the region's)")(
      "restarts", text("N"),
      ("greedy restarts" + fallback(std::to_string(search.restarts))).c_str())(
      "samples", text("N"),
      ("random layouts tried" + fallback(std::to_string(search.samples))).c_str())(
      "runs", text("N"),
      ("repeats of each search" + fallback(std::to_string(search.runs))).c_str())(
      "seed", text("S"), ("random seed" + fallback(std::to_string(search.seed))).c_str())(
      "max-combinations", text("N"),
      ("the exhaustive search's limit" + fallback(csvNumber(search.max_combinations))).c_str())(
      "limit", text("M"), "find the fewest sensors whose bound reaches M")(
      "grow", text("WHAT"),
      ("with --limit, add modules, boards or both" + fallback(search.grow_text)).c_str());
  cli.positional("layout", -1);
  return cli;
}

std::vector<std::string> choices(const std::string& option, const std::string& text,
                                 const std::vector<std::string>& allowed) {
  if (text == "all") {
    return allowed;
  }
  std::vector<std::string> listed = allowed;
  listed.push_back("all");
  return {rf::cli::choice(option, text, listed)};
}

Options read(const rf::cli::po::variables_map& values) {
  using rf::cli::CommandLine;
  using rf::cli::number;
  using rf::cli::wholeNumber;
  const auto given = [&](const char* name) { return values.count(name) > 0; };
  const auto value = [&](const char* name) { return CommandLine::text(values, name); };
  Options opt;
  OptimiseOptions o;
  const std::vector<std::string> layouts = CommandLine::texts(values, "layout");
  if (layouts.size() > 1) {
    throw rf::cli::UsageError("more than one layout given (a second one goes after --compare)");
  }
  opt.layout = layouts.empty() ? "" : layouts.front();
  if (given("compare")) {
    opt.compare = value("compare");
  }
  opt.out = value("out");
  if (given("plot")) {
    opt.plot_script = value("plot");
  }
  const auto distance = [&](const char* name, double& field) {
    if (given(name)) {
      field = number(std::string("--") + name, value(name), "a number");
    }
  };
  distance("extent", opt.config.extent);
  distance("resolution", opt.config.resolution);
  distance("height", opt.config.target_height);
  distance("weak-factor", opt.config.weak_factor);
  if (given("sectors")) {
    opt.config.sectors = static_cast<int>(wholeNumber("--sectors", value("sectors"), 1, 360,
                                                      "a whole number of sectors from 1 to 360"));
  }
  opt.config.planar = !values["3d"].as<bool>();
  const auto whole = [&](const char* name, double lo, double hi) {
    return wholeNumber(std::string("--") + name, value(name), lo, hi,
                       "a whole number from " + csvNumber(lo) + " to " + csvNumber(hi));
  };
  o.region = value("optimise");
  if (given("method")) {
    o.methods = choices("--method", value("method"), {"exhaustive", "greedy", "random"});
  }
  if (given("objective")) {
    o.objectives = choices("--objective", value("objective"), {"mean", "p90", "max"});
  }
  if (given("modules")) {
    o.modules = static_cast<int>(whole("modules", 0, 16));
  }
  if (given("boards")) {
    o.boards = static_cast<int>(whole("boards", 0, 16));
  }
  if (given("restarts")) {
    o.restarts = static_cast<int>(whole("restarts", 1, 1e6));
  }
  if (given("samples")) {
    o.samples = static_cast<int>(whole("samples", 1, 1e8));
  }
  if (given("runs")) {
    o.runs = static_cast<int>(whole("runs", 1, 1000));
  }
  if (given("seed")) {
    o.seed = static_cast<std::uint64_t>(whole("seed", 0, 1e9));
  }
  if (given("limit")) {
    o.limit = number("--limit", value("limit"), "a number");
  }
  if (given("grow")) {
    o.grow_text = rf::cli::choice("--grow", value("grow"), {"modules", "boards", "both"});
    o.grow = o.grow_text == "modules"  ? est::GrowSensors::kModules
             : o.grow_text == "boards" ? est::GrowSensors::kBoards
                                       : est::GrowSensors::kBoth;
  }
  if (given("max-combinations")) {
    o.max_combinations = number("--max-combinations", value("max-combinations"), "a number");
  }
  if (!o.region.empty()) {
    opt.optimise = o;
    rf::require(opt.layout.empty(), "LAYOUT.yaml", opt.layout,
                "no layout with --optimise (the reference goes after --compare)");
  } else {
    rf::require(!opt.layout.empty(), "LAYOUT.yaml", std::string("(none)"), "a layout file");
  }
  rf::require(!opt.out.empty(), "--out", std::string("(none)"), "an output directory");
  opt.config.validate();
  return opt;
}

}  // namespace

Options parse(int argc, char** argv) {
  return commandLine().parse(argc, argv, read);
}

}  // namespace placement_advisor
}  // namespace radio_follow
