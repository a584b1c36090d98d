// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/config/layout.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "radio_follow/common/angles.hpp"
#include "radio_follow/common/param_error.hpp"
#include "radio_follow/config/layout_writer.hpp"

namespace radio_follow {
namespace {

const char* const kMinimal = R"(
target: {uwb_anchor_id: "DA12"}
twr_modules:
  - {id: "5722", position: [0.175, 0.075, 0.115], calibration: [0.1, 0.9, 0.01]}
  - {id: "5A84", frame_id: rear, position: [-0.07, -0.04, 0.093]}
aoa_boards:
  - {id: left, kind: ant_b10, position: [0, 0.065, 0.25], rpy_deg: [0, 0, 90],
     field_of_view_deg: 60, elevation_offset_deg: -6.5}
tdoa_anchors:
  - {id: A, position: [1, 0, 0]}
  - {id: B, position: [0, 1, 0]}
)";

/// Expects parseLayout to throw a ParamError naming `parameter`.
void expectRejected(const std::string& yaml, const std::string& parameter) {
  try {
    parseLayout(yaml, "test");
    FAIL() << "accepted a layout with a bad " << parameter;
  } catch (const ParamError& e) {
    EXPECT_EQ(e.name(), parameter) << e.what();
  }
}

TEST(Layout, ParsesEveryField) {
  const Layout layout = parseLayout(kMinimal, "test");
  EXPECT_EQ(layout.fixed_frame, "base_link");
  EXPECT_EQ(layout.target_anchor_id, "DA12");
  ASSERT_EQ(layout.twr_modules.size(), 2u);
  EXPECT_EQ(layout.twr_modules[0].frame_id, "uwb_5722");
  EXPECT_EQ(layout.twr_modules[1].frame_id, "rear");
  EXPECT_DOUBLE_EQ(layout.twr_modules[0].position.y(), 0.075);
  ASSERT_EQ(layout.aoa_boards.size(), 1u);
  const AoaBoard& board = layout.aoa_boards[0];
  EXPECT_EQ(board.frame_id, "aoa_left");
  EXPECT_EQ(board.kind, AoaBoardKind::kAntB10);
  EXPECT_NEAR(board.field_of_view, deg2rad(60.0), 1e-12);
  EXPECT_NEAR(board.elevation_offset, deg2rad(-6.5), 1e-12);
  // Yaw 90 deg: the board's boresight (x) points along the robot's +y.
  const Eigen::Vector3d boresight = board.orientation * Eigen::Vector3d::UnitX();
  EXPECT_NEAR(boresight.y(), 1.0, 1e-12);
  EXPECT_EQ(layout.tdoa_anchors.size(), 2u);
  EXPECT_NE(layout.findTwrModule("rear"), nullptr);
  EXPECT_NE(layout.findAoaBoard("aoa_left"), nullptr);
  EXPECT_EQ(layout.findTdoaAnchor("C"), nullptr);
}

TEST(Layout, CalibrationPolynomialIsLowestOrderFirst) {
  const Layout layout = parseLayout(kMinimal, "test");
  // 0.1 + 0.9 * 2 + 0.01 * 4
  EXPECT_NEAR(layout.twr_modules[0].correctRange(2.0), 1.94, 1e-12);
  EXPECT_DOUBLE_EQ(layout.twr_modules[1].correctRange(3.0), 3.0);
}

TEST(Layout, RejectsBadFieldsNamingThem) {
  expectRejected("twr_modules: []", "twr_modules");
  expectRejected("twr_modules: [{id: '1', position: [0, 0, 0]}]", "target.uwb_anchor_id");
  expectRejected("target: {uwb_anchor_id: X}\ntwr_modules: [{id: '1', position: [0, 0]}]",
                 "twr_modules[0].position");
  expectRejected("target: {uwb_anchor_id: X}\ntwr_modules: [{id: '1', position: [0, a, 0]}]",
                 "twr_modules[0].position");
  expectRejected("target: {uwb_anchor_id: X}\ntwr_modules: [{id: '1'}]", "twr_modules[0].position");
  expectRejected("aoa_boards: [{id: b}]", "aoa_boards[0].position");
  expectRejected("target: {uwb_anchor_id: X}\ntwr_modules: [{position: [0, 0, 0]}]",
                 "twr_modules[0].id");
  expectRejected(
      "target: {uwb_anchor_id: X}\ntwr_modules: [{id: '1', position: [0, 0, 0]},"
      " {id: '1', position: [1, 0, 0]}]",
      "twr_modules[1].id");
  expectRejected(
      "target: {uwb_anchor_id: X}\ntwr_modules: [{id: '1', position: [0, 0, 0], frame_id: f}]\n"
      "aoa_boards: [{id: b, frame_id: f, position: [0, 0, 0]}]",
      "aoa_boards[0].frame_id");
  expectRejected("aoa_boards: [{id: b, kind: xplr, position: [0, 0, 0]}]", "aoa_boards[0].kind");
  expectRejected("aoa_boards: [{id: b, position: [0, 0, 0], field_of_view_deg: 120}]",
                 "aoa_boards[0].field_of_view_deg");
  expectRejected("aoa_boards: [{id: b, position: [0, 0, 0], elevation_offset_deg: 45}]",
                 "aoa_boards[0].elevation_offset_deg");
  expectRejected("tdoa_anchors: [{id: A, position: [0, 0, 0]}]", "tdoa_anchors");
  expectRejected("twr_modules: {id: 1}", "twr_modules");
  expectRejected("[1, 2", "layout");
  expectRejected("just text", "layout");
}

// A misspelt key used to drop what it held without a word (`twr_module:` lost every module
// and the controller drove on while 0.5 m ranges arrived).
TEST(Layout, MisspeltKeysAreRefused) {
  expectRejected("target: {uwb_anchor_id: X}\ntwr_module: [{id: '1', position: [0, 0, 0]}]",
                 "twr_module");
  expectRejected(
      "target: {uwb_anchor_id: X}\n"
      "twr_modules: [{id: '1', position: [0, 0, 0], calibraton: [0.1, 1.0]}]",
      "twr_modules[0].calibraton");
  expectRejected("target: {uwb_anchor_id: X, aoa_tag: Y}\ntwr_modules: []", "target.aoa_tag");
  expectRejected("aoa_boards: [{id: b, position: [0, 0, 0], fov_deg: 60}]",
                 "aoa_boards[0].fov_deg");
}

TEST(Layout, TdoaMeasurementsAreTheTargetsOnlyFromItsTag) {
  // By default the person's UWB device blinks with its own ID.
  const Layout by_default = parseLayout(kMinimal, "test");
  EXPECT_EQ(by_default.target_tdoa_tag_id, "DA12");
  EXPECT_TRUE(by_default.isTargetTdoaTag("da12"));
  EXPECT_FALSE(by_default.isTargetTdoaTag("5722"));  // the robot's own module
  EXPECT_FALSE(by_default.isTargetTdoaTag(""));
  const Layout own = parseLayout(R"(
target: {uwb_anchor_id: "DA12", tdoa_tag_id: "0c1f"}
tdoa_anchors:
  - {id: A, position: [1, 0, 0]}
  - {id: B, position: [0, 1, 0]}
)",
                                 "test");
  EXPECT_TRUE(own.isTargetTdoaTag("0C1F"));
  EXPECT_FALSE(own.isTargetTdoaTag("DA12"));
  EXPECT_EQ(parseLayout(writeLayout(own, {"test"}), "test").target_tdoa_tag_id, "0C1F");
  // TDoA anchors and no way to tell the person's blinks from anyone else's: refused.
  expectRejected("tdoa_anchors: [{id: A, position: [1, 0, 0]}, {id: B, position: [0, 1, 0]}]",
                 "target.tdoa_tag_id");
}

