// SPDX-License-Identifier: BSD-3-Clause
// Latency of one fused locator solve per sensor layout (warm start, as in steady tracking)
// and of a whole Locator::update (buffer, board selection, solve, filter). Baseline in the
// same run: the thesis's solve formulation (thesis_solver.hpp) on the same epochs from the
// same starts (thesisSolve/<case>).
// Each benchmark also times every solve and reports its median and 99th percentile
// (counters p50_us, p99_us): the mean alone hides the tail.
//
//   "$RF_WS"/devel/lib/radio_follow/bench_locator_solve
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <random>
#include <string>
#include <vector>

#include "radio_follow/common/angles.hpp"
#include "radio_follow/estimation/locator.hpp"
#include "radio_follow/estimation/position_solver.hpp"
#include "radio_follow/estimation/synthetic_observations.hpp"
#include "thesis_solver.hpp"

namespace rf = radio_follow;

namespace {

struct Epoch {
  rf::estimation::ObservationSet obs;
  Eigen::Vector3d truth;
  Eigen::Vector3d warm;
};

std::vector<Epoch> epochs(const std::string& layout_name, int max_bearings) {
  const rf::Layout layout =
      rf::loadLayoutFile(std::string(RF_CONFIG_DIR) + "/layouts/" + layout_name + ".yaml");
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> dist(1.0, 10.0);
  std::uniform_real_distribution<double> angle(-rf::kPi, rf::kPi);
  std::normal_distribution<double> step(0.0, 0.05);  // target motion between epochs
  rf::estimation::SyntheticNoise noise;
  noise.azimuth_sigma = noise.elevation_sigma = rf::deg2rad(5.0);
  std::vector<Epoch> out;
  for (int i = 0; i < 256; ++i) {
    const double r = dist(rng);
    const double a = angle(rng);
    Epoch e;
    e.truth = Eigen::Vector3d(r * std::cos(a), r * std::sin(a), 1.0);
    e.obs = rf::estimation::idealObservations(layout, e.truth, noise, max_bearings);
    rf::estimation::addGaussianNoise(e.obs, rng);
    e.warm = e.truth + Eigen::Vector3d(step(rng), step(rng), 0.0);
    out.push_back(e);
  }
  return out;
}

void reportPercentiles(benchmark::State& state, std::vector<double>& micros) {
  std::sort(micros.begin(), micros.end());
  state.counters["p50_us"] = micros[micros.size() / 2];
  state.counters["p99_us"] = micros[static_cast<std::size_t>(0.99 * (micros.size() - 1))];
}

void solve(benchmark::State& state, const std::string& layout, int max_bearings) {
  const std::vector<Epoch> data = epochs(layout, max_bearings);
  const rf::estimation::PositionSolver solver{rf::estimation::SolverConfig{}};
  std::vector<double> micros;
  std::size_t i = 0;
  for (auto _ : state) {
    const Epoch& e = data[i++ % data.size()];
    const auto start = std::chrono::steady_clock::now();
    rf::estimation::SolveResult r = solver.solve(e.obs, e.warm);
    micros.push_back(
        std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start)
            .count());
    benchmark::DoNotOptimize(r);
  }
  reportPercentiles(state, micros);
}

void thesisSolve(benchmark::State& state, const std::string& layout, int max_bearings) {
  const std::vector<Epoch> data = epochs(layout, max_bearings);
  const thesis_baseline::ThesisSolver solver(1.0);
  std::vector<double> micros;
  std::size_t i = 0;
  for (auto _ : state) {
    const Epoch& e = data[i++ % data.size()];
    const auto start = std::chrono::steady_clock::now();
    thesis_baseline::ThesisResult r = solver.solve(e.obs, e.warm);
    micros.push_back(
        std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start)
            .count());
    benchmark::DoNotOptimize(r);
  }
  reportPercentiles(state, micros);
}

