// SPDX-License-Identifier: BSD-3-Clause
// lab trilateration_compare: the locator's closed-form initial guess against seed 002's
// eqs 2-8 as written, on realistic simulated ranging: error and time per call.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <optional>
#include <string>
#include <vector>

#include "lab_commands.hpp"
#include "radio_follow/common/error_statistics.hpp"
#include "radio_follow/common/param_error.hpp"
#include "radio_follow/config/layout.hpp"
#include "radio_follow/estimation/initializer.hpp"
#include "radio_follow/sim/sensor_profile.hpp"
#include "target_grid.hpp"

namespace rf = radio_follow;
namespace est = radio_follow::estimation;

namespace {

constexpr double kTagHeight = 1.0;  // the tag's plane (2D mode), m
constexpr const char* kLayouts[] = {"spot_twr", "spot", "tracked", "cube"};

using Solver = std::optional<Eigen::Vector3d> (*)(const std::vector<est::RangeObservation>&,
                                                  const est::InitializerConfig&);

/// One epoch's calibrated ranges per trial and target, in time order per target.
struct Epochs {
  std::vector<std::vector<est::RangeObservation>> ranges;
  std::vector<Eigen::Vector3d> truth;
};

Epochs simulate(const rf::Layout& layout, int trials, unsigned long seed) {
  Epochs epochs;
  rf::sim::Rng rng(seed);
  const rf::sim::TwrNoise noise;  // the realistic figures add their own dropouts
  for (const Eigen::Vector3d& target : rf::lab::targetGrid(kTagHeight)) {
    std::vector<rf::sim::TwrHardware> hardware;
    std::vector<rf::sim::TwrNoiseState> state;
    for (const rf::TwrModule& m : layout.twr_modules) {
      hardware.push_back(rf::sim::drawTwrHardware(1, m.id, layout.target_anchor_id));
      state.emplace_back();
    }
    for (int t = 0; t < trials; ++t) {
      std::vector<est::RangeObservation> ranges;
      for (std::size_t i = 0; i < layout.twr_modules.size(); ++i) {
        const rf::TwrModule& m = layout.twr_modules[i];
        // One epoch per second: consecutive trials share part of the slow noise, as a
        // standing person's do.
        if (const auto r = rf::sim::simulateRealisticTwr(m, hardware[i], noise, state[i], target,
                                                         static_cast<double>(t), rng)) {
          est::RangeObservation z;
          z.module = m.position;
          z.range = m.correctRange(*r);
          ranges.push_back(z);
        }
      }
      epochs.ranges.push_back(ranges);
      epochs.truth.push_back(target);
    }
  }
  return epochs;
}

struct Accuracy {
  std::vector<double> errors;
  int failures = 0;
};

Accuracy accuracy(const Epochs& epochs, Solver solve, const est::InitializerConfig& config) {
  Accuracy a;
  for (std::size_t i = 0; i < epochs.ranges.size(); ++i) {
    if (const auto p = solve(epochs.ranges[i], config)) {
      a.errors.push_back((p->head<2>() - epochs.truth[i].head<2>()).norm());
    } else {
      ++a.failures;
    }
  }
  return a;
}

/// Mean time per call, us: the fastest of `repeats` passes over every epoch.
double microsPerCall(const Epochs& epochs, Solver solve, const est::InitializerConfig& config,
                     int repeats) {
  double best = 1e300;
  double sink = 0.0;
  for (int r = 0; r < repeats; ++r) {
    const auto start = std::chrono::steady_clock::now();
    for (const auto& ranges : epochs.ranges) {
      if (const auto p = solve(ranges, config)) {
        sink += p->x();
      }
    }
    const double us =
        std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count();
    best = std::min(best, us / static_cast<double>(epochs.ranges.size()));
  }
  // Keeps the loop from being optimised away.
  if (sink == 42.0) {
    std::fprintf(stderr, " ");
  }
  return best;
}

double rmse(const std::vector<double>& e) {
  double s = 0.0;
  for (double x : e) {
    s += x * x;
  }
  return std::sqrt(s / static_cast<double>(e.size()));
}

rf::cli::CommandLine trilaterationCommandLine() {
  namespace lab = rf::lab;
  rf::cli::CommandLine cli(
      "lab trilateration_compare",
      "usage: lab trilateration_compare [--trials N] [--seed S] [--layouts DIR] [--repeats N]\n",
      "The locator's closed-form initial guess (estimation::trilaterate: differences against\n"
      "the first module, normal equations) against seed 002 eqs 2-8 as written\n"
      "(estimation::trilaterateQr: consecutive differences, QR), on every shipped layout with\n"
      "three or more UWB modules, with the simulator's realistic ranging (hardware seed 1, the\n"
      "robot the shipped layouts' calibrations were fitted on) corrected by each module's\n"
      "calibration as the locator does. Horizontal error of the guess, and the time per call\n"
      "of each, measured in the same run. Deterministic but for the timings. Prints Markdown.\n");
  cli.options()("trials", lab::value("N", "200"), "epochs per target, >= 1")(
      "seed", lab::value("S", "1"), "the ranging noise's seed")(
      "layouts", lab::value("DIR", std::string(RF_CONFIG_DIR) + "/layouts"), "the layouts' folder")(
      "repeats", lab::value("N", "20"), "timing passes over every epoch, >= 1");
  return cli;
}

struct TrilaterationOptions {
  int trials = 200;
  int repeats = 20;
  unsigned long seed = 1;
  std::string layouts;
};

TrilaterationOptions readTrilaterationOptions(const rf::lab::po::variables_map& values) {
  TrilaterationOptions o;
  o.trials = static_cast<int>(rf::lab::count(values, "trials", 1));
  o.repeats = static_cast<int>(rf::lab::count(values, "repeats", 1));
  o.seed = static_cast<unsigned long>(rf::lab::count(values, "seed", 0));
  o.layouts = values["layouts"].as<std::string>();
  return o;
}

}  // namespace

