// SPDX-License-Identifier: BSD-3-Clause
// lab locator_montecarlo: the locator's solver against the Cramer-Rao lower bound, per
// sensor layout and noise level, plus the NLOS outlier test and per-solve latency.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "lab_commands.hpp"
#include "radio_follow/common/angles.hpp"
#include "radio_follow/config/layout.hpp"
#include "radio_follow/estimation/fisher.hpp"
#include "radio_follow/estimation/initializer.hpp"
#include "radio_follow/estimation/position_solver.hpp"
#include "radio_follow/estimation/synthetic_observations.hpp"
#include "target_grid.hpp"

namespace rf = radio_follow;

namespace {

struct Case {
  std::string layout;
  double azimuth_deg;  // 0: layout without bearings
  int max_bearings;
};

struct MontecarloOptions {
  int trials = 0;
  unsigned long seed = 0;
  std::string layouts;
  rf::estimation::LossConfig range_loss = rf::estimation::RangeObservation::kDefaultLoss;
  bool outliers = false;
};

constexpr double kTargetHeight = 1.0;  // target plane (2D mode), m
constexpr double kRangeSigma = 0.03;   // m
constexpr double kWellPosed = 0.1;     // sqrt(tr CRLB) / distance below this: well posed

double percentile(std::vector<double> v, double q) {
  if (v.empty())
    return std::nan("");
  std::sort(v.begin(), v.end());
  const std::size_t i = std::min(v.size() - 1, static_cast<std::size_t>(q * (v.size() - 1) + 0.5));
  return v[i];
}

rf::estimation::SolveResult coldSolve(const rf::estimation::PositionSolver& solver,
                                      const rf::estimation::ObservationSet& obs,
                                      const rf::estimation::InitializerConfig& init) {
  if (const auto guess = rf::estimation::trilaterate(obs.ranges, init)) {
    return solver.solveCold(obs, *guess);
  }
  return solver.solveMultiStart(obs, rf::estimation::multiStartCandidates(obs, init));
}

rf::estimation::SyntheticNoise noiseFor(const Case& c) {
  rf::estimation::SyntheticNoise noise;
  noise.range_sigma = kRangeSigma;
  noise.azimuth_sigma = rf::deg2rad(std::max(c.azimuth_deg, 1.0));
  noise.elevation_sigma = noise.azimuth_sigma;
  return noise;
}

void accuracyTable(const MontecarloOptions& opt, const std::vector<Case>& cases) {
  std::printf(
      "| layout | az sigma | bearings | well-posed | RMSE/CRLB median | p90 | max | "
      "RMSE, CRLB (m, pooled) | ill-posed RMSE/CRLB median | failures | cold solve median / p99 "
      "(us) |\n|---|---|---|---|---|---|---|---|---|---|---|\n");
  rf::estimation::SolverConfig config;
  config.height = kTargetHeight;
  config.loss<rf::estimation::RangeObservation>() = opt.range_loss;
  const rf::estimation::PositionSolver solver(config);
  rf::estimation::InitializerConfig init;
  init.height = kTargetHeight;
  std::vector<std::vector<double>> by_radius(cases.size());
  for (std::size_t ci = 0; ci < cases.size(); ++ci) {
    const Case& c = cases[ci];
    const rf::Layout layout = rf::loadLayoutFile(opt.layouts + "/" + c.layout + ".yaml");
    std::mt19937_64 rng(opt.seed);
    std::vector<double> ratios;
    std::vector<double> ill;
    std::vector<double> micros;
    double mse_pool = 0.0;
    double crlb_pool = 0.0;
    int failures = 0;
    int well = 0;
    std::vector<double> radius_mse(11, 0.0);
    std::vector<double> radius_crlb(11, 0.0);
    const auto points = rf::lab::targetGrid(kTargetHeight);
    for (const auto& truth : points) {
      const rf::estimation::ObservationSet ideal =
          rf::estimation::idealObservations(layout, truth, noiseFor(c), c.max_bearings);
      const auto crlb =
          rf::estimation::positionCrlb(rf::estimation::fisherInformation(ideal, truth), true);
      double se = 0.0;
      int n = 0;
      for (int t = 0; t < opt.trials; ++t) {
        rf::estimation::ObservationSet obs = ideal;
        rf::estimation::addGaussianNoise(obs, rng);
        const auto start = std::chrono::steady_clock::now();
        const rf::estimation::SolveResult r = coldSolve(solver, obs, init);
        micros.push_back(
            std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start)
                .count());
        if (!r.success) {
          ++failures;
          continue;
        }
        se += (r.position - truth).squaredNorm();
        ++n;
      }
      if (!crlb || n == 0)
        continue;
      const double mse = se / n;
      const double bound = crlb->trace();
      const double ratio = std::sqrt(mse / bound);
      const int radius = static_cast<int>(std::lround(truth.head<2>().norm()));
      radius_mse[radius] += mse;
      radius_crlb[radius] += bound;
      if (std::sqrt(bound) < kWellPosed * truth.head<2>().norm()) {
        ++well;
        ratios.push_back(ratio);
        mse_pool += mse;
        crlb_pool += bound;
      } else {
        ill.push_back(ratio);
      }
    }
    for (int r = 1; r <= 10; ++r) {
      by_radius[ci].push_back(std::sqrt(radius_mse[r] / radius_crlb[r]));
    }
    std::printf(
        "| %s | %s | %d | %d/%zu | %.3f | %.3f | %.3f | %.4f, %.4f | %s | %d | %.1f / %.1f |\n",
        c.layout.c_str(),
        c.azimuth_deg > 0 ? (std::to_string(static_cast<int>(c.azimuth_deg)) + " deg").c_str()
                          : "-",
        c.max_bearings, well, points.size(), percentile(ratios, 0.5), percentile(ratios, 0.9),
        percentile(ratios, 1.0), std::sqrt(mse_pool / std::max(1, well)),
        std::sqrt(crlb_pool / std::max(1, well)),
        ill.empty() ? "-" : std::to_string(percentile(ill, 0.5)).substr(0, 5).c_str(), failures,
        percentile(micros, 0.5), percentile(micros, 0.99));
  }
  std::printf(
      "\nRMSE / sqrt(trace CRLB) by distance (pooled over the 12 directions):\n\n"
      "| layout | az sigma | bearings |");
  for (int r = 1; r <= 10; ++r)
    std::printf(" %d m |", r);
  std::printf("\n|---|---|---|");
  for (int r = 1; r <= 10; ++r)
    std::printf("---|");
  std::printf("\n");
  for (std::size_t ci = 0; ci < cases.size(); ++ci) {
    std::printf("| %s | %.0f | %d |", cases[ci].layout.c_str(), cases[ci].azimuth_deg,
                cases[ci].max_bearings);
    for (double v : by_radius[ci])
      std::printf(" %.2f |", v);
    std::printf("\n");
  }
}

