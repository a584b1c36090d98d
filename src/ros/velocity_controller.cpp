// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/ros/velocity_controller.hpp"

#include "radio_follow/common/angles.hpp"

namespace radio_follow {

control::VelocityLawParams loadVelocityLawParams(const ros::NodeHandle& pnh,
                                                 const ControllerCommonParams& common) {
  control::VelocityLawParams p;
  pnh.param("follow_distance", p.follow_distance, p.follow_distance);
  pnh.param("slowdown_distance", p.slowdown_distance, p.slowdown_distance);
  pnh.param("degraded_speed_factor", p.degraded_speed_factor, p.degraded_speed_factor);
  pnh.param("allow_backwards", p.allow_backwards, p.allow_backwards);
  double backwards_deg = rad2deg(p.backwards_angle);
  pnh.param("backwards_angle_deg", backwards_deg, backwards_deg);
  p.backwards_angle = deg2rad(backwards_deg);
  pnh.param("backwards_cycles", p.backwards_cycles, p.backwards_cycles);
  loadPidGains(pnh, "linear_pid", p.linear);
  loadPidGains(pnh, "angular_pid", p.angular);
  p.max_linear = common.limits.max_linear;
  p.linear.output_limit = common.limits.max_linear;
  p.angular.output_limit = common.limits.max_angular;
  p.validate();
  return p;
}

control::TargetPolar targetPolar(const TargetEstimate& estimate) {
  control::TargetPolar t;
  t.range = estimate.range;
  t.bearing = estimate.bearing;
  t.range_valid = estimate.status == TargetEstimate::STATUS_OK ||
                  estimate.status == TargetEstimate::STATUS_DEGRADED;
  t.degraded = estimate.status == TargetEstimate::STATUS_DEGRADED;
  return t;
}

bool estimateUsable(const TargetEstimate& estimate) {
  return estimate.status != TargetEstimate::STATUS_LOST && std::isfinite(estimate.bearing) &&
         std::isfinite(estimate.range);
}

VelocityControllerNode::VelocityControllerNode(ros::NodeHandle& nh, ros::NodeHandle& private_nh)
    : ControllerBase(nh, private_nh, true), law_(loadVelocityLawParams(private_nh, common())) {
  estimate_sub_ = nh_.subscribe("target", 5, &VelocityControllerNode::onEstimate, this);
  start();
}

void VelocityControllerNode::onEstimate(const TargetEstimate::ConstPtr& msg) {
  estimate_ = msg;
  noteEstimate(msg->header.stamp, estimateUsable(*msg));
}

ControllerBase::Output VelocityControllerNode::compute(const ros::Time& /*now*/, double dt) {
  Output out;
  out.command = law_.update(targetPolar(*estimate_), dt);
  if (estimate_->status == TargetEstimate::STATUS_HEADING_ONLY) {
    out.text = "Direction only, turning to the target.";
  } else if (law_.arrived()) {
    out.state = control::FollowerState::kArrived;
    out.text = "At follow distance, waiting.";
  } else {
    out.text = law_.driving_backwards() ? "Following backwards." : "Following.";
  }
  return out;
}

}  // namespace radio_follow
