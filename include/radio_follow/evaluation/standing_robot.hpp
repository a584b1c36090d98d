// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <functional>
#include <optional>
#include <utility>
#include <vector>

#include "radio_follow/config/layout.hpp"
#include "radio_follow/estimation/locator.hpp"
#include "radio_follow/estimation/locator_node_params.hpp"
#include "radio_follow/sim/sensor_profile.hpp"
#include "radio_follow/sim/virtual_sensors.hpp"
#include "radio_follow/sim/world.hpp"

namespace radio_follow {
namespace evaluation {

/// The locator node's update period in the lab's open-loop runs (its shipped `rate`), s.
inline const double kLocatorUpdatePeriod = 1.0 / estimation::LocatorNodeParams().rate;

/// One range or bearing the standing robot's sensors delivered, as the locator got it.
struct SensorReading {
  enum class Kind { kRange, kBearing };
  Kind kind = Kind::kRange;
  std::size_t sensor = 0;  ///< index of the module or board in the layout
  double t = 0.0;          ///< s
  double value = 0.0;      ///< raw range (m) or azimuth in the board's frame (rad)
  double elevation = 0.0;  ///< bearings, rad
};

/// The sensors of one simulated robot that stands still, feeding a locator: every TWR
/// module and AoA board of `layout` reports at 10 Hz on its own phase, with the realistic
/// profile's hardware of robot `hardware_seed` (per-pair range bias and scale, mounting
/// errors, TDoA anchor offsets) and time-correlated noise state, or the ideal profile's
/// white noise. With TDoA anchors the target and every module blink at 10 Hz too (the
/// modules' blinks calibrate the anchors, Locator::addTdoaCalibration). Used by the cold
/// starts and the thesis's Experiments 1-2, where the robot does not move and the robot
/// frame is the world frame.
class StandingRobotSensors {
 public:
  /// Sensor report period, s.
  static constexpr double kPeriod = 0.1;

  /// Draws each sensor's phase from `rng`.
  StandingRobotSensors(const Layout& layout, const sim::WorldConfig& world,
                       std::uint64_t hardware_seed, sim::Rng& rng);

  /// Feeds `locator` every reading due up to `now`, of a target at `target(t)` (robot
  /// frame) at the reading's time t. Readings a sensor does not deliver (dropouts, out of
  /// view) are skipped.
  void feed(estimation::Locator& locator, double now,
            const std::function<Eigen::Vector3d(double)>& target, sim::Rng& rng);
  /// Calls `observer` with every range and bearing fed from now on (TDoA blinks are not
  /// reported); for tracing. Empty: none.
  void observeReadings(std::function<void(const SensorReading&)> observer) {
    observer_ = std::move(observer);
  }

 private:
  /// One TDoA blink of `source` (0: the target at `target`; k: module k - 1).
  void blink(estimation::Locator& locator, std::size_t source, const Eigen::Vector3d& target,
             double t, sim::Rng& rng);

  const Layout& layout_;
  const sim::WorldConfig& world_;
  bool realistic_;
  std::vector<sim::TwrNoiseState> states_;
  std::vector<sim::TwrHardware> hardware_;
  std::vector<sim::AoaErrorState> aoa_;
  std::optional<sim::TdoaHardware> tdoa_;
  /// Next report time per sensor: modules, boards, then with TDoA anchors the target's
  /// blinks and each module's.
  std::vector<double> next_;
  std::function<void(const SensorReading&)> observer_;
};

}  // namespace evaluation
}  // namespace radio_follow
