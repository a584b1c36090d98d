// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/sim/simulator_params.hpp"

#include "radio_follow/common/param_error.hpp"

namespace radio_follow {
namespace sim {

const ParamTable<SimulatorParams>& SimulatorParams::table() {
  using P = SimulatorParams;
  static const ParamTable<P> t =
      ParamTable<P>()
          .add("layout_file", &P::layout_file, "", "The robot's sensor layout (required).")
          .add("scenario_file", &P::scenario_file, "",
               "The person's walk and the obstacles (required).")
          .add("seed", &P::seed, "", "The noise's random seed.", Range::atLeast(0))
          .add("step_rate", &P::step_rate, "Hz", "Physics steps per simulated second.",
               Range::closed(10.0, 10000.0))
          .add("time_factor", &P::time_factor, "",
               "Simulated seconds per wall second (sim time only).", Range::aboveUpTo(0.0, 1000.0))
          .add("cmd_timeout", &P::cmd_timeout, "s",
               "Without cmd_vel this long the base stops by itself.", Range::above(0.0))
          .add("shutdown_on_finish", &P::shutdown_on_finish, "",
               "End the node (and a launch that requires it) when the scenario ends.")
          .add("odom_frame", &P::odom_frame, "", "World frame of odometry.")
          .include(WorldConfig::table(), &P::world)
          .include(ScanConfig::table(), &P::scan)
          .addChoice("output", &P::output,
                     std::vector<std::pair<std::string, std::string>>{{"messages", "messages"},
                                                                      {"serial", "serial"}},
                     "Publish the drivers' messages, or speak the devices' protocols on "
                     "pseudo-terminals under serial_dir so the real drivers run in the loop.")
          .add("serial_dir", &P::serial_dir, "", "Where the device links go (serial output).");
  return t;
}

void SimulatorParams::validate() const {
  require(!layout_file.empty(), "~layout_file", layout_file, "the path of a layout YAML");
  require(!scenario_file.empty(), "~scenario_file", scenario_file, "the path of a scenario YAML");
  table().check(*this);
  require(!odom_frame.empty(), "~odom_frame", odom_frame, "a non-empty frame name");
  require(output != "serial" || !serial_dir.empty(), "~serial_dir", serial_dir,
          "a directory for the device links");
  require(unplug.empty() || output == "serial", "~unplug", std::string("(list)"),
          "no faults unless ~output is 'serial'");
  world.validate();
  scan.validate();
}

}  // namespace sim
}  // namespace radio_follow
