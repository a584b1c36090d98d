// SPDX-License-Identifier: BSD-3-Clause
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "radio_follow/common/angles.hpp"
#include "radio_follow/models/sensor_tables.hpp"
#include "radio_follow/sim/virtual_sensors.hpp"

namespace radio_follow {
namespace sim {
namespace {

struct Stats {
  double mean = 0.0;
  double sigma = 0.0;
};

Stats stats(const std::vector<double>& v) {
  Stats s;
  for (double x : v)
    s.mean += x;
  s.mean /= v.size();
  for (double x : v)
    s.sigma += (x - s.mean) * (x - s.mean);
  s.sigma = std::sqrt(s.sigma / (v.size() - 1));
  return s;
}

TEST(SensorTables, UwbTableRowsAreReproducedAndInterpolated) {
  EXPECT_NEAR(models::uwbRangeError(1.0).bias, -0.13, 1e-12);
  EXPECT_NEAR(models::uwbRangeError(10.0).sigma, 0.018, 1e-12);
  // Midway between 4 m (bias -0.06, sigma 0.018) and 6 m (-0.11, 0.033).
  EXPECT_NEAR(models::uwbRangeError(5.0).bias, -0.085, 1e-12);
  EXPECT_NEAR(models::uwbRangeError(5.0).sigma, 0.0255, 1e-12);
  // Held outside the measured 1-12 m.
  EXPECT_NEAR(models::uwbRangeError(0.3).bias, -0.13, 1e-12);
  EXPECT_NEAR(models::uwbRangeError(30.0).bias, -0.24, 1e-12);
}

TEST(SensorTables, AoaTablesMatchThesisRows) {
  // XPLR-AOA-1, 4 m, -80 deg: mean -6.27 (error +73.73 deg), sigma 50.77 (Table 3.4).
  models::AoaError e = models::aoaError(AoaBoardKind::kXplrAoa1, deg2rad(-80.0), 4.0);
  EXPECT_NEAR(rad2deg(e.azimuth_bias), 73.73, 1e-9);
  EXPECT_NEAR(rad2deg(e.azimuth_sigma), 50.77, 1e-9);
  EXPECT_NEAR(e.rssi_mean, -56.96, 1e-9);
  // ANT-B10, 1 m, 0 deg: mean -3.03, sigma 0.62 (Table 3.5).
  e = models::aoaError(AoaBoardKind::kAntB10, 0.0, 1.0);
  EXPECT_NEAR(rad2deg(e.azimuth_bias), -3.03, 1e-9);
  EXPECT_NEAR(rad2deg(e.azimuth_sigma), 0.62, 1e-9);
  // Halfway between the 1 m and 2 m tables at 20 deg for XPLR (sigma 1.92 and 2.29).
  e = models::aoaError(AoaBoardKind::kXplrAoa1, deg2rad(20.0), 1.5);
  EXPECT_NEAR(rad2deg(e.azimuth_sigma), 2.105, 1e-9);
  // RSSI keeps falling beyond the last table (4 m): 20 log10(8/4) = 6.02 dB weaker.
  const double at4 = models::aoaError(AoaBoardKind::kXplrAoa1, 0.0, 4.0).rssi_mean;
  const double at8 = models::aoaError(AoaBoardKind::kXplrAoa1, 0.0, 8.0).rssi_mean;
  EXPECT_NEAR(at4 - at8, 20.0 * std::log10(2.0), 1e-9);
}

TEST(VirtualSensors, TwrRangeHasTableBiasAndSigma) {
  TwrModule module;
  module.position = Eigen::Vector3d(0.2, 0.1, 0.0);
  const Eigen::Vector3d target = module.position + Eigen::Vector3d(6.0, 0.0, 0.0);
  Rng rng(1);
  std::vector<double> ranges;
  for (int i = 0; i < 20000; ++i) {
    ranges.push_back(*simulateTwrRange(module, TwrNoise{}, target, rng));
  }
  const Stats s = stats(ranges);
  EXPECT_NEAR(s.mean, 5.89, 0.002);
  EXPECT_NEAR(s.sigma, 0.033, 0.002);
}

TEST(VirtualSensors, TwrOcclusionJumpsToTheReflection) {
  TwrModule module;
  TwrNoise noise;
  noise.use_table_bias = false;
  noise.sigma_scale = 0.0;
  noise.occlusions.push_back(OcclusionSector{"", deg2rad(-60), deg2rad(-20), 1.0, 0.5});
  Rng rng(2);
  int reflected = 0;
  const int n = 4000;
  const Eigen::Vector3d occluded(3.0 * std::cos(deg2rad(-40)), 3.0 * std::sin(deg2rad(-40)), 0);
  for (int i = 0; i < n; ++i) {
    const double r = *simulateTwrRange(module, noise, occluded, rng);
    ASSERT_TRUE(std::abs(r - 3.0) < 1e-9 || std::abs(r - 4.0) < 1e-9) << r;
    reflected += r > 3.5;
  }
  EXPECT_NEAR(reflected / static_cast<double>(n), 0.5, 0.03);
  // Outside the sector: always the direct path.
  EXPECT_NEAR(*simulateTwrRange(module, noise, Eigen::Vector3d(0, 3, 0), rng), 3.0, 1e-9);
  // A sector naming another module leaves this one alone.
  noise.occlusions.front().module = "OTHER";
  noise.occlusions.front().reflection_probability = 1.0;
  EXPECT_NEAR(*simulateTwrRange(module, noise, occluded, rng), 3.0, 1e-9);
}

TEST(VirtualSensors, OcclusionSectorWrapsThroughPi) {
  const OcclusionSector back{"", deg2rad(150), deg2rad(-150), 1.0, 1.0};
  EXPECT_TRUE(back.contains(deg2rad(180)));
  EXPECT_TRUE(back.contains(deg2rad(-170)));
  EXPECT_FALSE(back.contains(0.0));
  EXPECT_FALSE(back.contains(deg2rad(140)));
}

TEST(VirtualSensors, DropoutRateIsHonoured) {
  TwrModule module;
  TwrNoise noise;
  noise.dropout_probability = 0.25;
  Rng rng(3);
  int lost = 0;
  for (int i = 0; i < 8000; ++i) {
    lost += !simulateTwrRange(module, noise, Eigen::Vector3d(2, 0, 0), rng).has_value();
  }
  EXPECT_NEAR(lost / 8000.0, 0.25, 0.02);
}

TEST(VirtualSensors, AoaInFrontFollowsTheTablesInPackageConvention) {
  AoaBoard board;
  board.kind = AoaBoardKind::kAntB10;
  board.position = Eigen::Vector3d(0.5, 0.0, 0.0);
  board.orientation = Eigen::AngleAxisd(kPi / 2.0, Eigen::Vector3d::UnitZ());  // faces +y
  // 2 m straight ahead of the board, 20 deg to its left (counter-clockwise).
  const double az = deg2rad(20.0);
  const Eigen::Vector3d local(2.0 * std::cos(az), 2.0 * std::sin(az), 0.0);
  const Eigen::Vector3d target = board.position + board.orientation * local;
  AoaNoise noise;
  Rng rng(4);
  std::vector<double> azimuths;
  for (int i = 0; i < 5000; ++i) {
    const auto s = simulateAoa(board, noise, target, rng);
    ASSERT_TRUE(s);
    EXPECT_FALSE(s->behind);
    azimuths.push_back(s->azimuth);
  }
  // Device convention is clockwise: the true device angle is -20 deg, Table 3.6 row -20:
  // mean -18.18, sigma 0.91 -> in our convention mean +18.18 deg.
  const Stats st = stats(azimuths);
  EXPECT_NEAR(rad2deg(st.mean), 18.18, 0.05);
  EXPECT_NEAR(rad2deg(st.sigma), 0.91, 0.05);
}

TEST(VirtualSensors, AoaBehindTheBoardReportsTheMirrorWithPlausibleRssi) {
  AoaBoard board;
  AoaNoise noise;
  noise.sigma_scale = 0.0;
  noise.use_table_bias = false;
  Rng rng(5);
  // Target behind and to the left: true azimuth 150 deg; the array sees 30 deg.
  const double az = deg2rad(150.0);
  const auto s =
      simulateAoa(board, noise, Eigen::Vector3d(3 * std::cos(az), 3 * std::sin(az), 0), rng);
  ASSERT_TRUE(s);
  EXPECT_TRUE(s->behind);
  EXPECT_NEAR(rad2deg(s->azimuth), 30.0, 1e-9);
  EXPECT_LT(s->rssi, -40.0);
  EXPECT_GT(s->rssi, -90.0);
}

// Like the board, the simulator never reports an angle outside [-90, 90] deg, however
// much noise it adds near the edge of the hemisphere (the drivers refuse such lines).
TEST(VirtualSensors, AoaAnglesStayInTheBoardsHemisphere) {
  AoaBoard board;
  AoaNoise noise;
  noise.sigma_scale = 5.0;
  Rng rng(7);
  int at_edge = 0;
  for (int i = 0; i < 2000; ++i) {
    const double az = deg2rad(-100.0 + 0.1 * i);  // sweeps both edges and behind
    const auto s =
        simulateAoa(board, noise, Eigen::Vector3d(3 * std::cos(az), 3 * std::sin(az), 2.5), rng);
    ASSERT_TRUE(s);
    ASSERT_LE(std::abs(s->azimuth), kPi / 2.0 + 1e-12) << i;
    ASSERT_LE(std::abs(s->elevation), kPi / 2.0 + 1e-12) << i;
    at_edge += std::abs(s->azimuth) == kPi / 2.0;
  }
  EXPECT_GT(at_edge, 0);  // the noise did reach the edge: the clamp was exercised
}

TEST(VirtualSensors, AoaOutOfRangeIsSilent) {
  AoaBoard board;
  AoaNoise noise;
  noise.max_range = 5.0;
  Rng rng(6);
  EXPECT_FALSE(simulateAoa(board, noise, Eigen::Vector3d(6, 0, 0), rng));
}

TEST(VirtualSensors, TdoaDifferencesAreExactWithoutNoise) {
  const std::vector<TdoaAnchor> anchors{{"A", Eigen::Vector3d(0, 0, 0)},
                                        {"B", Eigen::Vector3d(0.5, 0, 0)},
                                        {"C", Eigen::Vector3d(0, 0.5, 0)}};
  Rng rng(7);
  const Eigen::Vector3d p(3, 4, 0);
  const auto d = simulateTdoa(anchors, 0, 0.0, p, rng);
  ASSERT_EQ(d.size(), 2u);
  EXPECT_NEAR(d[0], (p - anchors[1].position).norm() - 5.0, 1e-12);
  EXPECT_NEAR(d[1], (p - anchors[2].position).norm() - 5.0, 1e-12);
  EXPECT_TRUE(simulateTdoa(anchors, 3, 0.0, p, rng).empty());
}

}  // namespace
}  // namespace sim
}  // namespace radio_follow
