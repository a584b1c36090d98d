// SPDX-License-Identifier: BSD-3-Clause
// The commented example YAMLs in config/ document the defaults: check that they parse
// and agree with the in-class defaults of the core parameter structs that have no
// parameter table yet (the homing controller's).
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

// controller_common.yaml, velocity_controller.yaml, path_follower.yaml and locator.yaml:
// test/unit/common/param_tables_test.cpp checks them against the parameter tables.

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
