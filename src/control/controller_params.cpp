// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/control/controller_params.hpp"

namespace radio_follow {
namespace control {

const ParamTable<ControllerWiring>& ControllerWiring::table() {
  using W = ControllerWiring;
  static const ParamTable<W> t =
      ParamTable<W>()
          .add("cmd_vel_topic", &W::cmd_vel_topic, "", "Output topic (relative).")
          .add("rate", &W::rate, "Hz", "Control and publish rate.", Range::closed(1.0, 200.0))
          .add("start_enabled", &W::start_enabled, "", "Follow without an enable request.")
          .add("layout_file", &W::layout_file, "",
               "Optional sensor layout: range_topics and target_anchor_id then follow it.");
  return t;
}

}  // namespace control
}  // namespace radio_follow