int radio_follow::lab::trilaterationCompareMain(int argc, char** argv) {
  const TrilaterationOptions o =
      trilaterationCommandLine().parse(argc, argv, readTrilaterationOptions);
  const int trials = o.trials;
  const int repeats = o.repeats;
  const unsigned long seed = o.seed;
  try {
    est::InitializerConfig config;
    config.height = kTagHeight;
    std::printf(
        "| layout | modules | epochs | method | failures | error median (m) | p95 (m) | RMSE (m) "
        "| time per call (us) | time / first-difference normal |\n"
        "|---|---|---|---|---|---|---|---|---|---|\n");
    for (const char* name : kLayouts) {
      const rf::Layout layout = rf::loadLayoutFile(o.layouts + "/" + name + ".yaml");
      if (layout.twr_modules.size() < 3) {
        std::printf("| %s | %zu | - | (fewer than 3 modules: no trilateration) | | | | | | |\n",
                    name, layout.twr_modules.size());
        continue;
      }
      const Epochs epochs = simulate(layout, trials, seed);
      // Interleaved, so that a change of the machine's load hits both alike.
      double normal_us = 1e300;
      double qr_us = 1e300;
      for (int round = 0; round < 3; ++round) {
        normal_us = std::min(normal_us, microsPerCall(epochs, est::trilaterate, config, repeats));
        qr_us = std::min(qr_us, microsPerCall(epochs, est::trilaterateQr, config, repeats));
      }
      const struct {
        const char* label;
        Solver solve;
        double us;
      } methods[] = {
          {"first differences, normal equations (`trilaterate`, the locator's)", est::trilaterate,
           normal_us},
          {"consecutive differences, QR (`trilaterateQr`, seed 002)", est::trilaterateQr, qr_us}};
      for (const auto& m : methods) {
        const Accuracy a = accuracy(epochs, m.solve, config);
        std::printf("| %s | %zu | %zu | %s | %d | %.3f | %.3f | %.3f | %.3f | %.2f |\n", name,
                    layout.twr_modules.size(), epochs.ranges.size(), m.label, a.failures,
                    rf::quantile(a.errors, 0.5), rf::quantile(a.errors, 0.95), rmse(a.errors), m.us,
                    m.us / normal_us);
      }
      std::fflush(stdout);
    }
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "lab trilateration_compare: %s\n", e.what());
    return 1;
  }
}
