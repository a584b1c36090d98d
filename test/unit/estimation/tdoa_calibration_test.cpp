// SPDX-License-Identifier: BSD-3-Clause
// TDoA auto-calibration from the robot's own modules' blinks (issue 15 item 4).
#include "radio_follow/estimation/tdoa_calibration.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "radio_follow/common/param_error.hpp"
#include "radio_follow/estimation/locator.hpp"

namespace radio_follow {
namespace estimation {
namespace {

// The thesis's TDoA anchors on Spot (brozb/uwb_tdoa config) and one TWR module.
const char* const kLayout = R"(
target: {uwb_anchor_id: "DA12"}
twr_modules:
  - {id: "5722", position: [0.175, 0.075, 0.115]}
  - {id: "C4B5", position: [-0.30, 0.08, 0.098]}
tdoa_anchors:
  - {id: "2000", position: [0.29, 0.165, 0.135]}
  - {id: "2002", position: [0.29, -0.165, 0.135]}
  - {id: "2001", position: [-0.37, 0.0, 0.135]}
)";

/// |p - a| - |p - b| for anchors by index.
double difference(const Layout& l, const Eigen::Vector3d& p, std::size_t a, std::size_t b) {
  return (p - l.tdoa_anchors[a].position).norm() - (p - l.tdoa_anchors[b].position).norm();
}

TEST(TdoaCalibration, LearnsEachPairsOffsetFromTheModulesBlinks) {
  const Layout layout = parseLayout(kLayout, "test");
  TdoaCalibration calibration(layout, TdoaCalibrationConfig{});
  ASSERT_TRUE(calibration.active());
  // Anchor offsets (m): what each anchor's clock and antenna add to every tag's arrival.
  const double offset[3] = {0.04, -0.09, 0.12};
  std::mt19937 rng(7);
  std::normal_distribution<double> noise(0.0, 0.3);  // 1 ns per difference
  for (int k = 0; k < 100; ++k) {
    const double t = 0.05 * k;
    for (std::size_t m = 0; m < 2; ++m) {
      for (std::size_t a : {1u, 2u}) {
        const double d = difference(layout, layout.twr_modules[m].position, a, 0) + offset[a] -
                         offset[0] + noise(rng);
        ASSERT_TRUE(calibration.add(m, a, 0, d, t));
      }
    }
  }
  // 200 residuals per pair (two modules, 5 s): the median within 4 sigma/sqrt(n) of truth.
  ASSERT_TRUE(calibration.offset(1, 0));
  EXPECT_NEAR(*calibration.offset(1, 0), offset[1] - offset[0], 0.1);
  EXPECT_NEAR(*calibration.offset(2, 0), offset[2] - offset[0], 0.1);
  // The reversed pair's offset has the opposite sign.
  EXPECT_DOUBLE_EQ(*calibration.offset(0, 2), -*calibration.offset(2, 0));
  EXPECT_FALSE(calibration.offset(1, 2));  // never heard as a pair
  ASSERT_EQ(calibration.pairs().size(), 2u);
  EXPECT_EQ(calibration.pairs()[0].samples, 200u);  // both modules
}

TEST(TdoaCalibration, NeedsMinBlinksAndForgetsOutsideTheWindow) {
  const Layout layout = parseLayout(kLayout, "test");
  TdoaCalibrationConfig config;
  config.window = 2.0;
  config.min_blinks = 10;
  TdoaCalibration calibration(layout, config);
  const Eigen::Vector3d& m = layout.twr_modules[0].position;
  for (int k = 0; k < 9; ++k) {
    calibration.add(0, 1, 0, difference(layout, m, 1, 0) + 0.2, 0.1 * k);
  }
  EXPECT_FALSE(calibration.offset(1, 0));  // 9 < min_blinks
  calibration.add(0, 1, 0, difference(layout, m, 1, 0) + 0.2, 0.9);
  ASSERT_TRUE(calibration.offset(1, 0));
  EXPECT_NEAR(*calibration.offset(1, 0), 0.2, 1e-9);  // exact: every residual 0.2
  // The anchors' sync drifted: 2 s later only the new offset is in the window.
  for (int k = 0; k < 20; ++k) {
    calibration.add(0, 1, 0, difference(layout, m, 1, 0) - 0.1, 3.0 + 0.1 * k);
  }
  EXPECT_NEAR(*calibration.offset(1, 0), -0.1, 1e-9);
  EXPECT_EQ(calibration.pairs()[0].samples, 20u);
}

TEST(TdoaCalibration, TheMedianIgnoresLongReflections) {
  const Layout layout = parseLayout(kLayout, "test");
  TdoaCalibration calibration(layout, TdoaCalibrationConfig{});
  const Eigen::Vector3d& m = layout.twr_modules[1].position;
  for (int k = 0; k < 60; ++k) {  // above min_blinks (50)
    // Every fourth blink came round the robot's body: 1.5 m long.
    const double excess = k % 4 == 0 ? 1.5 : 0.0;
    calibration.add(1, 2, 0, difference(layout, m, 2, 0) + 0.05 + excess, 0.1 * k);
  }
  ASSERT_TRUE(calibration.offset(2, 0));
  EXPECT_NEAR(*calibration.offset(2, 0), 0.05, 1e-9);
}

TEST(TdoaCalibration, RefusesWhatItCannotUse) {
  const Layout layout = parseLayout(kLayout, "test");
  TdoaCalibration calibration(layout, TdoaCalibrationConfig{});
  EXPECT_FALSE(calibration.add(2, 1, 0, 0.1, 0.0));  // no third module
  EXPECT_FALSE(calibration.add(0, 3, 0, 0.1, 0.0));  // no fourth anchor
  EXPECT_FALSE(calibration.add(0, 1, 1, 0.1, 0.0));  // a pair needs two anchors
  EXPECT_FALSE(calibration.add(0, 1, 0, std::nan(""), 0.0));
  EXPECT_TRUE(calibration.pairs().empty());
  EXPECT_EQ(calibration.moduleOf("c4b5"), std::optional<std::size_t>(1));
  EXPECT_FALSE(calibration.moduleOf("DA12"));

  TdoaCalibrationConfig bad;
  bad.window = 0.0;
  try {
    bad.validate();
    FAIL() << "window 0 accepted";
  } catch (const ParamError& e) {
    EXPECT_NE(std::string(e.what()).find("tdoa_calibration_window"), std::string::npos);
  }
  bad = TdoaCalibrationConfig{};
  bad.min_blinks = 0;
  EXPECT_THROW(bad.validate(), ParamError);
}

TEST(TdoaCalibration, InactiveWithoutModulesOrWhenDisabled) {
  Layout layout = parseLayout(kLayout, "test");
  TdoaCalibrationConfig off;
  off.enabled = false;
  EXPECT_FALSE(TdoaCalibration(layout, off).active());
  layout.twr_modules.clear();
  EXPECT_FALSE(TdoaCalibration(layout, TdoaCalibrationConfig{}).active());
}

/// The locator holds the target's differences back until their pair is calibrated, then
/// fuses them corrected: the heading comes out right despite the anchors' offsets.
TEST(TdoaCalibration, TheLocatorFusesTheTargetsDifferencesCorrected) {
  const Layout layout = parseLayout(kLayout, "test");
  LocatorConfig config;
  config.estimator = Estimator::kSolver;
  config.tdoa_calibration.min_blinks = 10;
  Locator locator(layout, config);
  const double offset[3] = {0.0, 0.25, -0.2};  // large enough to turn the heading by 0.5 rad
  const Eigen::Vector3d person(0.0, 4.0, config.height);  // to the left
  const auto target = [&](std::size_t a) {
    return difference(layout, person, a, 0) + offset[a] - offset[0];
  };
  EXPECT_TRUE(locator.addTdoa(locator.layout().tdoaAnchorIndex("2002"),
                              locator.layout().tdoaAnchorIndex("2000"), target(1), 0.0, 0.0));
  EXPECT_TRUE(locator.addTdoa(locator.layout().tdoaAnchorIndex("2001"),
                              locator.layout().tdoaAnchorIndex("2000"), target(2), 0.0, 0.0));
  EXPECT_EQ(locator.stats().tdoa_uncalibrated, 2u);
  EXPECT_EQ(locator.update(0.0).status, TargetStatus::kLost);

  for (int k = 0; k < 10; ++k) {
    for (std::size_t a : {1u, 2u}) {
      const double d = difference(layout, layout.twr_modules[0].position, a, 0) + offset[a];
      EXPECT_TRUE(
          locator.addTdoaCalibration(locator.layout().twrModuleIndex("5722"),
                                     locator.layout().tdoaAnchorIndex(layout.tdoa_anchors[a].id),
                                     locator.layout().tdoaAnchorIndex("2000"), d, 0.01 * k));
    }
  }
  EXPECT_FALSE(locator.addTdoaCalibration(
      locator.layout().twrModuleIndex("DA12"), locator.layout().tdoaAnchorIndex("2002"),
      locator.layout().tdoaAnchorIndex("2000"), 0.1, 0.1));  // not a module
  EXPECT_EQ(locator.stats().tdoa_calibration_differences, 20u);
  locator.addTdoa(locator.layout().tdoaAnchorIndex("2002"),
                  locator.layout().tdoaAnchorIndex("2000"), target(1), 0.0, 0.2);
  locator.addTdoa(locator.layout().tdoaAnchorIndex("2001"),
                  locator.layout().tdoaAnchorIndex("2000"), target(2), 0.0, 0.2);
  const LocatorEstimate e = locator.update(0.2);
  ASSERT_EQ(e.status, TargetStatus::kHeadingOnly);
  const double heading = std::atan2(e.position.y(), e.position.x());
  EXPECT_NEAR(heading, std::atan2(person.y(), person.x()), 0.05);

  // The same differences uncorrected (calibration off): the offsets turn the heading.
  config.tdoa_calibration.enabled = false;
  Locator uncalibrated(layout, config);
  uncalibrated.addTdoa(uncalibrated.layout().tdoaAnchorIndex("2002"),
                       uncalibrated.layout().tdoaAnchorIndex("2000"), target(1), 0.0, 0.2);
  uncalibrated.addTdoa(uncalibrated.layout().tdoaAnchorIndex("2001"),
                       uncalibrated.layout().tdoaAnchorIndex("2000"), target(2), 0.0, 0.2);
  const LocatorEstimate u = uncalibrated.update(0.2);
  ASSERT_EQ(u.status, TargetStatus::kHeadingOnly);
  EXPECT_GT(std::abs(std::atan2(u.position.y(), u.position.x()) - heading), 0.2);
}

}  // namespace
}  // namespace estimation
}  // namespace radio_follow
