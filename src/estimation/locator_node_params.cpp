// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/estimation/locator_node_params.hpp"

#include "radio_follow/common/param_error.hpp"

namespace radio_follow {
namespace estimation {

const ParamTable<LocatorNodeParams>& LocatorNodeParams::table() {
  using P = LocatorNodeParams;
  static const ParamTable<P> t =
      ParamTable<P>()
          .add("layout_file", &P::layout_file, "", "The robot's sensor layout (required).")
          .add("rate", &P::rate, "Hz", "Solves per second.", Range::aboveUpTo(0.0, 200.0))
          .add("target_frame", &P::target_frame, "", "Child frame of the published TF.")
          .add("publish_tf", &P::publish_tf, "", "Publish the TF to target_frame.")
          .add("input_timeout", &P::input_timeout, "s",
               "An input topic without a message this long is silent.",
               Range::aboveUpTo(0.0, 600.0))
          .add("path_length", &P::path_length, "", "Estimates kept in target_path; 0 = none.",
               Range::closed(0, 100000))
          .add("odom_frame", &P::odom_frame, "",
               "Odometry frame the particle estimator tracks in; empty = the robot's frame.")
          .add("tf_tolerance", &P::tf_tolerance, "s",
               "A stamp up to this much newer than the newest odometry TF uses that TF.",
               Range::closed(0.0, 1.0));
  return t;
}

void LocatorNodeParams::load(const ParamSource& nh) {
  table().load(nh, *this);
  for (const std::string& name : topicsParams()) {
    std::vector<std::string>& list = topics[name];
    nh.param(name, list, list);
  }
  locator.load(nh);
}

void LocatorNodeParams::validate() const {
  require(!layout_file.empty(), "~layout_file", layout_file, "the path of a layout YAML file");
  // All topic lists empty is fine: the node then uses the layout's conventional topics.
  table().check(*this);
  require(!target_frame.empty(), "~target_frame", target_frame, "a frame name");
  locator.validate();  // the core names its fields exactly like these private parameters
}

}  // namespace estimation
}  // namespace radio_follow
