// SPDX-License-Identifier: BSD-3-Clause
// Runs the closed-loop experiments of test/experiments.yaml in the lockstep loop
// (sim/closed_loop.hpp) with the shipped configuration over noise seeds 1..N and prints
// the Markdown table of doc/experiments.md (ranges over the seeds); then, when some
// experiments' scenarios have obstacles, their table of obstacle metrics (success: runs
// that kept following without a collision, evaluation::keptFollowing); then one line per
// broken threshold. Exit status 1 when any run broke one. Deterministic: the same
// arguments print the same table.
//   experiments [--seeds N] [--file test/experiments.yaml] [--config-dir DIR]
//               [--sensor-profile ideal|realistic] [name ...]
// --sensor-profile replaces every experiment's (default: the file's); with realistic each
// seed is its own simulated robot, calibrated by the calibration run before it follows.
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iterator>
#include <limits>
#include <string>
#include <vector>

#include "radio_follow/common/param_error.hpp"
#include "radio_follow/evaluation/experiment.hpp"

namespace {

struct Column {
  const char* title;
  double (*value)(const radio_follow::control::FollowReport&);
  const char* format;  ///< of one number
  double scale;
};

const Column kColumns[] = {
    {"min gap while moving (m)", [](const auto& r) { return r.min_gap_while_moving; }, "%.2f", 1},
    {"gap held (%)", [](const auto& r) { return r.gap_within_tolerance; }, "%.0f", 100},
    {"mean gap (m)", [](const auto& r) { return r.gap_mean; }, "%.2f", 1},
    {"est. error median (m)", [](const auto& r) { return r.estimate_error_median; }, "%.3f", 1},
    {"est. error p95 (m)", [](const auto& r) { return r.estimate_error_p95; }, "%.2f", 1},
    {"path deviation max (m)", [](const auto& r) { return r.path_deviation_max; }, "%.2f", 1},
    {"NEES median (1.39)", [](const auto& r) { return r.estimate_nees_median; }, "%.2f", 1},
    {"inside 95 % ellipse", [](const auto& r) { return r.estimate_within_95; }, "%.2f", 1},
};

/// "a" or "a-b" for the range of the finite values, formatted alike ("nan" if none is;
/// "a-b (n nan)" when some are not: a metric without samples on some seeds).
std::string range(const std::vector<double>& all, const char* format, double scale) {
  std::vector<double> values;
  std::copy_if(all.begin(), all.end(), std::back_inserter(values),
               [](double v) { return std::isfinite(v); });
  if (values.empty()) {
    return "nan";
  }
  const std::string missing = values.size() == all.size()
                                  ? ""
                                  : " (" + std::to_string(all.size() - values.size()) + " nan)";
  const auto [lo, hi] = std::minmax_element(values.begin(), values.end());
  char a[32];
  char b[32];
  std::snprintf(a, sizeof(a), format, scale * *lo);
  std::snprintf(b, sizeof(b), format, scale * *hi);
  return (std::string(a) == b ? std::string(a) : std::string(a) + "-" + b) + missing;
}

/// One experiment's row of the obstacle table: its controller parameters, the share of
/// runs that kept following without a collision, the collisions, the smallest clearance.
std::string obstacleRow(const radio_follow::evaluation::Experiment& experiment, int runs,
                        int kept_following, int collisions, double min_clearance) {
  std::string params = "shipped";
  if (experiment.controller_params.IsMap()) {
    YAML::Emitter text;
    text << YAML::Flow << experiment.controller_params;
    params = text.c_str();
  }
  char row[300];
  std::snprintf(row, sizeof(row), "| %s | %s | %.0f | %d of %d | %.2f |\n", experiment.name.c_str(),
                params.c_str(), 100.0 * kept_following / runs, collisions, runs, min_clearance);
  return row;
}

}  // namespace

int main(int argc, char** argv) {
  int seeds = 8;
  std::string file = RF_EXPERIMENTS_FILE;
  std::string config_dir = RF_CONFIG_DIR;
  std::string profile;
  std::vector<std::string> names;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if ((arg == "--seeds" || arg == "--file" || arg == "--config-dir" ||
         arg == "--sensor-profile") &&
        i + 1 < argc) {
      const std::string value = argv[++i];
      if (arg == "--seeds") {
        seeds = std::atoi(value.c_str());
      } else if (arg == "--sensor-profile") {
        profile = value;
      } else if (arg == "--file") {
        file = value;
      } else {
        config_dir = value;
      }
    } else if (arg.rfind("--", 0) == 0) {
      std::fprintf(stderr,
                   "usage: experiments [--seeds N] [--file FILE] [--config-dir DIR] "
                   "[--sensor-profile ideal|realistic] [name ...]\n");
      return 2;
    } else {
      names.push_back(arg);
    }
  }
  if (seeds < 1) {
    std::fprintf(stderr, "experiments: --seeds must be >= 1\n");
    return 2;
  }
  try {
    std::vector<std::string> broken;
    std::string obstacle_rows;
    std::printf("| experiment |");
    for (const Column& c : kColumns) {
      std::printf(" %s |", c.title);
    }
    std::printf("\n|---|");
    for (std::size_t i = 0; i < std::size(kColumns); ++i) {
      std::printf("---|");
    }
    std::printf("\n");
    for (auto experiment : radio_follow::evaluation::loadExperiments(file)) {
      if (!names.empty() && std::find(names.begin(), names.end(), experiment.name) == names.end()) {
        continue;
      }
      if (!profile.empty()) {
        experiment.sensor_profile =
            radio_follow::sim::parseSensorProfile(profile, "--sensor-profile");
      }
      std::vector<std::vector<double>> values(std::size(kColumns));
      int kept_following = 0;
      int collisions = 0;
      double min_clearance = std::numeric_limits<double>::infinity();  // no obstacles
      for (int seed = 1; seed <= seeds; ++seed) {
        const auto result = radio_follow::evaluation::runExperiment(experiment, config_dir, seed);
        for (std::size_t i = 0; i < std::size(kColumns); ++i) {
          values[i].push_back(kColumns[i].value(result.report));
        }
        kept_following += result.kept_following;
        collisions += result.report.collided;
        min_clearance = std::min(min_clearance, result.report.min_clearance);
        for (const std::string& v : result.violations) {
          broken.push_back(experiment.name + ", seed " + std::to_string(seed) + ": " + v);
        }
      }
      std::printf("| %s |", experiment.name.c_str());
      for (std::size_t i = 0; i < std::size(kColumns); ++i) {
        std::printf(" %s |", range(values[i], kColumns[i].format, kColumns[i].scale).c_str());
      }
      std::printf("\n");
      if (std::isfinite(min_clearance)) {
        obstacle_rows += obstacleRow(experiment, seeds, kept_following, collisions, min_clearance);
      }
    }
    if (!obstacle_rows.empty()) {
      std::printf(
          "\n| experiment | controller parameters | success (%%) | collisions | min clearance "
          "(m) |\n|---|---|---|---|---|\n%s",
          obstacle_rows.c_str());
    }
    std::printf("\nseeds 1-%d; sensor profile %s; %zu threshold(s) broken\n", seeds,
                profile.empty() ? "as in the file" : profile.c_str(), broken.size());
    for (const std::string& b : broken) {
      std::printf("BROKEN %s\n", b.c_str());
    }
    return broken.empty() ? 0 : 1;
  } catch (const radio_follow::ParamError& e) {
    std::fprintf(stderr, "experiments: %s\n", e.what());
    return 2;
  }
}
