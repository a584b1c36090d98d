// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/ros/controller_reconfigure.hpp"

#include <utility>

#include "radio_follow/common/param_error.hpp"

namespace radio_follow {

namespace {

ControllerTuningConfig toTuning(const ControllerCommonParams& p) {
  ControllerTuningConfig t = ControllerTuningConfig::__getDefault__();
  t.safe_distance = p.safety.safe_distance;
  t.estimate_timeout = p.safety.estimate_timeout;
  t.range_timeout = p.safety.range_timeout;
  t.hold_time = p.safety.hold_time;
  t.max_linear = p.limits.max_linear;
  t.max_angular = p.limits.max_angular;
  t.max_linear_accel = p.limits.max_linear_accel;
  t.max_linear_decel = p.limits.max_linear_decel;
  t.max_angular_accel = p.limits.max_angular_accel;
  return t;
}

ControllerCommonParams fromTuning(const ControllerTuningConfig& t, ControllerCommonParams p) {
  p.safety.safe_distance = t.safe_distance;
  p.safety.estimate_timeout = t.estimate_timeout;
  p.safety.range_timeout = t.range_timeout;
  p.safety.hold_time = t.hold_time;
  p.limits.max_linear = t.max_linear;
  p.limits.max_angular = t.max_angular;
  p.limits.max_linear_accel = t.max_linear_accel;
  p.limits.max_linear_decel = t.max_linear_decel;
  p.limits.max_angular_accel = t.max_angular_accel;
  return p;
}

}  // namespace

ControllerReconfigure::ControllerReconfigure(
    const ros::NodeHandle& private_nh, const ControllerCommonParams& initial,
    std::function<void(const ControllerCommonParams&)> apply)
    : server_(mutex_, private_nh), current_(initial), apply_(std::move(apply)) {
  // Replace what the server read (parameter server or .cfg defaults) by the values in use.
  server_.updateConfig(toTuning(current_));
  server_.setCallback(
      [this](ControllerTuningConfig& request, uint32_t level) { onRequest(request, level); });
}

void ControllerReconfigure::onRequest(ControllerTuningConfig& request, uint32_t /*level*/) {
  try {
    const ControllerCommonParams next = fromTuning(request, current_);
    next.validate();
    apply_(next);
    current_ = next;
  } catch (const ParamError& e) {
    ROS_ERROR("controller: reconfigure refused, old values kept: %s", e.what());
    request = toTuning(current_);  // the server stores and publishes what is left here
  }
}

}  // namespace radio_follow