TEST(Layout, IdsAreNormalisedAtParseTime) {
  const Layout layout = parseLayout(R"(
target: {uwb_anchor_id: "da12", aoa_tag_id: "ccf9578e0d8a"}
twr_modules:
  - {id: "5a84", position: [0, 0, 0]}
tdoa_anchors:
  - {id: "a1", position: [1, 0, 0]}
  - {id: "b2", position: [0, 1, 0]}
)",
                                    "test");
  EXPECT_EQ(layout.target_anchor_id, "DA12");
  EXPECT_EQ(layout.target_tag_id, "CCF9578E0D8A");
  EXPECT_EQ(layout.twr_modules[0].id, "5A84");
  EXPECT_NE(layout.findTwrModule("5a84"), nullptr);  // a message's lower-case ID
  EXPECT_NE(layout.findTdoaAnchor("a1"), nullptr);
}

TEST(Layout, ConventionalTopicsFollowTheSensorIds) {
  const SensorTopics topics = conventionalTopics(parseLayout(kMinimal, "test"));
  EXPECT_EQ(topics.uwb, (std::vector<std::string>{"uwb/5722/ranges", "uwb/5A84/ranges"}));
  EXPECT_EQ(topics.aoa, std::vector<std::string>{"aoa/left/bearing"});
  EXPECT_EQ(topics.tdoa, std::vector<std::string>{"tdoa/measurements"});
}

