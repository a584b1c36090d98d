// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/ros/control/controller_reconfigure.hpp"

#include <utility>

#include "radio_follow/ros/common/reconfigure_table.hpp"

namespace radio_follow {

namespace {

// The mappings follow from the parameter tables by name (ros/common/reconfigure_table.hpp).
ControllerTuningConfig toTuning(const ControllerCommonParams& p) {
  return tuningFromTable<ControllerTuningConfig>(
      control::CommandPipelineParams::table(),
      static_cast<const control::CommandPipelineParams&>(p));
}

ControllerCommonParams fromTuning(const ControllerTuningConfig& t, ControllerCommonParams p) {
  control::CommandPipelineParams& pipeline = p;
  pipeline = tableFromTuning(control::CommandPipelineParams::table(), t, pipeline);
  return p;
}

FollowLawTuningConfig toLawTuning(const control::VelocityLawParams& p) {
  return tuningFromTable<FollowLawTuningConfig>(control::VelocityLawParams::table(), p);
}

control::VelocityLawParams fromLawTuning(const FollowLawTuningConfig& t,
                                         control::VelocityLawParams p) {
  return tableFromTuning(control::VelocityLawParams::table(), t, std::move(p));
}

}  // namespace

std::unique_ptr<ControllerReconfigure> makeControllerReconfigure(
    const ros::NodeHandle& private_nh, const ControllerCommonParams& initial,
    std::function<void(const ControllerCommonParams&)> apply) {
  return std::make_unique<ControllerReconfigure>(private_nh, initial, toTuning, fromTuning,
                                                 std::move(apply));
}

std::unique_ptr<FollowLawReconfigure> makeFollowLawReconfigure(
    const ros::NodeHandle& private_nh, const control::VelocityLawParams& initial,
    std::function<void(const control::VelocityLawParams&)> apply) {
  return std::make_unique<FollowLawReconfigure>(
      ros::NodeHandle(private_nh, "law"), initial, toLawTuning, fromLawTuning,
      [private_nh, apply = std::move(apply)](const control::VelocityLawParams& p) {
        apply(p);  // throws ParamError to refuse: nothing is written then
        // The server only updates its copies under ~law; the node's own names too, so
        // that `rosparam get` (or a respawned node) sees the tuned values.
        writeTuned<FollowLawTuningConfig>(private_nh, control::VelocityLawParams::table(), p);
      });
}

}  // namespace radio_follow
