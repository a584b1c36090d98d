// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/estimation/locator.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "../../support/true_ranges.hpp"
#include "radio_follow/common/param_error.hpp"
#include "radio_follow/common/plausibility.hpp"

namespace radio_follow {
namespace estimation {
namespace {

using test::feedRanges;
/// These tests feed true ranges: the layouts without their range calibration.
Layout layoutFile(const std::string& name) {
  return test::uncalibratedLayout(name);
}

void feedBearing(Locator& locator, const AoaBoard& board, const Eigen::Vector3d& from, double rssi,
                 double t) {
  const Eigen::Vector2d ae =
      predictBearing(from, board.position, board.orientation.toRotationMatrix());
  ASSERT_TRUE(locator.addBearing(locator.layout().aoaBoardIndex(board.id), ae(0), ae(1), rssi, t));
}

double headingError(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::abs(wrapAngle(std::atan2(a.y(), a.x()) - std::atan2(b.y(), b.x())));
}

TEST(Locator, NothingFreshIsLost) {
  Locator locator(layoutFile("spot.yaml"), test::solverBackend());
  EXPECT_EQ(locator.update(1.0).status, TargetStatus::kLost);
}

TEST(Locator, ThreeRangesGiveAPositionThatGoesStale) {
  LocatorConfig config = test::solverBackend();
  Locator locator(layoutFile("spot_twr.yaml"), config);
  const Eigen::Vector3d truth(-2.0, 3.0, config.height);
  feedRanges(locator, truth, 10.0);
  const LocatorEstimate e = locator.update(10.05);
  ASSERT_EQ(e.status, TargetStatus::kOk);
  EXPECT_LT((e.position - truth).norm(), 1e-4);
  EXPECT_EQ(e.sources, kSourceTwr);
  EXPECT_DOUBLE_EQ(e.stamp, 10.0);
  // Nothing new: after max_age every range is dropped and the target is lost.
  EXPECT_EQ(locator.update(10.0 + config.max_age + 0.01).status, TargetStatus::kLost);
  EXPECT_EQ(locator.stats().stale_dropped, 3u);
}

// Measurements stamped ahead of the clock never age: the locator kept publishing OK
// estimates 80 s ahead with no input at all. Now they are dropped (and counted).
TEST(Locator, MeasurementsFromTheFutureAreDroppedNotKeptFresh) {
  LocatorConfig config = test::solverBackend();
  Locator locator(layoutFile("spot_twr.yaml"), config);
  const Eigen::Vector3d truth(-2.0, 3.0, config.height);
  feedRanges(locator, truth, 90.0);  // a clock 80 s ahead
  EXPECT_EQ(locator.update(10.0).status, TargetStatus::kLost);
  EXPECT_EQ(locator.stats().future_dropped, 3u);
  EXPECT_EQ(locator.update(11.0).status, TargetStatus::kLost);  // gone, not waiting
}

// A bag looped under /use_sim_time: the clock goes back; the locator starts over and
// tracks on the new clock instead of freezing on slots stamped in its future.
TEST(Locator, ClockJumpBackStartsOver) {
  LocatorConfig config = test::solverBackend();
  Locator locator(layoutFile("spot_twr.yaml"), config);
  const Eigen::Vector3d truth(-2.0, 3.0, config.height);
  feedRanges(locator, truth, 50.0);
  ASSERT_EQ(locator.update(50.05).status, TargetStatus::kOk);
  EXPECT_EQ(locator.update(1.0).status, TargetStatus::kLost);
  feedRanges(locator, truth, 1.1);
  const LocatorEstimate e = locator.update(1.15);
  EXPECT_EQ(e.status, TargetStatus::kOk);
  EXPECT_LT((e.position - truth).norm(), 1e-3);
}

TEST(Locator, ImplausibleRangesAreRefused) {
  Locator locator(layoutFile("spot_twr.yaml"), test::solverBackend());
  EXPECT_FALSE(locator.addRange(locator.layout().twrModuleIndex("5722"), 1e154,
                                0.0));  // a long plain number from a device
  EXPECT_FALSE(locator.addRange(locator.layout().twrModuleIndex("5722"), kMaxUwbRange + 1.0, 0.0));
  EXPECT_EQ(locator.stats().invalid_measurements, 2u);
}

TEST(Locator, NoSensorSendsAnRssDirection) {
  // The particle estimator forms RSS directions from the bearings' RSSI: a reading of
  // that kind handed to the Locator is refused and counted, like any invalid input.
  Locator locator(layoutFile("cube.yaml"), LocatorConfig{});
  EXPECT_FALSE(locator.add(0.0, RssDirectionReading{0, 3.0}));
  EXPECT_FALSE(locator.add(std::nan(""), RangeReading{0, 3.0}));
  EXPECT_EQ(locator.stats().invalid_measurements, 2u);
  EXPECT_EQ(locator.update(0.0).status, TargetStatus::kLost);
}

TEST(Locator, OneRangeAloneIsLost) {
  Locator locator(layoutFile("spot_twr.yaml"), test::solverBackend());
  ASSERT_TRUE(locator.addRange(locator.layout().twrModuleIndex("5722"), 3.0, 0.0));
  EXPECT_EQ(locator.update(0.0).status, TargetStatus::kLost);
  EXPECT_FALSE(locator.addRange(locator.layout().twrModuleIndex("FFFF"), 3.0, 0.0));
  EXPECT_FALSE(locator.addRange(locator.layout().twrModuleIndex("5722"), -1.0, 0.0));
}

TEST(Locator, CubeWithOneRangeIgnoresTheBoardBehind) {
  LocatorConfig config = test::solverBackend();
  const Layout layout = layoutFile("cube.yaml");
  Locator locator(layout, config);
  const Eigen::Vector3d truth(4.0, 0.8, config.height);
  // "front" faces the target; "back" hears a reflection and reports a plausible bearing
  // towards a point 4 m behind-left of the robot.
  const Eigen::Vector3d ghost(-3.0, 3.0, config.height);
  // Until both boards were heard kMinRssiToChoose times no board is chosen, and one range
  // alone is no position.
  const int first = static_cast<int>(kMinRssiToChoose) - 1;
  for (int k = 0; k < first + 6; ++k) {
    const double t = 0.05 * k;
    feedRanges(locator, truth, t);
    feedBearing(locator, layout.aoa_boards[0], truth, -55.0, t);
    feedBearing(locator, layout.aoa_boards[2], ghost, -62.0, t);
    const LocatorEstimate e = locator.update(t);
    if (k < first) {
      EXPECT_EQ(e.status, TargetStatus::kLost) << "epoch " << k;
      continue;
    }
    ASSERT_EQ(e.status, TargetStatus::kOk) << "epoch " << k;
    EXPECT_LT((e.position - truth).norm(), 0.02) << "epoch " << k;
    EXPECT_EQ(e.bearings_used, std::vector<std::size_t>{0});
    EXPECT_EQ(e.sources, kSourceTwr | kSourceAoa);
  }
}

TEST(Locator, BearingOnlyIsHeadingOnly) {
  const Layout layout = layoutFile("cube.yaml");
  Locator locator(layout, test::solverBackend());
  const Eigen::Vector3d truth(1.0, 5.0, 1.0);
  LocatorEstimate e;
  for (std::size_t k = 0; k < kMinRssiToChoose; ++k) {
    feedBearing(locator, layout.aoa_boards[1], truth, -60.0, 0.1 * k);
    e = locator.update(0.1 * k + 0.01);
    if (k + 1 < kMinRssiToChoose) {
      EXPECT_EQ(e.status, TargetStatus::kLost) << k;  // still comparing the boards' RSSI
    }
  }
  ASSERT_EQ(e.status, TargetStatus::kHeadingOnly);
  EXPECT_LT(headingError(e.position, truth), 0.02);
  EXPECT_EQ(e.sources, kSourceAoa);
}

TEST(Locator, TdoaOnlyIsHeadingOnly) {
  const Layout layout = parseLayout(R"(
target: {tdoa_tag_id: "T1"}
tdoa_anchors:
  - {id: a, position: [0.3, 0.3, 0.5]}
  - {id: b, position: [-0.3, 0.3, 0.5]}
  - {id: c, position: [-0.3, -0.3, 0.5]}
  - {id: d, position: [0.3, -0.3, 0.5]}
)",
                                    "test");
  LocatorConfig config = test::solverBackend();
  Locator locator(layout, config);
  const Eigen::Vector3d truth(-4.0, -2.0, config.height);
  auto diff = [&](int a, int b) {
    return (truth - layout.tdoa_anchors[a].position).norm() -
           (truth - layout.tdoa_anchors[b].position).norm();
  };
  ASSERT_TRUE(locator.addTdoa(locator.layout().tdoaAnchorIndex("b"),
                              locator.layout().tdoaAnchorIndex("a"), diff(1, 0), 0.0004, 0.0));
  ASSERT_TRUE(locator.addTdoa(locator.layout().tdoaAnchorIndex("c"),
                              locator.layout().tdoaAnchorIndex("a"), diff(2, 0), 0.0004, 0.0));
  ASSERT_TRUE(locator.addTdoa(locator.layout().tdoaAnchorIndex("d"),
                              locator.layout().tdoaAnchorIndex("a"), diff(3, 0), 0.0004, 0.0));
  const LocatorEstimate e = locator.update(0.0);
  ASSERT_EQ(e.status, TargetStatus::kHeadingOnly);
  EXPECT_LT(headingError(e.position, truth), 0.05);
  EXPECT_EQ(e.sources, kSourceTdoa);
  EXPECT_FALSE(locator.addTdoa(locator.layout().tdoaAnchorIndex("a"),
                               locator.layout().tdoaAnchorIndex("a"), 0.0, 0.0, 0.0));
}

TEST(Locator, AppliesTheCalibrationPolynomial) {
  const Layout layout = parseLayout(R"(
target: {uwb_anchor_id: "DA12"}
twr_modules:
  - {id: "1", position: [0.3, 0.25, 0.4], calibration: [-0.1, 1.0]}
  - {id: "2", position: [0.3, -0.25, 0.4], calibration: [-0.1, 1.0]}
  - {id: "3", position: [-0.3, -0.25, 0.4], calibration: [-0.1, 1.0]}
)",
                                    "test");
  LocatorConfig config = test::solverBackend();
  Locator locator(layout, config);
  const Eigen::Vector3d truth(3.0, 1.0, config.height);
  for (const auto& m : layout.twr_modules) {
    locator.addRange(locator.layout().twrModuleIndex(m.id), (truth - m.position).norm() + 0.1,
                     0.0);  // raw reads 10 cm long
  }
  const LocatorEstimate e = locator.update(0.0);
  ASSERT_EQ(e.status, TargetStatus::kOk);
  EXPECT_LT((e.position - truth).norm(), 1e-4);
}

TEST(Locator, SubtractsTheBoardsElevationOffset) {
  // A board reading 8 deg low, calibrated (elevation_offset_deg: -8): the locator sees the
  // true elevation, which (no range) alone places the person along the bearing.
  const Layout layout = parseLayout(R"(
aoa_boards:
  - {id: front, position: [0.0, 0.0, 0.4], elevation_offset_deg: -8}
)",
                                    "test");
  LocatorConfig config = test::solverBackend();
  Locator locator(layout, config);
  const Eigen::Vector3d truth(2.0, 0.5, config.height);
  const AoaBoard& board = layout.aoa_boards[0];
  const Eigen::Vector2d ae =
      predictBearing(truth, board.position, board.orientation.toRotationMatrix());
  LocatorEstimate e;
  for (std::size_t k = 0; k < kMinRssiToChoose; ++k) {
    ASSERT_TRUE(locator.addBearing(locator.layout().aoaBoardIndex("front"), ae(0),
                                   ae(1) - deg2rad(8.0), -60.0, 0.1 * k));
    e = locator.update(0.1 * k + 0.01);
  }
  ASSERT_EQ(e.status, TargetStatus::kHeadingOnly);
  ASSERT_EQ(e.bearing_angles.size(), 1u);
  EXPECT_NEAR(e.bearing_angles[0](1), ae(1), 1e-12);
  EXPECT_LT((e.position - truth).norm(), 0.1);
}

