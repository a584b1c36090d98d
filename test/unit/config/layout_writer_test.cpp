// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/config/layout_writer.hpp"

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <Eigen/Geometry>
#include <fstream>
#include <sstream>

#include "radio_follow/common/angles.hpp"
#include "radio_follow/common/param_error.hpp"
#include "radio_follow/config/layout.hpp"

namespace radio_follow {
namespace {

std::string shippedSpot() {
  std::ifstream in(std::string(RF_CONFIG_DIR) + "/layouts/spot.yaml");
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(WriteCalibratedLayout, ChangesOnlyTheCalibrationAndTheYaw) {
  const std::string input = shippedSpot();
  LayoutCalibrationUpdate update;
  update.range_calibration["5A84"] = {0.1, 0.98, 0.001};
  update.yaw_offset["left"] = deg2rad(2.5);
  const std::string text = writeCalibratedLayout(input, "spot.yaml", update, {"a header"});
  EXPECT_EQ(text.rfind("# a header\n", 0), 0u);
  const Layout before = parseLayout(input, "spot.yaml");
  const Layout after = parseLayout(text, "written");
  ASSERT_EQ(after.twr_modules.size(), before.twr_modules.size());
  EXPECT_EQ(after.twr_modules[1].calibration, (std::vector<double>{0.1, 0.98, 0.001}));
  EXPECT_EQ(after.twr_modules[0].calibration, before.twr_modules[0].calibration);
  for (std::size_t i = 0; i < after.twr_modules.size(); ++i) {
    EXPECT_EQ(after.twr_modules[i].id, before.twr_modules[i].id);
    EXPECT_EQ(after.twr_modules[i].position, before.twr_modules[i].position);
  }
  const Eigen::Quaterniond turned =
      before.aoa_boards[1].orientation * Eigen::AngleAxisd(deg2rad(2.5), Eigen::Vector3d::UnitZ());
  EXPECT_LT(after.aoa_boards[1].orientation.angularDistance(turned), 1e-6);
  EXPECT_LT(after.aoa_boards[0].orientation.angularDistance(before.aoa_boards[0].orientation),
            1e-12);
  EXPECT_EQ(after.target_anchor_id, before.target_anchor_id);
  // Quoted IDs stay quoted (a bare 5722 is an integer to other YAML readers), flow
  // mappings stay one line per sensor, the untouched values keep their digits.
  const std::size_t untouched = input.find(R"({id: "5722", position: [0.175, 0.075, 0.115],)");
  ASSERT_NE(untouched, std::string::npos) << input;
  EXPECT_NE(text.find(input.substr(untouched, input.find('}', untouched) + 1 - untouched)),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("rpy_deg: [0, 0, 92.5]"), std::string::npos) << text;
  EXPECT_NE(text.find("uwb_anchor_id: \"DA12\""), std::string::npos) << text;
}

TEST(WriteCalibratedLayout, AddsAMissingRpyAndRefusesUnknownSensors) {
  const std::string input =
      "target: {uwb_anchor_id: DA12}\n"
      "twr_modules:\n  - id: '1'\n    position: [0, 0, 0]\n"
      "aoa_boards:\n  - id: b\n    position: [0, 0, 0]\n";
  LayoutCalibrationUpdate update;
  update.yaw_offset["b"] = deg2rad(-4.0);
  update.elevation_offset["b"] = deg2rad(-7.25);
  update.range_calibration["1"] = {0.2, 1.0};
  const std::string text = writeCalibratedLayout(input, "in", update, {});
  const YAML::Node root = YAML::Load(text);
  EXPECT_NEAR(root["aoa_boards"][0]["rpy_deg"][2].as<double>(), -4.0, 1e-9);
  EXPECT_NEAR(root["aoa_boards"][0]["elevation_offset_deg"].as<double>(), -7.25, 1e-9);
  EXPECT_NEAR(parseLayout(text, "written").aoa_boards[0].elevation_offset, deg2rad(-7.25), 1e-9);
  // writeLayout keeps it too.
  EXPECT_NEAR(parseLayout(writeLayout(parseLayout(text, "written"), {}), "again")
                  .aoa_boards[0]
                  .elevation_offset,
              deg2rad(-7.25), 1e-9);
  EXPECT_EQ(root["twr_modules"][0]["calibration"].as<std::vector<double>>(),
            (std::vector<double>{0.2, 1.0}));
  update.range_calibration["2"] = {0.0, 1.0};
  EXPECT_THROW(writeCalibratedLayout(input, "in", update, {}), ParamError);
  update.range_calibration.erase("2");
  update.elevation_offset["c"] = 0.0;
  EXPECT_THROW(writeCalibratedLayout(input, "in", update, {}), ParamError);
  EXPECT_THROW(writeCalibratedLayout("twr_modules: 3\n", "in", {}, {}), ParamError);
}

TEST(RpyWithYawOffset, TurnsTheBoardAboutItsOwnZAxis) {
  EXPECT_TRUE(rpyWithYawOffset({0, 0, 179}, deg2rad(2.0)).isApprox(Eigen::Vector3d(0, 0, -179)));
  // Upside down, the board's z is the robot's -z: its yaw turns the other way.
  EXPECT_TRUE(rpyWithYawOffset({180, 0, 90}, deg2rad(2.0)).isApprox(Eigen::Vector3d(180, 0, 88)));
  // Tilted: roll and pitch move too; the rotation is what is checked.
  const Eigen::Vector3d rpy(0, 30, 45);
  const Eigen::Vector3d next = rpyWithYawOffset(rpy, deg2rad(5.0));
  auto rotation = [](const Eigen::Vector3d& d) {
    const Eigen::Vector3d r = deg2rad(1.0) * d;
    return Eigen::Quaterniond(Eigen::AngleAxisd(r.z(), Eigen::Vector3d::UnitZ()) *
                              Eigen::AngleAxisd(r.y(), Eigen::Vector3d::UnitY()) *
                              Eigen::AngleAxisd(r.x(), Eigen::Vector3d::UnitX()));
  };
  const Eigen::Quaterniond expected =
      rotation(rpy) * Eigen::AngleAxisd(deg2rad(5.0), Eigen::Vector3d::UnitZ());
  EXPECT_LT(rotation(next).angularDistance(expected), 1e-9);
}

}  // namespace
}  // namespace radio_follow
