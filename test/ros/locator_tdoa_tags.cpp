// SPDX-License-Identifier: BSD-3-Clause
// LocatorInputs with TDoA anchors (issue 15: "the locator takes TDoA messages of ANY tag:
// the robot's own modules' blinks would be fused as the person"; they calibrate the
// anchors instead). The messages are the tdoa_driver's (radio_follow/TdoaMeasurements);
// the estimator is the node's.
#include <gtest/gtest.h>
#include <ros/ros.h>

#include <map>
#include <string>

#include "radio_follow/TdoaMeasurements.h"
#include "radio_follow/config/layout.hpp"
#include "radio_follow/estimation/locator.hpp"
#include "radio_follow/ros/locator/locator_inputs.hpp"

namespace radio_follow {
namespace {

const char* const kLayout = R"(
target: {uwb_anchor_id: "DA12"}
twr_modules:
  - {id: "5722", position: [0.2, 0.0, 0.3]}
tdoa_anchors:
  - {id: a, position: [0.3, 0.3, 0.5]}
  - {id: b, position: [-0.3, 0.3, 0.5]}
  - {id: c, position: [-0.3, -0.3, 0.5]}
  - {id: d, position: [0.3, -0.3, 0.5]}
)";

/// What the inputs report in the locator's diagnostics, by key.
std::map<std::string, std::string> diagnostics(const LocatorInputs& inputs) {
  diagnostic_updater::DiagnosticStatusWrapper status;
  for (const auto& input : inputs.inputs()) {
    input->diagnose(status);
  }
  std::map<std::string, std::string> values;
  for (const auto& kv : status.values) {
    values[kv.key] = kv.value;
  }
  return values;
}

/// The differences the anchors measure for a tag at `at`, against anchor a.
TdoaMeasurements blink(const Layout& layout, const std::string& tag, const Eigen::Vector3d& at,
                       double t) {
  TdoaMeasurements msg;
  msg.header.stamp = ros::Time(t);
  msg.header.frame_id = "base_link";
  msg.tag_id = tag;
  for (std::size_t i = 1; i < layout.tdoa_anchors.size(); ++i) {
    TdoaDifference d;
    d.anchor_a = layout.tdoa_anchors[i].id;
    d.anchor_b = layout.tdoa_anchors[0].id;
    d.distance_difference = (at - layout.tdoa_anchors[i].position).norm() -
                            (at - layout.tdoa_anchors[0].position).norm();
    d.variance = 0.0004;
    msg.differences.push_back(d);
  }
  return msg;
}

TEST(LocatorTdoaTags, OnlyTheTargetsTagIsFused) {
  const Layout layout = parseLayout(kLayout, "test");
  estimation::LocatorConfig config;
  config.estimator = estimation::Estimator::kSolver;
  estimation::Locator locator(layout, config);
  LocatorInputs inputs(locator);
  // The robot's own module (5722, on the robot: its blinks point into the robot) and
  // someone else's tag, for five seconds: nothing reaches the estimate; the module's
  // blinks calibrate the anchors (min_blinks, 50, per pair), the stranger's are counted.
  for (int k = 0; k < 50; ++k) {
    EXPECT_EQ(inputs.add(blink(layout, "5722", layout.twr_modules[0].position, 0.1 * k)), 0u);
    EXPECT_EQ(inputs.add(blink(layout, "0c1f", Eigen::Vector3d(2.0, 3.0, 1.0), 0.1 * k)), 0u);
  }
  // Neither counts as the other: 50 of the robot's module, 50 of the stranger's tag.
  EXPECT_EQ(diagnostics(inputs).at("TDoA calibration blinks (robot's modules)"), "50");
  EXPECT_EQ(diagnostics(inputs).at("TDoA messages of other tags (not fused)"), "50");
  EXPECT_EQ(locator.stats().tdoa_calibration_differences, 150u);  // three differences each
  EXPECT_EQ(locator.update(5.0).status, TargetStatus::kLost);
  for (const auto& pair : locator.tdoaCalibration().pairs()) {
    ASSERT_TRUE(pair.offset);
    EXPECT_NEAR(*pair.offset, 0.0, 1e-9);  // exact differences: no offset
  }
  // The person's device (the layout's uwb_anchor_id, in any case): fused.
  const Eigen::Vector3d person(-4.0, -2.0, config.height);
  EXPECT_EQ(inputs.add(blink(layout, "da12", person, 5.05)), 0u);
  const estimation::LocatorEstimate e = locator.update(5.05);
  EXPECT_EQ(e.status, TargetStatus::kHeadingOnly);
  EXPECT_EQ(e.sources, kSourceTdoa);
  EXPECT_EQ(diagnostics(inputs).at("TDoA messages of other tags (not fused)"), "50");
}

}  // namespace
}  // namespace radio_follow

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "locator_tdoa_tags_rostest");
  return RUN_ALL_TESTS();
}