// The node's whole per-epoch work for the Spot layout: fresh ranges and bearings from all
// four boards (the one behind the robot included), selection, warm solve, filter, and the
// mirror test with ambiguity_margin = the argument (0: off, the baseline; 2: the default:
// one more warm solve per range-only epoch, and per epoch until the track is confirmed).
// spot_twr: the same walk with ranges only (no boards in that layout).
// locatorUpdate/<layout>_particle: the same inputs through the particle estimator (the
// default; argument: particles of the main hypothesis), every measurement applied at its
// stamp: 7 per update here, more than the 3-4 of a Spot at its sensors' 10 Hz.
void locatorUpdate(benchmark::State& state, const std::string& name,
                   rf::estimation::Estimator estimator) {
  const rf::Layout layout =
      rf::loadLayoutFile(std::string(RF_CONFIG_DIR) + "/layouts/" + name + ".yaml");
  rf::estimation::LocatorConfig config;
  config.estimator = estimator;
  if (estimator == rf::estimation::Estimator::kSolver) {
    config.ambiguity_margin = static_cast<double>(state.range(0));
  } else {
    config.particles = static_cast<int>(state.range(0));
  }
  rf::estimation::Locator locator(layout, config);
  std::mt19937_64 rng(3);
  std::normal_distribution<double> noise(0.0, 1.0);
  double t = 0.0;
  std::vector<double> micros;
  for (auto _ : state) {
    t += 0.05;
    const Eigen::Vector3d truth(4.0 * std::cos(0.1 * t), 4.0 * std::sin(0.1 * t), 1.0);
    for (std::size_t i = 0; i < layout.twr_modules.size(); ++i) {
      const auto& m = layout.twr_modules[i];
      locator.addRange(i, (truth - m.position).norm() + 0.03 * noise(rng), t);
      t += 0.002;  // each sensor at its own stamp
    }
    for (std::size_t i = 0; i < layout.aoa_boards.size(); ++i) {
      const auto& b = layout.aoa_boards[i];
      const Eigen::Vector2d ae =
          rf::estimation::predictBearing(truth, b.position, b.orientation.toRotationMatrix());
      locator.addBearing(i, ae(0) + 0.08 * noise(rng), ae(1) + 0.08 * noise(rng), -60.0, t);
      t += 0.002;
    }
    const auto start = std::chrono::steady_clock::now();
    rf::estimation::LocatorEstimate e = locator.update(t);
    micros.push_back(
        std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start)
            .count());
    benchmark::DoNotOptimize(e);
  }
  reportPercentiles(state, micros);
}

}  // namespace

BENCHMARK_CAPTURE(solve, spot_twr, std::string("spot_twr"), 0)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(solve, tracked, std::string("tracked"), 0)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(solve, cube_1_bearing, std::string("cube"), 1)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(solve, spot_1_bearing, std::string("spot"), 1)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(solve, spot_all_in_fov, std::string("spot"), 4)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(thesisSolve, spot_twr, std::string("spot_twr"), 0)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(thesisSolve, tracked, std::string("tracked"), 0)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(thesisSolve, cube_1_bearing, std::string("cube"), 1)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(thesisSolve, spot_1_bearing, std::string("spot"), 1)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(thesisSolve, spot_all_in_fov, std::string("spot"), 4)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(locatorUpdate, spot, std::string("spot"), rf::estimation::Estimator::kSolver)
    ->Arg(0)
    ->Arg(2)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(locatorUpdate, spot_twr, std::string("spot_twr"),
                  rf::estimation::Estimator::kSolver)
    ->Arg(0)
    ->Arg(2)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(locatorUpdate, spot_particle, std::string("spot"),
                  rf::estimation::Estimator::kParticle)
    ->Arg(250)
    ->Arg(500)
    ->Arg(1000)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(locatorUpdate, spot_twr_particle, std::string("spot_twr"),
                  rf::estimation::Estimator::kParticle)
    ->Arg(500)
    ->Unit(benchmark::kMicrosecond);

BENCHMARK_MAIN();
