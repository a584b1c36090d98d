// SPDX-License-Identifier: BSD-3-Clause
// Per-call cost of the control core on the robot's CPU: one hybrid homing update, one
// pure-pursuit step on a full path, one safety evaluation with three range sources.
#include <benchmark/benchmark.h>

#include <cmath>

#include "radio_follow/control/homing.hpp"
#include "radio_follow/control/path_follower.hpp"
#include "radio_follow/control/safety_monitor.hpp"

namespace {

using namespace radio_follow::control;

void BM_HybridHomingUpdate(benchmark::State& state) {
  HybridHoming homing{HomingParams()};
  const Eigen::Vector2d target(5.0, 3.0);
  int i = 0;
  for (auto _ : state) {
    const Eigen::Vector2d robot(0.01 * (i % 300), 0.005 * (i % 300));
    const Eigen::Vector2d d = target - robot;
    homing.update(robot, std::atan2(d.y(), d.x()) + 0.01 * std::sin(i),
                  d.norm() + 0.1 * std::cos(i));
    benchmark::DoNotOptimize(homing.goal());
    ++i;
  }
}
BENCHMARK(BM_HybridHomingUpdate);

void BM_PathPruneAndPursuit(benchmark::State& state) {
  PathBuffer path(0.1, static_cast<std::size_t>(state.range(0)));
  for (int i = 0; i < state.range(0); ++i) {
    path.add({0.1 * i, std::sin(0.05 * i)});
  }
  Pose2 robot;
  for (auto _ : state) {
    PathBuffer copy = path;
    copy.prune(robot.position(), 0.3);
    const PursuitTarget t = purePursuit(copy.points(), robot, 0.6);
    benchmark::DoNotOptimize(t);
    benchmark::DoNotOptimize(copy.lengthFrom(robot.position()));
  }
}
BENCHMARK(BM_PathPruneAndPursuit)->Arg(100)->Arg(2000);

void BM_SafetyEvaluate(benchmark::State& state) {
  SafetyMonitor monitor{SafetyParams()};
  monitor.setEnabled(true);
  double t = 0.0;
  for (auto _ : state) {
    t += 0.01;
    monitor.onRange(t, t, "uwb_ranges/a", 3.0);
    monitor.onRange(t, t, "uwb_ranges/b", 3.1);
    monitor.onRange(t, t, "uwb_ranges/c", 2.9);
    monitor.onEstimate(t, t, EstimateQuality::kUsable);
    benchmark::DoNotOptimize(monitor.evaluate(t));
  }
}
BENCHMARK(BM_SafetyEvaluate);

}  // namespace

BENCHMARK_MAIN();