TEST(Locator, TwoRangesNeedAWarmStart) {
  LocatorConfig config = test::solverBackend();
  Locator locator(layoutFile("tracked.yaml"), config);
  const Eigen::Vector3d truth(3.0, -1.0, config.height);
  // Five epochs of four ranges: the data have told the sides apart (mirror test).
  for (int k = 0; k < 5; ++k) {
    feedRanges(locator, truth, 0.1 * k);
    ASSERT_EQ(locator.update(0.1 * k).status, TargetStatus::kOk) << k;
  }
  // Two modules stop: two ranges keep tracking the confirmed side, flagged DEGRADED.
  ASSERT_TRUE(locator.addRange(locator.layout().twrModuleIndex("1A01"),
                               (truth - locator.layout().twr_modules[0].position).norm(), 0.9));
  ASSERT_TRUE(locator.addRange(locator.layout().twrModuleIndex("1A02"),
                               (truth - locator.layout().twr_modules[1].position).norm(), 0.9));
  const LocatorEstimate e = locator.update(1.05);
  EXPECT_EQ(e.status, TargetStatus::kDegraded);
  EXPECT_LT((e.position - truth).norm(), 1e-3);
}

// The same two ranges after a single epoch of four: nothing has confirmed the side yet,
// and two circles cross twice.
TEST(Locator, TwoRangesOfAnUnconfirmedTrackAreAmbiguous) {
  LocatorConfig config = test::solverBackend();
  Locator locator(layoutFile("tracked.yaml"), config);
  const Eigen::Vector3d truth(3.0, -1.0, config.height);
  feedRanges(locator, truth, 0.0);
  ASSERT_EQ(locator.update(0.0).status, TargetStatus::kOk);
  ASSERT_TRUE(locator.addRange(locator.layout().twrModuleIndex("1A01"),
                               (truth - locator.layout().twr_modules[0].position).norm(), 0.4));
  ASSERT_TRUE(locator.addRange(locator.layout().twrModuleIndex("1A02"),
                               (truth - locator.layout().twr_modules[1].position).norm(), 0.4));
  EXPECT_EQ(locator.update(0.55).status, TargetStatus::kAmbiguous);
}

