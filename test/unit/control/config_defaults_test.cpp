// SPDX-License-Identifier: BSD-3-Clause
// The commented example YAMLs in config/ document the defaults: check that they parse
// and agree with the in-class defaults of the core parameter structs.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <string>

#include "radio_follow/common/angles.hpp"
#include "radio_follow/control/homing.hpp"
#include "radio_follow/control/homing_controller.hpp"
#include "radio_follow/control/obstacle_avoidance.hpp"
#include "radio_follow/control/rate_limiter.hpp"
#include "radio_follow/control/rssi_model.hpp"
#include "radio_follow/control/safety_monitor.hpp"
#include "radio_follow/control/velocity_law.hpp"

namespace radio_follow {
namespace control {
namespace {

YAML::Node load(const std::string& name) {
  return YAML::LoadFile(std::string(RF_CONFIG_DIR) + "/" + name);
}

TEST(ConfigDefaults, CommonYamlMatchesSafetyLimitsAndAvoidance) {
  const YAML::Node y = load("controller_common.yaml");
  const SafetyParams safety;
  EXPECT_DOUBLE_EQ(y["safe_distance"].as<double>(), safety.safe_distance);
  EXPECT_DOUBLE_EQ(y["estimate_timeout"].as<double>(), safety.estimate_timeout);
  EXPECT_DOUBLE_EQ(y["range_timeout"].as<double>(), safety.range_timeout);
  EXPECT_DOUBLE_EQ(y["hold_time"].as<double>(), safety.hold_time);
  const MotionLimits limits;
  EXPECT_DOUBLE_EQ(y["max_linear"].as<double>(), limits.max_linear);
  EXPECT_DOUBLE_EQ(y["max_angular"].as<double>(), limits.max_angular);
  EXPECT_DOUBLE_EQ(y["max_linear_accel"].as<double>(), limits.max_linear_accel);
  EXPECT_DOUBLE_EQ(y["max_linear_decel"].as<double>(), limits.max_linear_decel);
  EXPECT_DOUBLE_EQ(y["max_angular_accel"].as<double>(), limits.max_angular_accel);
  const AvoidanceParams avoidance;
  EXPECT_DOUBLE_EQ(y["avoidance"]["obstacle_threshold"].as<double>(), avoidance.obstacle_threshold);
  EXPECT_DOUBLE_EQ(y["avoidance"]["stop_threshold"].as<double>(), avoidance.stop_threshold);
  EXPECT_DOUBLE_EQ(y["avoidance"]["side_threshold"].as<double>(), avoidance.side_threshold);
  EXPECT_DOUBLE_EQ(y["avoidance"]["turn_rate"].as<double>(), avoidance.turn_rate);
}

TEST(ConfigDefaults, VelocityControllerYamlMatchesLaw) {
  const YAML::Node y = load("velocity_controller.yaml");
  const VelocityLawParams law;
  EXPECT_DOUBLE_EQ(y["follow_distance"].as<double>(), law.follow_distance);
  EXPECT_DOUBLE_EQ(y["slowdown_distance"].as<double>(), law.slowdown_distance);
  EXPECT_DOUBLE_EQ(y["closing_distance"].as<double>(), law.closing_distance);
  EXPECT_DOUBLE_EQ(y["stop_margin"].as<double>(), law.stop_margin);
  EXPECT_DOUBLE_EQ(y["feed_forward"].as<double>(), law.feed_forward);
  EXPECT_DOUBLE_EQ(y["degraded_speed_factor"].as<double>(), law.degraded_speed_factor);
  EXPECT_EQ(y["allow_backwards"].as<bool>(), law.allow_backwards);
  EXPECT_NEAR(deg2rad(y["backwards_angle_deg"].as<double>()), law.backwards_angle, 1e-12);
  EXPECT_EQ(y["backwards_cycles"].as<int>(), law.backwards_cycles);
  for (const auto& [key, gains] :
       {std::make_pair("linear_pid", law.linear), std::make_pair("angular_pid", law.angular)}) {
    EXPECT_DOUBLE_EQ(y[key]["kp"].as<double>(), gains.kp) << key;
    EXPECT_DOUBLE_EQ(y[key]["ki"].as<double>(), gains.ki) << key;
    EXPECT_DOUBLE_EQ(y[key]["kd"].as<double>(), gains.kd) << key;
    EXPECT_DOUBLE_EQ(y[key]["integral_limit"].as<double>(), gains.integral_limit) << key;
    EXPECT_DOUBLE_EQ(y[key]["derivative_time_constant"].as<double>(),
                     gains.derivative_time_constant)
        << key;
  }
}

TEST(ConfigDefaults, HomingYamlMatchesHomingParams) {
  const YAML::Node y = load("homing_controller.yaml");
  const HomingParams h;
  EXPECT_DOUBLE_EQ(y["tau"].as<double>(), h.tau);
  EXPECT_EQ(y["window"].as<int>(), h.window);
  EXPECT_DOUBLE_EQ(y["kohonen_k"].as<double>(), h.k);
  EXPECT_DOUBLE_EQ(y["min_baseline"].as<double>(), h.min_baseline);
  EXPECT_DOUBLE_EQ(y["min_parallax_angle"].as<double>(), h.min_parallax_angle);
  EXPECT_DOUBLE_EQ(y["error_threshold"].as<double>(), h.error_threshold);
  EXPECT_DOUBLE_EQ(y["z_threshold"].as<double>(), h.z_threshold);
  EXPECT_DOUBLE_EQ(y["arrival_distance"].as<double>(), h.arrival_distance);
  EXPECT_DOUBLE_EQ(y["agreement_distance"].as<double>(), h.agreement_distance);
  EXPECT_DOUBLE_EQ(y["linear_gain"].as<double>(), h.linear_gain);
  EXPECT_DOUBLE_EQ(y["angular_gain"].as<double>(), h.angular_gain);
  const RssiModel rssi;
  EXPECT_DOUBLE_EQ(y["rssi_at_1m"].as<double>(), rssi.rssi_at_1m);
  EXPECT_DOUBLE_EQ(y["rssi_exponent"].as<double>(), rssi.exponent);
  const HomingControllerParams law;
  EXPECT_DOUBLE_EQ(y["board_x"].as<double>(), law.board_x);
  EXPECT_DOUBLE_EQ(y["board_y"].as<double>(), law.board_y);
  EXPECT_DOUBLE_EQ(y["board_yaw"].as<double>(), law.board_yaw);
  EXPECT_EQ(y["distance_source"].as<std::string>(), law.distance_source);
  EXPECT_DOUBLE_EQ(y["distance_max_age"].as<double>(), law.distance_max_age);
  EXPECT_DOUBLE_EQ(y["odom_timeout"].as<double>(), law.odom_timeout);
  EXPECT_DOUBLE_EQ(y["search_speed"].as<double>(), law.search_speed);
}

}  // namespace
}  // namespace control
}  // namespace radio_follow