// One range reads +2 m (blocked direct path) in 10 % of epochs.
void outlierTable(const MontecarloOptions& opt, const std::vector<Case>& cases) {
  std::printf(
      "\nNLOS outlier test: one range +2 m in 10 %% of epochs; RMSE (m) over the grid, "
      "tracking (warm start from the last epoch), bearing loss = range loss:\n\n| layout | az "
      "sigma | bearings | loss | clean | with "
      "outliers | ratio |\n|---|---|---|---|---|---|---|\n");
  const std::vector<rf::estimation::LossConfig> losses{{rf::estimation::LossType::kNone, 1.0},
                                                       {rf::estimation::LossType::kHuber, 2.0},
                                                       {rf::estimation::LossType::kSoftL1, 1.0},
                                                       {rf::estimation::LossType::kCauchy, 1.0},
                                                       {rf::estimation::LossType::kCauchy, 2.0}};
  for (const Case& c : cases) {
    const rf::Layout layout = rf::loadLayoutFile(opt.layouts + "/" + c.layout + ".yaml");
    for (const auto& loss : losses) {
      rf::estimation::SolverConfig config;
      config.height = kTargetHeight;
      config.loss<rf::estimation::RangeObservation>() =
          config.loss<rf::estimation::BearingObservation>() = loss;
      const rf::estimation::PositionSolver solver(config);
      double se[2] = {0.0, 0.0};
      int n[2] = {0, 0};
      for (int pass = 0; pass < 2; ++pass) {
        std::mt19937_64 rng(opt.seed);
        std::uniform_real_distribution<double> unit(0.0, 1.0);
        for (const auto& truth : rf::lab::targetGrid(kTargetHeight)) {
          const rf::estimation::ObservationSet ideal =
              rf::estimation::idealObservations(layout, truth, noiseFor(c), c.max_bearings);
          // Tracking: the first epoch starts cold (and clean), the others from the last
          // estimate, as in the node.
          std::optional<Eigen::Vector3d> warm;
          for (int t = 0; t < opt.trials; ++t) {
            rf::estimation::ObservationSet obs = ideal;
            rf::estimation::addGaussianNoise(obs, rng);
            const double u = unit(rng);
            const auto which = static_cast<std::size_t>(unit(rng) * obs.ranges.size());
            if (pass == 1 && u < 0.1 && warm)
              obs.ranges[which].range += 2.0;
            rf::estimation::InitializerConfig init;
            init.height = kTargetHeight;
            const rf::estimation::SolveResult r =
                warm ? solver.solve(obs, *warm) : coldSolve(solver, obs, init);
            if (r.success) {
              warm = r.position;
              se[pass] += (r.position - truth).squaredNorm();
              ++n[pass];
            }
          }
        }
      }
      const double clean = std::sqrt(se[0] / n[0]);
      const double dirty = std::sqrt(se[1] / n[1]);
      std::printf("| %s | %.0f | %d | %s %.0f | %.3f | %.3f | %.2f |\n", c.layout.c_str(),
                  c.azimuth_deg, c.max_bearings, rf::estimation::toString(loss.type).c_str(),
                  loss.scale, clean, dirty, dirty / clean);
    }
  }
}

