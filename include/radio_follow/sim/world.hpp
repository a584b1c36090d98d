// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "radio_follow/common/param_source.hpp"
#include "radio_follow/config/layout.hpp"
#include "radio_follow/sim/robot.hpp"
#include "radio_follow/sim/sensor_profile.hpp"
#include "radio_follow/sim/target_path.hpp"
#include "radio_follow/sim/virtual_sensors.hpp"

namespace radio_follow {
namespace sim {

/// How often each kind of sensor reports, and how noisy it is.
struct SensorRates {
  double twr_hz = 10.0;   ///< per UWB module (DWM1001 default update rate)
  double aoa_hz = 10.0;   ///< per AoA board (C209 advertising interval 100 ms)
  double tdoa_hz = 10.0;  ///< blinks per second
};

struct WorldConfig {
  RobotLimits robot;
  SensorRates rates;
  TwrNoise twr;
  AoaNoise aoa;
  double tdoa_sigma = 0.3;  ///< m (1 ns)
  std::size_t tdoa_reference = 0;
  std::uint64_t seed = 1;  ///< the noise: every random draw but the hardware's
  SensorProfile profile = SensorProfile::kRealistic;
  /// The simulated robot's hardware (realistic profile): every module's bias and scale,
  /// every board's mounting error, every anchor's offset. Independent of `seed`.
  std::uint64_t hardware_seed = 1;
  /// The realistic profile's figures (not a parameter).
  RealisticFigures figures;

  /// The simulator's world parameters (config/simulator.yaml: sensor_profile,
  /// hardware_seed, robot/*, *_rate, twr_*, aoa_*, tdoa_*; not the seed nor
  /// twr_occlusions, which the caller sets).
  static const ParamTable<WorldConfig>& table();
  void load(const ParamSource& source);
  void validate() const;
};

/// Sensor events of one step, in the order they happened.
struct TwrEvent {
  double t;
  std::size_t module;  ///< index into Layout::twr_modules
  double range;        ///< m, as the module reports it (uncalibrated)
};
struct AoaEvent {
  double t;
  std::size_t board;  ///< index into Layout::aoa_boards
  AoaSample sample;
};
struct TdoaEvent {
  double t;
  std::vector<double> differences;  ///< vs the reference anchor, in anchor order
  /// Whose blink: the target's (nothing) or one of the robot's own TWR modules (index into
  /// Layout::twr_modules), which the anchors hear as well (TDoA auto-calibration).
  std::optional<std::size_t> module;
};

struct StepEvents {
  std::vector<TwrEvent> twr;
  std::vector<AoaEvent> aoa;
  std::vector<TdoaEvent> tdoa;
};

/// The simulated world: a robot driven by cmd_vel, a scripted target, and every
/// sensor of a layout reporting at its own rate and phase. Deterministic for a seed.
/// With the realistic profile the layout is where the sensors were meant to be: the
/// hardware errs from it (WorldConfig::hardware_seed), and a locator given the same
/// layout uncalibrated sees those errors (evaluation/calibration_run.hpp fits them).
class World {
 public:
  World(const Layout& layout, const Scenario& scenario, const WorldConfig& config);

  /// Advances by dt seconds under the command and returns the sensor events.
  StepEvents step(double cmd_linear, double cmd_angular, double dt);

  double time() const { return t_; }
  const UnicycleRobot& robot() const { return robot_; }
  /// The target in the world frame (z = tag height).
  Eigen::Vector3d targetInWorld() const;
  /// The target in the robot's fixed frame (the layout's frame).
  Eigen::Vector3d targetInRobot() const;
  /// The target's walking speed now, m/s.
  double targetSpeed() const { return scenario_.target.at(t_).speed; }
  bool finished() const { return t_ >= scenario_.duration; }
  const Scenario& scenario() const { return scenario_; }

 private:
  /// A sensor's next report time; phases are staggered like free-running devices.
  struct Schedule {
    double period;
    double next;
  };

  Layout layout_;
  Scenario scenario_;
  WorldConfig config_;
  UnicycleRobot robot_;
  Rng rng_;
  double t_ = 0.0;
  std::vector<Schedule> twr_schedule_;
  std::vector<Schedule> aoa_schedule_;
  Schedule tdoa_schedule_{0.0, 0.0};
  std::vector<Schedule> module_blink_schedule_;  ///< per TWR module, with TDoA anchors
  // The realistic profile's hardware and per-sensor noise state (unused when ideal).
  std::vector<TwrHardware> twr_hardware_;
  std::vector<TwrNoiseState> twr_state_;
  std::vector<AoaErrorState> aoa_state_;
  std::optional<TdoaHardware> tdoa_hardware_;
};

}  // namespace sim
}  // namespace radio_follow
