// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/evaluation/standing_robot.hpp"

#include <random>

#include "radio_follow/evaluation/simulated_tdoa.hpp"

namespace radio_follow {
namespace evaluation {

StandingRobotSensors::StandingRobotSensors(const Layout& layout, const sim::WorldConfig& world,
                                           std::uint64_t hardware_seed, sim::Rng& rng)
    : layout_(layout),
      world_(world),
      realistic_(world.profile == sim::SensorProfile::kRealistic) {
  for (const auto& m : layout.twr_modules) {
    hardware_.push_back(
        sim::drawTwrHardware(hardware_seed, m.id, layout.target_anchor_id, world.figures));
    states_.emplace_back(world.figures);
  }
  for (const auto& b : layout.aoa_boards) {
    aoa_.emplace_back(b, hardware_seed, world.figures);
  }
  const bool tdoa = layout.tdoa_anchors.size() >= 2;
  if (tdoa && realistic_) {
    tdoa_.emplace(layout.tdoa_anchors, hardware_seed, world.figures);
  }
  // Free-running sensors: each its own phase.
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  next_.resize(layout.twr_modules.size() + layout.aoa_boards.size() +
               (tdoa ? 1 + layout.twr_modules.size() : 0));
  for (double& t : next_) {
    t = kPeriod * unit(rng);
  }
}

void StandingRobotSensors::feed(estimation::Locator& locator, double now,
                                const std::function<Eigen::Vector3d(double)>& target,
                                sim::Rng& rng) {
  const std::size_t modules = layout_.twr_modules.size();
  for (std::size_t s = 0; s < next_.size(); ++s) {
    while (next_[s] <= now) {
      const double t = next_[s];
      next_[s] += kPeriod;
      const Eigen::Vector3d at = target(t);
      if (s < modules) {
        const TwrModule& m = layout_.twr_modules[s];
        const std::optional<double> range =
            realistic_
                ? sim::simulateRealisticTwr(m, hardware_[s], world_.twr, states_[s], at, t, rng)
                : sim::simulateTwrRange(m, world_.twr, at, rng);
        if (range) {
          locator.addRange(s, *range, t);
          if (observer_) {
            observer_({SensorReading::Kind::kRange, s, t, *range, 0.0});
          }
        }
      } else if (s >= modules + layout_.aoa_boards.size()) {
        blink(locator, s - modules - layout_.aoa_boards.size(), at, t, rng);
      } else {
        const std::size_t b = s - modules;
        const std::optional<sim::AoaSample> sample =
            realistic_ ? aoa_[b].simulate(world_.aoa, at, t, rng)
                       : sim::simulateAoa(layout_.aoa_boards[b], world_.aoa, at, rng);
        if (sample) {
          locator.addBearing(b, sample->azimuth, sample->elevation, sample->rssi, t);
          if (observer_) {
            observer_({SensorReading::Kind::kBearing, b, t, sample->azimuth, sample->elevation});
          }
        }
      }
    }
  }
}

void StandingRobotSensors::blink(estimation::Locator& locator, std::size_t source,
                                 const Eigen::Vector3d& target, double t, sim::Rng& rng) {
  // Source 0 is the target's device, 1.. the robot's modules at their known positions.
  const Eigen::Vector3d from = source == 0 ? target : layout_.twr_modules[source - 1].position;
  const std::size_t ref = world_.tdoa_reference;
  const std::vector<double> differences =
      sim::simulateBlink(tdoa_, layout_.tdoa_anchors, ref, world_.tdoa_sigma, from, t, rng);
  if (differences.empty()) {
    return;  // missed
  }
  feedTdoaBlink(locator, layout_, ref, differences,
                source == 0 ? std::nullopt : std::optional<std::size_t>(source - 1),
                world_.tdoa_sigma * world_.tdoa_sigma, t);
}

}  // namespace evaluation
}  // namespace radio_follow
