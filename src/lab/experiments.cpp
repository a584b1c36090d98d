// SPDX-License-Identifier: BSD-3-Clause
// lab experiments: the closed-loop experiments of test/experiments.yaml over seeds 1..N
// (evaluation/experiment.hpp), as doc/experiments.md's tables.
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iterator>
#include <limits>
#include <string>
#include <vector>

#include "lab_commands.hpp"
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

radio_follow::cli::CommandLine experimentsCommandLine() {
  namespace lab = radio_follow::lab;
  radio_follow::cli::CommandLine cli(
      "lab experiments",
      "usage: lab experiments [--seeds N] [--file FILE] [--config-dir DIR]\n"
      "         [--sensor-profile ideal|realistic] [name ...]\n",
      "Runs the closed-loop experiments of test/experiments.yaml (all, or those named) in the\n"
      "lockstep loop with the shipped configuration over noise seeds 1..N and prints the\n"
      "Markdown table of doc/experiments.md (ranges over the seeds); then, when some\n"
      "experiments' scenarios have obstacles, their table of obstacle metrics (success: runs\n"
      "that kept following without a collision); then one line per broken threshold. Exit 1\n"
      "when any run broke one, 2 on a bad option or file. Deterministic.\n");
  cli.options()("seeds", lab::value("N", "8"), "noise seeds 1..N")(
      "file", lab::value("FILE", RF_EXPERIMENTS_FILE), "the experiments and their thresholds")(
      "config-dir", lab::value("DIR", RF_CONFIG_DIR), "the shipped configuration's folder")(
      "sensor-profile", lab::value("P"),
      "ideal or realistic, for every experiment (default: the file's); realistic: each seed "
      "is its own simulated robot, calibrated by the calibration run before it follows");
  cli.positional("name", -1);
  return cli;
}

struct ExperimentsOptions {
  int seeds = 8;
  std::string file;
  std::string config_dir;
  std::string profile;
  std::vector<std::string> names;
};

ExperimentsOptions readExperimentsOptions(const radio_follow::lab::po::variables_map& values) {
  using radio_follow::cli::CommandLine;
  ExperimentsOptions o;
  o.seeds = static_cast<int>(radio_follow::lab::count(values, "seeds", 1));
  o.file = values["file"].as<std::string>();
  o.config_dir = values["config-dir"].as<std::string>();
  o.profile = CommandLine::text(values, "sensor-profile");
  if (!o.profile.empty()) {
    radio_follow::sim::parseSensorProfile(o.profile, "--sensor-profile");  // refused before a run
  }
  o.names = CommandLine::texts(values, "name");
  return o;
}

}  // namespace

int radio_follow::lab::experimentsMain(int argc, char** argv) {
  const ExperimentsOptions o = experimentsCommandLine().parse(argc, argv, readExperimentsOptions);
  const int seeds = o.seeds;
  const std::string& profile = o.profile;
  const std::vector<std::string>& names = o.names;
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
    for (auto experiment : radio_follow::evaluation::loadExperiments(o.file)) {
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
        const auto result = radio_follow::evaluation::runExperiment(experiment, o.config_dir, seed);
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
    std::fprintf(stderr, "lab experiments: %s\n", e.what());
    return 2;
  }
}