TEST(Layout, FootprintIsTheSensorsConvexHullGrownByTheMargin) {
  const Layout layout = parseLayout(kMinimal, "test");
  const double margin = 0.1;
  const std::vector<Eigen::Vector2d> hull = layoutFootprint(layout, margin);
  ASSERT_GE(hull.size(), 3u);
  // Counter-clockwise and convex: every turn is to the left.
  for (std::size_t i = 0; i < hull.size(); ++i) {
    const Eigen::Vector2d a = hull[(i + 1) % hull.size()] - hull[i];
    const Eigen::Vector2d b = hull[(i + 2) % hull.size()] - hull[(i + 1) % hull.size()];
    EXPECT_GT(a.x() * b.y() - a.y() * b.x(), 0.0) << i;
  }
  // Every module and board lies inside, at least the margin from each edge; the TDoA
  // anchors (off the robot, 1 m out) do not.
  auto edgeDistance = [&](const Eigen::Vector2d& p) {
    double nearest = 1e9;
    for (std::size_t i = 0; i < hull.size(); ++i) {
      const Eigen::Vector2d e = (hull[(i + 1) % hull.size()] - hull[i]).normalized();
      const Eigen::Vector2d d = p - hull[i];
      nearest = std::min(nearest, e.x() * d.y() - e.y() * d.x());  // > 0 inside
    }
    return nearest;
  };
  for (const auto& m : layout.twr_modules) {
    EXPECT_GE(edgeDistance(m.position.head<2>()), margin - 1e-9) << m.id;
  }
  for (const auto& b : layout.aoa_boards) {
    EXPECT_GE(edgeDistance(b.position.head<2>()), margin - 1e-9) << b.id;
  }
  for (const auto& a : layout.tdoa_anchors) {
    EXPECT_LT(edgeDistance(a.position.head<2>()), 0.0) << a.id;
  }
  // And not much more than the margin: the rear module's corner is at most 8 % further.
  EXPECT_LT(edgeDistance(Eigen::Vector2d(-0.07 - margin * 1.09, -0.04)), 0.0);
}

TEST(Layout, MissingFileIsAParamError) {
  EXPECT_THROW(loadLayoutFile("/nonexistent/layout.yaml"), ParamError);
}

TEST(Layout, ShippedLayoutsAreValid) {
  int layouts = 0;
  for (const auto& entry :
       std::filesystem::directory_iterator(std::string(RF_CONFIG_DIR) + "/layouts")) {
    SCOPED_TRACE(entry.path().string());
    const Layout layout = loadLayoutFile(entry.path().string());
    EXPECT_FALSE(layout.twr_modules.empty());
    ++layouts;
  }
  EXPECT_GE(layouts, 7);
}

TEST(Layout, UncalibratedModulesAreTheIdentityOnes) {
  const std::string dir = std::string(RF_CONFIG_DIR) + "/layouts/";
  EXPECT_TRUE(uncalibratedModules(loadLayoutFile(dir + "spot.yaml")).empty());
  EXPECT_EQ(uncalibratedModules(loadLayoutFile(dir + "small_kit.yaml")),
            (std::vector<std::string>{"2B01", "2B02"}));
}

TEST(Layout, AnUnreadablePathSaysWhatToDo) {
  try {
    loadLayoutFile("my_robot.yaml");
    FAIL() << "no error";
  } catch (const ParamError& e) {
    EXPECT_NE(std::string(e.what()).find("'~layout_file'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("give an absolute path"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace radio_follow
