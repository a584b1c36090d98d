// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/estimation/aoa_selector.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "radio_follow/common/angles.hpp"
#include "radio_follow/common/param_error.hpp"

namespace radio_follow {
namespace estimation {
namespace {

// Four boards facing +x, +y, -x, -y (the thesis's cube).
std::vector<AoaCandidate> cube() {
  std::vector<AoaCandidate> boards;
  for (std::size_t i = 0; i < 4; ++i) {
    AoaCandidate c;
    c.board = i;
    const double yaw = kPi / 2.0 * static_cast<double>(i);
    c.rotation = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    c.position = 0.065 * c.rotation.col(0);
    c.field_of_view = deg2rad(70.0);
    boards.push_back(c);
  }
  return boards;
}

TEST(AoaSelector, FieldOfViewCone) {
  const auto boards = cube();
  EXPECT_TRUE(inFieldOfView(boards[0], Eigen::Vector3d(3.0, 1.0, 0.0)));
  EXPECT_FALSE(inFieldOfView(boards[0], Eigen::Vector3d(-3.0, 0.0, 0.0)));
  EXPECT_FALSE(inFieldOfView(boards[0], Eigen::Vector3d(0.5, 3.0, 0.0)));  // 80 deg off axis
  EXPECT_TRUE(inFieldOfView(boards[1], Eigen::Vector3d(0.5, 3.0, 0.0)));
}

TEST(AoaSelector, RssiModeUsesMeanMinusTwoStdAndMajority) {
  AoaSelectorConfig config;
  config.mode = AoaSelectionMode::kRssi;
  config.rssi_window = 4;
  config.vote_window = 3;
  AoaSelector selector(4, config);
  auto boards = cube();
  // Board 0: steady -60 dBm; board 1: higher mean but noisy -> lower score.
  for (double v : {-60.0, -60.0, -60.0, -60.0})
    selector.recordRssi(0, v);
  for (double v : {-45.0, -65.0, -45.0, -65.0})
    selector.recordRssi(1, v);
  EXPECT_NEAR(selector.score(0), -60.0, 1e-12);
  EXPECT_NEAR(selector.score(1), -75.0, 1e-12);
  std::vector<AoaCandidate> fresh{boards[0], boards[1]};
  const Eigen::Vector3d both(3.0, 2.5, 0.0);  // in both boards' fields of view
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(selector.select(fresh, both), std::vector<std::size_t>{0});
  }
  // Board 1 becomes best once; the majority of the last three selections keeps board 0.
  for (double v : {-50.0, -50.0, -50.0, -50.0})
    selector.recordRssi(1, v);
  EXPECT_EQ(selector.select(fresh, both), std::vector<std::size_t>{0});
  EXPECT_EQ(selector.select(fresh, both), std::vector<std::size_t>{1});
}

TEST(AoaSelector, ExternalModePicksTheBoardFacingTheEstimate) {
  AoaSelectorConfig config;
  config.mode = AoaSelectionMode::kExternal;
  AoaSelector selector(4, config);
  auto boards = cube();
  boards[2].rssi = -40.0;  // behind the robot, strongest (reflection): must not be chosen
  boards[0].rssi = -70.0;
  boards[1].rssi = -65.0;
  const std::vector<std::size_t> chosen =
      selector.select({boards[0], boards[1], boards[2]}, Eigen::Vector3d(3.0, 2.5, 0.0));
  // Target at 40 deg: in the cones of board 0 (40 deg) and board 1 (50 deg); 1 is louder.
  EXPECT_EQ(chosen, std::vector<std::size_t>{1});
}

TEST(AoaSelector, AllInFovUsesEveryBoardFacingTheEstimateAndNoOther) {
  AoaSelector selector(4, AoaSelectorConfig{});
  const auto boards = cube();
  const auto chosen = selector.select(boards, Eigen::Vector3d(3.0, 2.5, 0.0));
  EXPECT_EQ(chosen, (std::vector<std::size_t>{0, 1}));
  EXPECT_TRUE(selector.select({boards[2], boards[3]}, Eigen::Vector3d(3.0, 2.5, 0.0)).empty());
}

TEST(AoaSelector, ParsesModes) {
  EXPECT_EQ(parseAoaSelectionMode("external", "m"), AoaSelectionMode::kExternal);
  EXPECT_THROW(parseAoaSelectionMode("loudest", "aoa_selection"), ParamError);
}

TEST(AoaSelector, WithoutAnEstimateWaitsUntilEveryReportingBoardWasHeardEnough) {
  AoaSelector selector(4, AoaSelectorConfig());
  const auto boards = cube();
  const std::vector<AoaCandidate> fresh{boards[0], boards[2]};
  // The back board (tag behind it, 6 dB weaker) happens to report first.
  selector.recordRssi(2, -66.0);
  EXPECT_TRUE(selector.select(fresh, std::nullopt).empty());
  for (std::size_t k = 1; k < kMinRssiToChoose; ++k) {
    selector.recordRssi(0, -60.0);
    selector.recordRssi(2, -66.0);
    EXPECT_TRUE(selector.select(fresh, std::nullopt).empty()) << k;
  }
  selector.recordRssi(0, -60.0);  // now both have kMinRssiToChoose values
  EXPECT_EQ(selector.select(fresh, std::nullopt), std::vector<std::size_t>{0});
  // With an estimate the field of view decides at once.
  AoaSelector fresh_start(4, AoaSelectorConfig());
  EXPECT_EQ(fresh_start.select(fresh, Eigen::Vector3d(3.0, 0.0, 0.0)), std::vector<std::size_t>{0});
}

TEST(AoaSelector, AtStartUpTheLouderBoardWinsNotTheSteadierOne) {
  // The thesis score (mean - 2 std) would prefer the steady back board (-61 vs about
  // -63); the board facing the tag is louder on average, and that is what decides.
  for (const AoaSelectionMode mode :
       {AoaSelectionMode::kRssi, AoaSelectionMode::kExternal, AoaSelectionMode::kAllInFov}) {
    AoaSelectorConfig config;
    config.mode = mode;
    AoaSelector selector(4, config);
    const auto boards = cube();
    for (std::size_t k = 0; k < kMinRssiToChoose; ++k) {
      selector.recordRssi(0, k % 2 ? -51.0 : -59.0);  // mean -55, std 4
      selector.recordRssi(2, k % 2 ? -60.5 : -61.5);  // mean -61, std 0.5
    }
    ASSERT_LT(selector.score(0), selector.score(2));
    EXPECT_EQ(selector.select({boards[0], boards[2]}, std::nullopt), std::vector<std::size_t>{0});
  }
}

}  // namespace
}  // namespace estimation
}  // namespace radio_follow
