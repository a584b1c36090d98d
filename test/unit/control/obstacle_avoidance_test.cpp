// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/control/obstacle_avoidance.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "radio_follow/common/angles.hpp"

namespace radio_follow {
namespace control {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// 181 beams from -90 to +90 deg, all at `far`, with `near` over [from, to] deg.
std::vector<float> scan(double far, double near, double from, double to) {
  std::vector<float> ranges(181, static_cast<float>(far));
  for (int deg = -90; deg <= 90; ++deg) {
    if (deg >= from && deg <= to) {
      ranges[static_cast<std::size_t>(deg + 90)] = static_cast<float>(near);
    }
  }
  return ranges;
}

TEST(ScanSectors, MinimumPerSector) {
  const SectorRanges s =
      scanSectors(scan(5.0, 0.8, 40, 50), deg2rad(-90.0), deg2rad(1.0), 0.05, 10.0, 0.4);
  EXPECT_NEAR(s.left, 0.8, 1e-6);
  EXPECT_NEAR(s.centre, 5.0, 1e-6);
  EXPECT_NEAR(s.right, 5.0, 1e-6);
  const SectorRanges c =
      scanSectors(scan(5.0, 0.8, 20, 25), deg2rad(-90.0), deg2rad(1.0), 0.05, 10.0, 0.4);
  EXPECT_NEAR(c.centre, 0.8, 1e-6);
  EXPECT_NEAR(c.centre_narrow, 5.0, 1e-6);  // 20..25 deg lies outside the middle 20 %
}

// The strip the robot sweeps: a return at 40 deg, 0.4 m away, is 0.26 m to the side and
// 0.31 m ahead; at 70 deg it is 0.38 m to the side (inside a 0.4 m strip), and a far
// wall's returns lie outside it.
TEST(ScanSectors, CorridorIsTheNearestReturnAheadWithinTheHalfWidth) {
  const SectorRanges s =
      scanSectors(scan(5.0, 0.4, 40, 40), deg2rad(-90.0), deg2rad(1.0), 0.05, 10.0, 0.4);
  EXPECT_NEAR(s.corridor, 0.4 * std::cos(deg2rad(40.0)), 1e-6);
  EXPECT_NEAR(s.centre, 5.0, 1e-6);  // the paper's centre sector does not see it
  const SectorRanges side =
      scanSectors(scan(kInf, 0.4, 70, 70), deg2rad(-90.0), deg2rad(1.0), 0.05, 10.0, 0.4);
  EXPECT_NEAR(side.corridor, 0.4 * std::cos(deg2rad(70.0)), 1e-6);
  const SectorRanges open =
      scanSectors(scan(kInf, 1.0, 40, 90), deg2rad(-90.0), deg2rad(1.0), 0.05, 10.0, 0.4);
  EXPECT_EQ(open.corridor, kInf);  // 1 m at 40 deg or more is 0.64 m or more to the side
}

TEST(ScanSectors, IgnoresInvalidReturns) {
  std::vector<float> ranges = scan(5.0, 0.01, 0, 0);
  ranges[10] = std::numeric_limits<float>::quiet_NaN();
  const SectorRanges s = scanSectors(ranges, deg2rad(-90.0), deg2rad(1.0), 0.05, 10.0, 0.4);
  EXPECT_NEAR(s.centre, 5.0, 1e-6);
}

TEST(AvoidObstacles, ClearScanChangesNothing) {
  const VelocityCommand cmd{0.8, 0.1};
  const VelocityCommand out =
      avoidObstacles(cmd, {kInf, kInf, kInf, kInf, kInf}, AvoidanceParams());
  EXPECT_EQ(out.linear, 0.8);
  EXPECT_EQ(out.angular, 0.1);
}

TEST(AvoidObstacles, StopsAndTurnsToFreerSideWhenBlocked) {
  const VelocityCommand out =
      avoidObstacles({0.8, 0.0}, {3.0, 0.3, 0.3, 1.0, kInf}, AvoidanceParams());
  EXPECT_EQ(out.linear, 0.0);
  EXPECT_GT(out.angular, 0.0);  // left is freer
}

TEST(AvoidObstacles, SlowsAndBendsForObstacleAhead) {
  AvoidanceParams params;
  const VelocityCommand out = avoidObstacles({1.0, 0.0}, {0.5, 1.0, 1.0, 3.0, kInf}, params);
  EXPECT_NEAR(out.linear, (1.0 - 0.35) / (1.5 - 0.35), 1e-12);
  EXPECT_LT(out.angular, 0.0);  // right is freer
}

// The corner of a wall the robot follows the person round: 0.41 m away at 34 deg (left
// sector, above side_threshold), 0.34 m ahead. The paper's rules let it drive on at full
// speed; the corridor stops the forward motion and turns it away.
TEST(AvoidObstacles, StopsForAnObstacleInTheCorridorOutsideTheCentreSector) {
  const double r = 0.41;
  const double a = deg2rad(34.0);
  const SectorRanges corner{r, kInf, kInf, kInf, r * std::cos(a)};
  const VelocityCommand out = avoidObstacles({0.7, 0.7}, corner, AvoidanceParams());
  EXPECT_EQ(out.linear, 0.0);
  EXPECT_LT(out.angular, 0.0);  // the right is freer
  const SectorRanges paper{r, kInf, kInf, kInf, kInf};
  EXPECT_EQ(avoidObstacles({0.7, 0.7}, paper, AvoidanceParams()).linear, 0.7);
}

TEST(AvoidObstacles, TurnsAwayFromCloseSide) {
  const VelocityCommand out =
      avoidObstacles({0.5, 0.3}, {0.3, kInf, kInf, kInf, kInf}, AvoidanceParams());
  EXPECT_EQ(out.linear, 0.5);
  EXPECT_LT(out.angular, 0.0);
}

TEST(AvoidObstacles, NeverRaisesSpeed) {
  for (double c : {0.1, 0.5, 1.0, 2.0}) {
    EXPECT_LE(avoidObstacles({0.4, 0.0}, {c, c, c, c, c}, AvoidanceParams()).linear, 0.4);
  }
}

}  // namespace
}  // namespace control
}  // namespace radio_follow
