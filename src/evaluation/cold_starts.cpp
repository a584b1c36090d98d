// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/evaluation/cold_starts.hpp"

#include <algorithm>
#include <cmath>
#include <random>

#include "radio_follow/common/angles.hpp"
#include "radio_follow/common/error_statistics.hpp"
#include "radio_follow/estimation/mirror_axis.hpp"
#include "radio_follow/evaluation/calibration_run.hpp"
#include "radio_follow/evaluation/standing_robot.hpp"
#include "radio_follow/sim/sensor_profile.hpp"
#include "radio_follow/sim/virtual_sensors.hpp"

namespace radio_follow {
namespace evaluation {
namespace {

/// A mirror image closer than this to the person is no wrong side, m.
constexpr double kMinMirrorSeparation = 1.0;

/// `p` reflected across the main axis of the layout's TWR modules.
Eigen::Vector3d mirrorOf(const Layout& layout, const Eigen::Vector3d& p) {
  std::vector<Eigen::Vector3d> modules;
  for (const auto& m : layout.twr_modules) {
    modules.push_back(m.position);
  }
  const std::optional<estimation::MirrorAxis> axis = estimation::mirrorAxis(modules);
  return axis ? axis->reflect(p) : p;
}

}  // namespace

ColdStartResult runColdStarts(const Layout& layout, sim::WorldConfig world,
                              const estimation::LocatorConfig& locator,
                              const ColdStartParams& params) {
  ColdStartResult result;
  std::vector<Layout> calibrated;
  for (int r = 0; r < params.robots; ++r) {
    world.hardware_seed = static_cast<std::uint64_t>(r + 1);
    calibrated.push_back(locatorLayoutFor(layout, world));
  }
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<double> times_to_usable;
  std::vector<double> errors;
  std::vector<double> nees;
  for (std::size_t trial = params.first_trial; trial < params.first_trial + params.trials;
       ++trial) {
    std::seed_seq seeds{static_cast<std::uint32_t>(params.seed),
                        static_cast<std::uint32_t>(params.seed >> 32),
                        static_cast<std::uint32_t>(trial),
                        static_cast<std::uint32_t>(static_cast<std::uint64_t>(trial) >> 32)};
    sim::Rng rng(seeds);
    const auto robot = static_cast<std::uint64_t>(trial % static_cast<std::size_t>(params.robots));
    const double r = params.min_distance + (params.max_distance - params.min_distance) * unit(rng);
    const double a = (2.0 * unit(rng) - 1.0) * kPi;
    const Eigen::Vector3d target(r * std::cos(a), r * std::sin(a), locator.height);
    const Eigen::Vector3d mirror = mirrorOf(layout, target);
    const bool has_mirror = (mirror - target).head<2>().norm() > kMinMirrorSeparation;

    estimation::Locator estimator(calibrated[robot], locator);
    StandingRobotSensors sensors(layout, world, robot + 1, rng);
    if (params.reading_observer) {
      sensors.observeReadings([&params, trial, &target](const SensorReading& r) {
        params.reading_observer(trial, r, target);
      });
    }
    const auto at_target = [&target](double) { return target; };
    double mirror_run = 0.0;
    double longest = 0.0;
    double longest_start = 0.0;
    bool usable_seen = false;
    for (double now = kLocatorUpdatePeriod; now <= params.duration + 1e-9; now += kLocatorUpdatePeriod) {
      sensors.feed(estimator, now, at_target, rng);
      const estimation::LocatorEstimate e = estimator.update(now);
      if (params.observer) {
        params.observer(trial, now, e, target);
      }
      ++result.updates;
      result.ambiguous_updates += e.status == TargetStatus::kAmbiguous;
      if (!hasPosition(e.status)) {
        mirror_run = 0.0;
        continue;
      }
      if (!usable_seen) {
        usable_seen = true;
        times_to_usable.push_back(now);
      }
      const double to_target = (e.position - target).head<2>().norm();
      const bool on_mirror = has_mirror && (e.position - mirror).head<2>().norm() < to_target;
      mirror_run = on_mirror ? mirror_run + kLocatorUpdatePeriod : 0.0;
      if (mirror_run > longest) {
        longest = mirror_run;
        longest_start = now - mirror_run + kLocatorUpdatePeriod;
      }
      if (now >= 1.0) {
        errors.push_back(to_target);
        if (const auto v =
                nees2d((e.position - target).head<2>(), e.covariance.topLeftCorner<2, 2>())) {
          nees.push_back(*v);
        }
      }
    }
    ++result.trials;
    result.mirror_any += longest > 0.0;
    if (longest > 1.0) {
      result.locks.push_back(MirrorLock{trial, robot, target, longest_start, longest});
    }
    result.longest_mirror_s = std::max(result.longest_mirror_s, longest);
  }
  result.usable = times_to_usable.size();
  result.median_time_to_usable = quantile(times_to_usable, 0.5);
  result.error_median = quantile(errors, 0.5);
  result.error_p95 = quantile(errors, 0.95);
  result.nees_samples = nees.size();
  result.nees_mean = mean(nees);
  result.nees_median = quantile(nees, 0.5);
  result.nees_p99 = quantile(nees, 0.99);
  result.nees_max = nees.empty() ? 0.0 : *std::max_element(nees.begin(), nees.end());
  result.within_95 = shareInside95(nees);
  return result;
}

}  // namespace evaluation
}  // namespace radio_follow