TEST(LocatorConfig, ValidationNamesTheParameter) {
  LocatorConfig config = test::solverBackend();
  config.range_sigma = 0.0;
  try {
    config.validate();
    FAIL() << "expected ParamError";
  } catch (const ParamError& e) {
    EXPECT_EQ(e.name(), "~range_sigma");
  }
  config = test::solverBackend();
  config.gate_probability = 1.0;
  EXPECT_THROW(config.validate(), ParamError);
  config = test::solverBackend();
  config.range_loss = {LossType::kHuber, -1.0};
  EXPECT_THROW(Locator(layoutFile("spot.yaml"), config), ParamError);
}

// --- Mirror test (LocatorConfig::ambiguity_margin) ---

/// Three modules on the x axis: a target at (x, y) and at (x, -y) give the same ranges.
Layout collinearLayout() {
  Layout layout;
  layout.target_anchor_id = "DA12";
  const double xs[] = {-0.3, 0.0, 0.25};
  for (int i = 0; i < 3; ++i) {
    TwrModule m;
    m.id = "M" + std::to_string(i);
    m.frame_id = "uwb_" + m.id;
    m.position = Eigen::Vector3d(xs[i], 0.0, 1.0);
    layout.twr_modules.push_back(m);
  }
  return layout;
}

TEST(LocatorMirror, CollinearModulesAreAmbiguousAndStaySo) {
  LocatorConfig config = test::solverBackend();
  Locator locator(collinearLayout(), config);
  const Eigen::Vector3d truth(2.0, 3.0, config.height);
  for (int k = 0; k < 20; ++k) {
    const double t = 1.0 + 0.1 * k;
    feedRanges(locator, truth, t);
    const LocatorEstimate e = locator.update(t + 0.01);
    ASSERT_EQ(e.status, TargetStatus::kAmbiguous) << "epoch " << k;
    // Whichever side it holds, it is one of the two solutions.
    EXPECT_NEAR(std::abs(e.position.y()), 3.0, 0.05);
  }
  EXPECT_EQ(locator.stats().ambiguous, 20u);
}

