// SPDX-License-Identifier: BSD-3-Clause
// Issue 14's Gaussian tracking benchmark (evaluation/walking_pcrb.hpp): a person walks past
// a standing robot (a straight line and an arc, 1-1.4 m/s; and a walk drawn from the
// locator's own motion model), every sensor reports at its
// rate (config/simulator.yaml) with the ideal profile's white Gaussian noise, and the
// shipped locator (config/locator.yaml: the particle estimator; second row: `estimator:
// solver`) is compared with the posterior Cramer-Rao bound of the same measurements, over
// many Monte Carlo runs. Deterministic: same seed, same table. Prints Markdown.
// A --layouts item ending in .yaml is a layout file (e.g. placement_advisor --optimise's
// output), run with the shipped simulator and locator files, named by its file's stem.
//   locator_pcrb [--layouts spot,cube,tracked,FILE.yaml] [--paths straight,arc,model] [--runs 100]
//   [--seed 1]
//                [--locator-overrides FILE] [--config-dir DIR]
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "radio_follow/common/param_error.hpp"
#include "radio_follow/common/tool_options.hpp"
#include "radio_follow/config/layout.hpp"
#include "radio_follow/evaluation/closed_loop.hpp"
#include "radio_follow/evaluation/walking_pcrb.hpp"

namespace {

namespace fs = std::filesystem;

int usage(const std::string& problem) {
  std::fprintf(
      stderr,
      "locator_pcrb: %s\nusage: locator_pcrb [--layouts L1,FILE.yaml] [--paths P1,P2] [--runs N] "
      "[--seed S] "
      "[--locator-overrides FILE] [--config-dir DIR]\n",
      problem.c_str());
  return 2;
}

std::vector<std::string> split(const std::string& text) {
  std::vector<std::string> out;
  std::stringstream in(text);
  for (std::string item; std::getline(in, item, ',');) {
    if (!item.empty()) {
      out.push_back(item);
    }
  }
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  namespace rf = radio_follow;
  namespace ev = radio_follow::evaluation;
  std::map<std::string, std::string> options{{"--layouts", "spot,cube,tracked"},
                                             {"--paths", "straight,arc,model"},
                                             {"--runs", "100"},
                                             {"--seed", "1"},
                                             {"--locator-overrides", ""},
                                             {"--config-dir", RF_CONFIG_DIR}};
  if (const auto problem = rf::readToolOptions(argc, argv, options)) {
    return usage(*problem);
  }
  try {
    const auto runs = static_cast<int>(rf::toolCount("--runs", options["--runs"], 1));
    const auto seed = static_cast<int>(rf::toolCount("--seed", options["--seed"], 1));
    std::printf(
        "| layout | path | estimator | runs | samples (no position) | RMSE (m) | sqrt tr PCRB (m) "
        "| RMSE / PCRB | PCRB, FOV bearings only (m) | RMSE / that | along-track mean (m) | "
        "across mean (m) | median error (m) | runs > 1 m |\n");
    std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
    for (const std::string& item : split(options["--layouts"])) {
      // A shipped layout's name, or a layout file (e.g. placement_advisor --optimise's).
      const bool file = fs::path(item).extension() == ".yaml";
      const std::string layout = file ? fs::path(item).stem().string() : item;
      // The lockstep loop's loader: the shipped simulator and locator files; a layout file
      // replaces the layout they are loaded with (only the layout enters the benchmark).
      ev::ClosedLoopConfig c =
          ev::loadClosedLoopConfig(options["--config-dir"], file ? "spot" : item, "outdoor_loop",
                                   ev::FollowController::kVelocity, 1, "",
                                   options["--locator-overrides"], rf::sim::SensorProfile::kIdeal);
      if (file) {
        c.layout = rf::loadLayoutFile(item);
      }
      for (const std::string& path : split(options["--paths"])) {
        const ev::WalkShape shape = ev::parseWalkShape(path, "--paths");
        for (const auto estimator :
             {rf::estimation::Estimator::kParticle, rf::estimation::Estimator::kSolver}) {
          rf::estimation::LocatorConfig locator = c.locator;
          locator.estimator = estimator;
          ev::WalkingPcrbParams params;
          params.runs = static_cast<std::size_t>(runs);
          params.shape = shape;
          params.seed = static_cast<std::uint64_t>(seed);
          const ev::WalkingPcrbResult r =
              ev::runWalkingPcrb(c.layout, c.world, locator, c.locator_rate, params);
          std::printf(
              "| %s | %s | %s | %zu | %zu (%zu) | %.4f | %.4f | %.2f | %.4f | %.2f | %+.4f | "
              "%+.4f | %.4f | %zu |\n",
              layout.c_str(), ev::toString(shape).c_str(),
              estimator == rf::estimation::Estimator::kParticle ? "particle" : "solver", r.runs,
              r.samples, r.without_position, r.rmse, r.pcrb, r.rmse / r.pcrb, r.pcrb_in_fov,
              r.rmse / r.pcrb_in_fov, r.along_mean, r.across_mean, r.median_error, r.runs_over_1m);
          std::fflush(stdout);
        }
      }
    }
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "locator_pcrb: %s\n", e.what());
    return 1;
  }
}