radio_follow::cli::CommandLine montecarloCommandLine() {
  namespace lab = radio_follow::lab;
  radio_follow::cli::CommandLine cli(
      "lab locator_montecarlo",
      "usage: lab locator_montecarlo [--trials N] [--seed S] [--layouts DIR]\n"
      "         [--range-loss none|huber|soft_l1|cauchy] [--range-loss-scale S] "
      "[--outliers 0|1]\n",
      "Monte Carlo accuracy of the locator's solver against the Cramer-Rao lower bound, per\n"
      "sensor layout and noise level, plus the NLOS outlier test and per-solve latency.\n"
      "ROS-free; prints Markdown tables (doc/locator_accuracy.md holds a run and the command).\n");
  cli.options()("trials", lab::value("N", "200"), "trials per grid point, >= 1")(
      "seed", lab::value("S", "1"), "the noise seed")(
      "layouts", lab::value("DIR", "config/layouts"), "the layouts' folder")(
      "range-loss", lab::value("TYPE"),
      "the solver's range loss: none, huber, soft_l1 or cauchy; default: the solver's")(
      "range-loss-scale", lab::value("S"), "its scale, > 0; default: the solver's")(
      "outliers", lab::value("0|1", "1"), "1: also the NLOS outlier test");
  return cli;
}

MontecarloOptions readMontecarloOptions(const radio_follow::lab::po::variables_map& values) {
  namespace lab = radio_follow::lab;
  MontecarloOptions opt;
  opt.trials = static_cast<int>(lab::count(values, "trials", 1));
  opt.seed = static_cast<unsigned long>(lab::count(values, "seed", 0));
  opt.layouts = values["layouts"].as<std::string>();
  if (values.count("range-loss")) {
    opt.range_loss.type =
        rf::estimation::parseLossType(values["range-loss"].as<std::string>(), "--range-loss");
  }
  if (values.count("range-loss-scale")) {
    opt.range_loss.scale =
        lab::number(values, "range-loss-scale", "a scale > 0", [](double v) { return v > 0.0; });
  }
  opt.outliers =
      rf::cli::choice("--outliers", values["outliers"].as<std::string>(), {"0", "1"}) == "1";
  return opt;
}

}  // namespace

int radio_follow::lab::locatorMontecarloMain(int argc, char** argv) {
  const MontecarloOptions opt = montecarloCommandLine().parse(argc, argv, readMontecarloOptions);
  try {
    std::printf(
        "Target on the plane z = %.1f m (2D mode), range sigma %.2f m, elevation sigma = "
        "azimuth sigma, %d trials per grid point (1-10 m x 12 directions), range "
        "loss %s %.1f, bearing loss huber 2, cold start (trilateration or multi-start).\n\n",
        kTargetHeight, kRangeSigma, opt.trials,
        rf::estimation::toString(opt.range_loss.type).c_str(), opt.range_loss.scale);
    accuracyTable(opt, {{"spot_twr", 0, 0},
                        {"tracked", 0, 0},
                        {"cube", 2, 1},
                        {"cube", 5, 1},
                        {"cube", 2, 2},
                        {"spot", 2, 1},
                        {"spot", 5, 1},
                        {"spot", 5, 2}});
    if (opt.outliers)
      outlierTable(opt, {{"tracked", 0, 0}, {"spot", 2, 1}, {"spot_twr", 0, 0}});
  } catch (const std::exception& e) {
    std::fprintf(stderr, "lab locator_montecarlo: %s\n", e.what());
    return 1;
  }
  return 0;
}
