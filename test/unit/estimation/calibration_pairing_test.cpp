// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/estimation/calibration_pairing.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>

#include "radio_follow/common/angles.hpp"
#include "radio_follow/common/param_error.hpp"

namespace radio_follow {
namespace estimation {
namespace {

using Kind = CalibrationMeasurement::Kind;

Layout twoSensors() {
  return parseLayout(R"(
target: {uwb_anchor_id: "DA12"}
twr_modules:
  - {id: "5722", position: [0.2, 0.0, 0.1]}
aoa_boards:
  - {id: left, position: [0.0, 0.1, 0.25], rpy_deg: [0, 0, 90]}
)",
                     "test");
}

TEST(CalibrationReference, InterpolatesTheTrackAndDropsMeasurementsInItsGaps) {
  const CalibrationReference r = CalibrationReference::fromTrack(
      {{2.0, {2.0, 0.0, 1.0}}, {1.0, {1.0, 0.0, 1.0}}, {5.0, {5.0, 0.0, 1.0}}}, 0.6);
  Eigen::Vector3d p;
  ASSERT_EQ(r.at(1.25, 0.0, p), CalibrationReference::Lookup::kFound);  // unsorted input
  EXPECT_NEAR(p.x(), 1.25, 1e-12);
  EXPECT_NEAR(p.z(), 1.0, 1e-12);
  // 2.5 s from both neighbours of 3.5: the tag may have gone anywhere.
  EXPECT_EQ(r.at(3.5, 0.0, p), CalibrationReference::Lookup::kGap);
  ASSERT_EQ(r.at(4.5, 0.0, p), CalibrationReference::Lookup::kFound);
  EXPECT_NEAR(p.x(), 4.5, 1e-12);
  // Beyond the ends: the end sample, held while close enough.
  ASSERT_EQ(r.at(5.5, 0.0, p), CalibrationReference::Lookup::kFound);
  EXPECT_NEAR(p.x(), 5.0, 1e-12);
  EXPECT_EQ(r.at(5.7, 0.0, p), CalibrationReference::Lookup::kGap);
  EXPECT_EQ(r.at(0.3, 0.0, p), CalibrationReference::Lookup::kGap);
  EXPECT_THROW(CalibrationReference::fromTrack({}, 0.1), std::invalid_argument);
  EXPECT_THROW(CalibrationReference::fromTrack({{0.0, Eigen::Vector3d::Zero()}}, 0.0),
               std::invalid_argument);
}

TEST(CalibrationReference, TapePointsAreLookedUpByRecordingTime) {
  const CalibrationReference r = CalibrationReference::fromPoints(
      parseTapePoints("points:\n  - {position: [2, 0, 1], from: 5, until: 20}\n"
                      "  - {position: [0, 3, 1], from: 30, until: 45.5}\n",
                      "test"));
  Eigen::Vector3d p;
  // The header stamp plays no part: windows are on the recording's clock.
  ASSERT_EQ(r.at(1e9, 30.0, p), CalibrationReference::Lookup::kFound);
  EXPECT_EQ(p, Eigen::Vector3d(0, 3, 1));
  EXPECT_EQ(r.at(0.0, 25.0, p), CalibrationReference::Lookup::kNoWindow);
  EXPECT_EQ(r.at(0.0, 45.6, p), CalibrationReference::Lookup::kNoWindow);
}

TEST(ParseTapePoints, NamesTheFieldValueAndExpectation) {
  auto message = [](const std::string& text) {
    try {
      parseTapePoints(text, "p.yaml");
    } catch (const ParamError& e) {
      return std::string(e.what());
    }
    return std::string("(accepted)");
  };
  EXPECT_NE(message("points:\n  - {position: [1, 2], from: 0, until: 1}\n")
                .find("'points[0].position' = [1, 2]"),
            std::string::npos);
  EXPECT_NE(message("points:\n  - {position: [1, 2, 0], from: 3, until: 1}\n")
                .find("'points[0].until' = 1: expected a time after `from` (3 s)"),
            std::string::npos);
  EXPECT_NE(
      message("points:\n  - {position: [1, 2, 0], from: -1, until: 1}\n").find("'points[0].from'"),
      std::string::npos);
  EXPECT_NE(message("points:\n  - {position: [1, 2, 0], from: 0, untl: 1}\n").find("untl"),
            std::string::npos);
  EXPECT_NE(message("points:\n  - {position: [1, 0, 0], from: 10, until: 20}\n"
                    "  - {position: [2, 0, 0], from: 0, until: 11}\n")
                .find("'points[0].from' = 10: expected a window not overlapping points[1]"),
            std::string::npos);
  EXPECT_NE(message("points: []\n").find("'points'"), std::string::npos);
  EXPECT_NE(message("[1, 2]").find("'points' = 'p.yaml'"), std::string::npos);
}

TEST(PairWithReference, TrueDistanceIs3dAndTrueAzimuthIsInTheBoardFrame) {
  const Layout layout = twoSensors();
  const Eigen::Vector3d tag(0.2, 3.0, 1.1);
  const CalibrationReference r = CalibrationReference::fromTrack({{0.0, tag}, {1.0, tag}}, 0.6);
  const CalibrationSamples s = pairWithReference({{Kind::kRange, "5722", 0.5, 0.0, 3.3},
                                                  {Kind::kRange, "uwb_5722", 0.5, 0.0, 3.4},
                                                  {Kind::kBearing, "aoa_left", 0.6, 0.0, 0.1},
                                                  {Kind::kRange, "FFFF", 0.5, 0.0, 1.0},
                                                  {Kind::kRange, "5722", 3.0, 0.0, 1.0},
                                                  {Kind::kRange, "5722", 0.5, 0.0, NAN}},
                                                 layout, r);
  ASSERT_EQ(s.ranges.at("5722").size(), 2u);  // by ID and by frame
  EXPECT_NEAR(s.ranges.at("5722")[0].truth, std::hypot(3.0, 1.0), 1e-12);
  EXPECT_DOUBLE_EQ(s.ranges.at("5722")[1].raw, 3.4);
  ASSERT_EQ(s.azimuths.at("left").size(), 1u);
  // The board looks along +y: a tag at x = 0.2 ahead of it is to its right.
  EXPECT_NEAR(s.azimuths.at("left")[0].truth, -std::atan2(0.2, 2.9), 1e-12);
  EXPECT_EQ(s.unknown_sensor, 1u);
  EXPECT_EQ(s.gap_dropped, 1u);
  EXPECT_EQ(s.non_finite, 1u);
}

TEST(PairWithReference, LeavesOutBearingsFromOutsideTheFieldOfView) {
  const Layout layout = twoSensors();
  // Behind the left board (it looks along +y): what it reports there is a reflection.
  const CalibrationReference r = CalibrationReference::fromPoints({{{0.0, -3.0, 0.25}, 0, 10}});
  const CalibrationSamples s =
      pairWithReference({{Kind::kBearing, "left", 0.0, 1.0, 0.3}}, layout, r);
  EXPECT_EQ(s.outside_view, 1u);
  EXPECT_TRUE(s.azimuths.empty());
}

/// A person standing at tape points 1-8 m around the robot, the module reading
/// `bias` + (1 + `slope`) d with noise and 5 % long reflections; the board mounted
/// `yaw_error` rad off the layout's orientation.
std::vector<CalibrationMeasurement> standAtPoints(const Layout& layout,
                                                  std::vector<TapePoint>& points, double bias,
                                                  double slope, double yaw_error) {
  std::mt19937_64 rng(7);
  std::normal_distribution<double> noise(0.0, 0.05);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<CalibrationMeasurement> out;
  const TwrModule& module = layout.twr_modules[0];
  const AoaBoard& board = layout.aoa_boards[0];
  double t = 0.0;
  for (double d = 1.0; d <= 8.0; d += 1.0) {
    const double heading = deg2rad(60.0 + 10.0 * d);  // several directions, all left
    points.push_back({{d * std::cos(heading), d * std::sin(heading), 1.0}, t + 1.0, t + 11.0});
    for (int k = 0; k < 100; ++k) {
      const double since_start = t + 0.1 * k;  // a tenth before the window: walking
      const Eigen::Vector3d tag = points.back().position;
      double raw = bias + (1.0 + slope) * (tag - module.position).norm() + noise(rng);
      if (unit(rng) < 0.05) {
        raw += 0.5 + 2.0 * unit(rng);
      }
      out.push_back({Kind::kRange, module.id, 0.0, since_start + 0.01, raw});
      out.push_back({Kind::kBearing, board.id, 0.0, since_start + 0.02,
                     trueAzimuth(board, tag) - yaw_error + 0.3 * noise(rng)});
    }
    t += 12.0;
  }
  return out;
}

TEST(FitLayoutCalibration, RecoversBiasSlopeAndYawFromTapePoints) {
  const Layout layout = twoSensors();
  std::vector<TapePoint> points;
  const auto measurements = standAtPoints(layout, points, 0.15, 0.02, deg2rad(3.0));
  const CalibrationSamples s =
      pairWithReference(measurements, layout, CalibrationReference::fromPoints(points));
  EXPECT_EQ(s.outside_windows, 2u * 8u * 10u);  // the first second of each stay
  const LayoutCalibration c = fitLayoutCalibration(s, layout, 1, 30, true);
  ASSERT_EQ(c.modules.size(), 1u);
  ASSERT_TRUE(c.modules[0].fit) << c.modules[0].error;
  const RangeCalibrationFit& f = *c.modules[0].fit;
  // corrected = (raw - bias) / (1 + slope)
  EXPECT_NEAR(f.coefficients[1], 1.0 / 1.02, 0.01);
  EXPECT_NEAR(f.coefficients[0], -0.15 / 1.02, 0.03);
  EXPECT_GT(f.rejected, 20u);  // the reflections
  EXPECT_LT(f.rms_after, 0.06);
  EXPECT_GT(f.rms_before, 0.2);
  ASSERT_EQ(c.boards.size(), 1u);
  ASSERT_TRUE(c.boards[0].fit) << c.boards[0].error;
  EXPECT_NEAR(rad2deg(c.boards[0].fit->yaw_offset), 3.0, 0.3);
  EXPECT_EQ(c.fitted(), 2u);
}

TEST(FitLayoutCalibration, ASensorWithTooFewSamplesKeepsItsOldValueWithAReason) {
  const Layout layout = twoSensors();
  CalibrationSamples s;
  s.ranges["5722"] = std::vector<RangeSample>(10, {2.0, 2.0});
  const LayoutCalibration c = fitLayoutCalibration(s, layout, 1, 30, false);
  ASSERT_EQ(c.modules.size(), 1u);
  EXPECT_FALSE(c.modules[0].fit);
  EXPECT_EQ(c.modules[0].error, "10 samples paired with the reference, 30 needed");
  EXPECT_TRUE(c.boards.empty());  // not asked for
  // Enough samples but all at one distance: the fit's own refusal becomes the reason.
  s.ranges["5722"] = std::vector<RangeSample>(40, {2.0, 2.0});
  const LayoutCalibration one = fitLayoutCalibration(s, layout, 1, 30, true);
  EXPECT_NE(one.modules[0].error.find("span"), std::string::npos) << one.modules[0].error;
  EXPECT_EQ(one.boards[0].error, "0 samples paired with the reference, 30 needed");
  EXPECT_EQ(one.fitted(), 0u);
}

}  // namespace
}  // namespace estimation
}  // namespace radio_follow
