// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/ros/control/controller_reconfigure.hpp"

#include <utility>

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

FollowLawTuningConfig toLawTuning(const control::VelocityLawParams& p) {
  FollowLawTuningConfig t = FollowLawTuningConfig::__getDefault__();
  t.follow_distance = p.follow_distance;
  t.slowdown_distance = p.slowdown_distance;
  t.closing_distance = p.closing_distance;
  t.stop_margin = p.stop_margin;
  t.feed_forward = p.feed_forward;
  t.degraded_speed_factor = p.degraded_speed_factor;
  t.linear_pid_kp = p.linear.kp;
  t.linear_pid_ki = p.linear.ki;
  t.linear_pid_kd = p.linear.kd;
  t.linear_pid_integral_limit = p.linear.integral_limit;
  t.angular_pid_kp = p.angular.kp;
  t.angular_pid_ki = p.angular.ki;
  t.angular_pid_kd = p.angular.kd;
  t.angular_pid_integral_limit = p.angular.integral_limit;
  return t;
}

control::VelocityLawParams fromLawTuning(const FollowLawTuningConfig& t,
                                         control::VelocityLawParams p) {
  p.follow_distance = t.follow_distance;
  p.slowdown_distance = t.slowdown_distance;
  p.closing_distance = t.closing_distance;
  p.stop_margin = t.stop_margin;
  p.feed_forward = t.feed_forward;
  p.degraded_speed_factor = t.degraded_speed_factor;
  p.linear.kp = t.linear_pid_kp;
  p.linear.ki = t.linear_pid_ki;
  p.linear.kd = t.linear_pid_kd;
  p.linear.integral_limit = t.linear_pid_integral_limit;
  p.angular.kp = t.angular_pid_kp;
  p.angular.ki = t.angular_pid_ki;
  p.angular.kd = t.angular_pid_kd;
  p.angular.integral_limit = t.angular_pid_integral_limit;
  return p;
}

/// Writes an accepted law change back under the node's own parameter names (~follow_distance,
/// ~linear_pid/kp, ...): the server only updates its copies under ~law, and `rosparam get`
/// (or a respawned node) would otherwise see the start-up values.
void writeLawParams(const ros::NodeHandle& private_nh, const control::VelocityLawParams& p) {
  private_nh.setParam("follow_distance", p.follow_distance);
  private_nh.setParam("slowdown_distance", p.slowdown_distance);
  private_nh.setParam("closing_distance", p.closing_distance);
  private_nh.setParam("stop_margin", p.stop_margin);
  private_nh.setParam("feed_forward", p.feed_forward);
  private_nh.setParam("degraded_speed_factor", p.degraded_speed_factor);
  const auto pid = [&private_nh](const std::string& ns, const control::PidGains& gains) {
    private_nh.setParam(ns + "/kp", gains.kp);
    private_nh.setParam(ns + "/ki", gains.ki);
    private_nh.setParam(ns + "/kd", gains.kd);
    private_nh.setParam(ns + "/integral_limit", gains.integral_limit);
  };
  pid("linear_pid", p.linear);
  pid("angular_pid", p.angular);
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
        writeLawParams(private_nh, p);
      });
}

}  // namespace radio_follow
