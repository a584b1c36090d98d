// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>
#include <vector>

#include "radio_follow/common/param_table.hpp"
#include "radio_follow/sim/obstacles.hpp"
#include "radio_follow/sim/serial_devices.hpp"
#include "radio_follow/sim/world.hpp"

namespace radio_follow {
namespace sim {

/// The simulator node's parameters (config/simulator.yaml), which the lockstep closed
/// loop reads from the same file.
struct SimulatorParams {
  std::string layout_file;
  std::string scenario_file;
  int seed = 1;
  double step_rate = 100.0;        ///< physics steps per simulated second
  double time_factor = 1.0;        ///< simulated seconds per wall second (sim time only)
  double cmd_timeout = 0.5;        ///< s without cmd_vel before the base stops by itself
  bool shutdown_on_finish = true;  ///< end the node (and a launch that requires it) at the end
  /// World frame of odometry; the robot frame is the layout's fixed_frame.
  std::string odom_frame = "odom";
  WorldConfig world;
  ScanConfig scan;
  /// "messages": publish driver messages; "serial": speak the devices' protocols on
  /// pseudo-terminals under serial_dir so the real drivers run in the loop.
  std::string output = "messages";
  std::string serial_dir = "/tmp/radio_follow_sim";
  std::vector<UnplugFault> unplug;

  /// Every parameter but the lists ~twr_occlusions and ~unplug (config/simulator.yaml).
  static const ParamTable<SimulatorParams>& table();
  void validate() const;
};

}  // namespace sim
}  // namespace radio_follow
