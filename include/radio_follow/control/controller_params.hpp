// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>

#include "radio_follow/common/param_table.hpp"

namespace radio_follow {
namespace control {

/// What every controller node reads besides its command pipeline and its law
/// (doc/nodes/velocity_controller.md); the lockstep closed loop runs at the same rate.
struct ControllerWiring {
  std::string cmd_vel_topic = "cmd_vel";
  double rate = 20.0;  ///< Hz
  bool start_enabled = false;
  /// Optional sensor layout: when set, `range_topics` and `target_anchor_id` default to
  /// the layout's conventional topics (`uwb/<module id>/ranges`) and target anchor.
  std::string layout_file;

  static const ParamTable<ControllerWiring>& table();
};

}  // namespace control
}  // namespace radio_follow
