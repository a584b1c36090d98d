// SPDX-License-Identifier: BSD-3-Clause
// lab locator_pcrb: issue 14's Gaussian tracking benchmark (evaluation/walking_pcrb.hpp),
// the shipped locator against the posterior Cramer-Rao bound of a walking person.
#include <cstdio>
#include <exception>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "lab_commands.hpp"
#include "radio_follow/common/param_error.hpp"
#include "radio_follow/config/layout.hpp"
#include "radio_follow/evaluation/closed_loop.hpp"
#include "radio_follow/evaluation/walking_pcrb.hpp"

namespace {

namespace fs = std::filesystem;

std::vector<std::string> splitList(const std::string& text) {
  std::vector<std::string> out;
  std::stringstream in(text);
  for (std::string item; std::getline(in, item, ',');) {
    if (!item.empty()) {
      out.push_back(item);
    }
  }
  return out;
}

radio_follow::cli::CommandLine pcrbCommandLine() {
  namespace lab = radio_follow::lab;
  radio_follow::cli::CommandLine cli(
      "lab locator_pcrb",
      "usage: lab locator_pcrb [--layouts L1,FILE.yaml] [--paths P1,P2] [--runs N] [--seed S]\n"
      "         [--locator-overrides FILE] [--config-dir DIR]\n",
      "Issue 14's Gaussian tracking benchmark (evaluation/walking_pcrb.hpp): a person walks past\n"
      "a standing robot (a straight line and an arc, 1-1.4 m/s; and a walk drawn from the\n"
      "locator's own motion model), every sensor reports at its rate (config/simulator.yaml)\n"
      "with the ideal profile's white Gaussian noise, and the shipped locator (the particle\n"
      "estimator; second row: `estimator: solver`) is compared with the posterior Cramer-Rao\n"
      "bound of the same measurements, over many Monte Carlo runs. Deterministic: same seed,\n"
      "same table. Prints Markdown.\n");
  cli.options()("layouts", lab::value("LIST", "spot,cube,tracked"),
                "shipped layouts' names or layout files (an item ending in .yaml, e.g. "
                "placement_advisor --optimise's output, named by its file's stem), "
                "comma-separated")("paths", lab::value("LIST", "straight,arc,model"),
                                   "walks: straight, arc, model; comma-separated")(
      "runs", lab::value("N", "100"), "Monte Carlo runs per row, >= 1")(
      "seed", lab::value("S", "1"), "the seed, >= 1")("locator-overrides", lab::value("FILE"),
                                                      "YAML over config/locator.yaml")(
      "config-dir", lab::value("DIR", RF_CONFIG_DIR), "the shipped configuration's folder");
  return cli;
}

struct PcrbOptions {
  std::vector<std::string> layouts;
  std::vector<radio_follow::evaluation::WalkShape> shapes;
  int runs = 100;
  int seed = 1;
  std::string locator_overrides;
  std::string config_dir;
};

PcrbOptions readPcrbOptions(const radio_follow::lab::po::variables_map& values) {
  namespace lab = radio_follow::lab;
  PcrbOptions o;
  o.layouts = splitList(values["layouts"].as<std::string>());
  for (const std::string& path : splitList(values["paths"].as<std::string>())) {
    o.shapes.push_back(radio_follow::evaluation::parseWalkShape(path, "--paths"));
  }
  o.runs = static_cast<int>(lab::count(values, "runs", 1));
  o.seed = static_cast<int>(lab::count(values, "seed", 1));
  o.locator_overrides = radio_follow::cli::CommandLine::text(values, "locator-overrides");
  o.config_dir = values["config-dir"].as<std::string>();
  return o;
}

}  // namespace

int radio_follow::lab::locatorPcrbMain(int argc, char** argv) {
  namespace rf = radio_follow;
  namespace ev = radio_follow::evaluation;
  const PcrbOptions o = pcrbCommandLine().parse(argc, argv, readPcrbOptions);
  try {
    std::printf(
        "| layout | path | estimator | runs | samples (no position) | RMSE (m) | sqrt tr PCRB (m) "
        "| RMSE / PCRB | PCRB, FOV bearings only (m) | RMSE / that | along-track mean (m) | "
        "across mean (m) | median error (m) | runs > 1 m |\n");
    std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
    for (const std::string& item : o.layouts) {
      // A shipped layout's name, or a layout file (e.g. placement_advisor --optimise's).
      const bool file = fs::path(item).extension() == ".yaml";
      const std::string layout = file ? fs::path(item).stem().string() : item;
      // The lockstep loop's loader: the shipped simulator and locator files; a layout file
      // replaces the layout they are loaded with (only the layout enters the benchmark).
      ev::ClosedLoopConfig c = ev::loadClosedLoopConfig(
          o.config_dir, file ? "spot" : item, "outdoor_loop", ev::FollowController::kVelocity, 1,
          "", o.locator_overrides, rf::sim::SensorProfile::kIdeal);
      if (file) {
        c.layout = rf::loadLayoutFile(item);
      }
      for (const ev::WalkShape shape : o.shapes) {
        for (const auto estimator :
             {rf::estimation::Estimator::kParticle, rf::estimation::Estimator::kSolver}) {
          rf::estimation::LocatorConfig locator = c.locator;
          locator.estimator = estimator;
          ev::WalkingPcrbParams params;
          params.runs = static_cast<std::size_t>(o.runs);
          params.shape = shape;
          params.seed = static_cast<std::uint64_t>(o.seed);
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
    std::fprintf(stderr, "lab locator_pcrb: %s\n", e.what());
    return 1;
  }
}
