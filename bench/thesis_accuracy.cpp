// SPDX-License-Identifier: BSD-3-Clause
// Accuracy of the thesis's solve formulation (thesis_solver.hpp) and of the locator's
// PositionSolver on the same noisy measurements, against the Cramer-Rao bound: the grid,
// noise and well-posed test of lab locator_montecarlo (doc/locator_accuracy.md). Both solvers
// start at the true position, the start most favourable to each, so the difference is the
// formulation (weights, squared ranges, azimuth only, loss), not an initial guess.
// Deterministic: same seed, same table. Prints Markdown.
//
//   "$RF_WS"/devel/lib/radio_follow/bench_thesis_accuracy [--trials N] [--seed S]
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

#include "radio_follow/common/angles.hpp"
#include "radio_follow/config/layout.hpp"
#include "radio_follow/estimation/fisher.hpp"
#include "radio_follow/estimation/position_solver.hpp"
#include "radio_follow/estimation/synthetic_observations.hpp"
#include "thesis_solver.hpp"

namespace rf = radio_follow;

namespace {

constexpr double kHeight = 1.0;       // target plane (2D mode), m
constexpr double kRangeSigma = 0.03;  // m
constexpr double kWellPosed = 0.1;    // sqrt(tr CRLB) / distance below this: well posed

struct Case {
  std::string layout;
  double azimuth_deg;  // 0: no bearings
  int max_bearings;
};

/// Sums over the well-posed grid points of one solver.
struct Pool {
  double mse = 0.0;
  double crlb = 0.0;
  int failures = 0;
  std::vector<double> ratios;

  double pooled() const { return std::sqrt(mse / crlb); }
  double median() const {
    std::vector<double> v = ratios;
    std::sort(v.begin(), v.end());
    return v.empty() ? std::nan("") : v[v.size() / 2];
  }
};

void runCase(const Case& c, int trials, unsigned long seed) {
  const rf::Layout layout =
      rf::loadLayoutFile(std::string(RF_CONFIG_DIR) + "/layouts/" + c.layout + ".yaml");
  rf::estimation::SyntheticNoise noise;
  noise.range_sigma = kRangeSigma;
  noise.azimuth_sigma = noise.elevation_sigma = rf::deg2rad(std::max(c.azimuth_deg, 1.0));
  rf::estimation::SolverConfig config;
  config.height = kHeight;
  const rf::estimation::PositionSolver locator(config);
  const thesis_baseline::ThesisSolver thesis(kHeight);
  std::mt19937_64 rng(seed);
  Pool ours;
  Pool theirs;
  int well = 0;
  int points = 0;
  for (int r = 1; r <= 10; ++r) {
    for (int k = 0; k < 12; ++k) {
      ++points;
      const double a = rf::deg2rad(15.0 + 30.0 * k);  // off the boards' seams and axes
      const Eigen::Vector3d truth(r * std::cos(a), r * std::sin(a), kHeight);
      const rf::estimation::ObservationSet ideal =
          rf::estimation::idealObservations(layout, truth, noise, c.max_bearings);
      const auto crlb =
          rf::estimation::positionCrlb(rf::estimation::fisherInformation(ideal, truth), true);
      double se_ours = 0.0;
      double se_theirs = 0.0;
      int n_ours = 0;
      int n_theirs = 0;
      for (int t = 0; t < trials; ++t) {
        rf::estimation::ObservationSet obs = ideal;
        rf::estimation::addGaussianNoise(obs, rng);
        const rf::estimation::SolveResult mine = locator.solveCostOnly(obs, truth);
        const thesis_baseline::ThesisResult base = thesis.solve(obs, truth);
        if (mine.success) {
          se_ours += (mine.position - truth).squaredNorm();
          ++n_ours;
        } else {
          ++ours.failures;
        }
        if (base.success) {
          se_theirs += (base.position - truth).squaredNorm();
          ++n_theirs;
        } else {
          ++theirs.failures;
        }
      }
      if (!crlb || n_ours == 0 || n_theirs == 0 ||
          std::sqrt(crlb->trace()) >= kWellPosed * truth.head<2>().norm()) {
        continue;
      }
      ++well;
      const double bound = crlb->trace();
      for (auto [pool, mse] :
           {std::pair{&ours, se_ours / n_ours}, std::pair{&theirs, se_theirs / n_theirs}}) {
        pool->mse += mse;
        pool->crlb += bound;
        pool->ratios.push_back(std::sqrt(mse / bound));
      }
    }
  }
  std::printf(
      "| %s | %s | %d | %d/%d | %.3f | %.3f | %d | %.3f | %.3f | %d | %.2f |\n", c.layout.c_str(),
      c.azimuth_deg > 0 ? (std::to_string(static_cast<int>(c.azimuth_deg)) + " deg").c_str() : "-",
      c.max_bearings, well, points, ours.pooled(), ours.median(), ours.failures, theirs.pooled(),
      theirs.median(), theirs.failures, theirs.pooled() / ours.pooled());
}

}  // namespace

int main(int argc, char** argv) {
  int trials = 200;
  unsigned long seed = 1;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string key = argv[i];
    if (key == "--trials") {
      trials = std::atoi(argv[i + 1]);
    } else if (key == "--seed") {
      seed = std::strtoul(argv[i + 1], nullptr, 10);
    } else {
      std::fprintf(stderr, "usage: %s [--trials N] [--seed S]\n", argv[0]);
      return 2;
    }
  }
  if (trials < 1 || argc % 2 == 0) {
    std::fprintf(stderr, "usage: %s [--trials N >= 1] [--seed S]\n", argv[0]);
    return 2;
  }
  std::printf(
      "Target on the plane z = %.1f m, range sigma %.2f m, elevation sigma = azimuth sigma, "
      "%d trials per grid point (1-10 m x 12 directions), seed %lu; both solvers start at "
      "the truth. RMSE / sqrt(trace CRLB) over the well-posed points.\n\n"
      "| layout | az sigma | bearings | well-posed | locator pooled | locator median | "
      "locator failures | thesis pooled | thesis median | thesis failures | thesis / locator "
      "|\n|---|---|---|---|---|---|---|---|---|---|---|\n",
      kHeight, kRangeSigma, trials, seed);
  try {
    for (const Case& c : {Case{"tracked", 0, 0}, Case{"spot_twr", 0, 0}, Case{"spot", 2, 1},
                          Case{"spot", 5, 1}, Case{"spot", 5, 2}, Case{"cube", 2, 1}}) {
      runCase(c, trials, seed);
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
  return 0;
}