TEST(LocatorMirror, OnTheModulesAxisBothSidesMeet) {
  LocatorConfig config = test::solverBackend();
  Locator locator(collinearLayout(), config);
  const Eigen::Vector3d truth(3.0, 0.1, config.height);  // mirror 0.2 m away: the same answer
  feedRanges(locator, truth, 1.0);
  const LocatorEstimate e = locator.update(1.01);
  EXPECT_TRUE(hasPosition(e.status)) << toString(e.status);  // DEGRADED: y is weak here
  EXPECT_EQ(locator.stats().ambiguous, 0u);
}

TEST(LocatorMirror, ZeroMarginDisablesTheTest) {
  LocatorConfig config = test::solverBackend();
  config.ambiguity_margin = 0.0;
  Locator locator(collinearLayout(), config);
  feedRanges(locator, Eigen::Vector3d(2.0, 3.0, config.height), 1.0);
  EXPECT_EQ(locator.update(1.01).status, TargetStatus::kOk);
  EXPECT_THROW(
      [] {
        LocatorConfig bad = test::solverBackend();
        bad.ambiguity_margin = -1.0;
        bad.validate();
      }(),
      ParamError);
}

// A bearing decides between the sides: the Spot layout (nearly collinear modules plus
// four boards) is never ambiguous, on either side of the robot.
TEST(LocatorMirror, ABearingDecides) {
  for (const double y : {3.0, -3.0}) {
    LocatorConfig config = test::solverBackend();
    Locator locator(layoutFile("spot.yaml"), config);
    const Eigen::Vector3d truth(-1.0, y, config.height);
    for (int k = 0; k < 15; ++k) {  // the boards are chosen after 10 RSSI values each
      const double t = 1.0 + 0.1 * k;
      feedRanges(locator, truth, t);
      for (const auto& board : locator.layout().aoa_boards) {
        const Eigen::Vector3d in_board = board.orientation.inverse() * (truth - board.position);
        const bool facing = in_board.x() > 0.0;
        feedBearing(locator, board, truth, facing ? -50.0 : -65.0, t);
      }
      const LocatorEstimate e = locator.update(t + 0.01);
      EXPECT_NE(e.status, TargetStatus::kAmbiguous) << "y " << y << " epoch " << k;
      if (k == 14) {
        EXPECT_LT((e.position - truth).norm(), 0.05) << "y " << y;
      }
    }
  }
}

// Noise must not confirm a side the geometry cannot tell: exactly collinear modules,
// ranges with the configured sigma of noise, 200 epochs: AMBIGUOUS throughout (a lucky run
// of epochs preferring one side would stop the test from saying so).
TEST(LocatorMirror, NoiseDoesNotConfirmASide) {
  LocatorConfig config = test::solverBackend();
  Locator locator(collinearLayout(), config);
  const Eigen::Vector3d truth(-2.0, 3.0, config.height);
  std::mt19937 rng(7);
  std::normal_distribution<double> noise(0.0, config.range_sigma);
  int ambiguous = 0;
  const int epochs = 200;
  for (int k = 0; k < epochs; ++k) {
    const double t = 1.0 + 0.1 * k;
    for (const auto& m : locator.layout().twr_modules) {
      ASSERT_TRUE(locator.addRange(locator.layout().twrModuleIndex(m.id),
                                   (truth - m.position).norm() + noise(rng), t));
    }
    ambiguous += locator.update(t + 0.01).status == TargetStatus::kAmbiguous;
  }
  EXPECT_GE(ambiguous, epochs * 95 / 100);
}

}  // namespace
}  // namespace estimation
}  // namespace radio_follow
