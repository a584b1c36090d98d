// SPDX-License-Identifier: BSD-3-Clause
// What the follow laws take from an estimate (targetPolar, polarSpread) and which
// estimates the followers' track takes (TrackGate).
#include "radio_follow/control/follow_inputs.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace radio_follow {
namespace control {
namespace {

TEST(TrackGate, ADegradedEstimateCountsOnlyInATrackThatWasOk) {
  TrackGate gate;
  EXPECT_FALSE(gate.accept(TargetStatus::kDegraded)) << "a young track's wide cloud";
  EXPECT_FALSE(gate.accept(TargetStatus::kDegraded));
  EXPECT_TRUE(gate.accept(TargetStatus::kOk));
  EXPECT_TRUE(gate.accept(TargetStatus::kDegraded)) << "the confirmed track gone wide";
  EXPECT_TRUE(gate.accept(TargetStatus::kDegraded));
  EXPECT_TRUE(gate.accept(TargetStatus::kOk));
}

TEST(TrackGate, AnEstimateWithoutAPositionEndsTheTrack) {
  for (const TargetStatus gap : {TargetStatus::kLost, TargetStatus::kAmbiguous,
                                 TargetStatus::kHeadingOnly, TargetStatus::kUnset}) {
    TrackGate gate;
    ASSERT_TRUE(gate.accept(TargetStatus::kOk));
    EXPECT_FALSE(gate.accept(gap)) << toString(gap);
    EXPECT_FALSE(gate.accept(TargetStatus::kDegraded))
        << "after " << toString(gap) << " the track is young again";
    EXPECT_TRUE(gate.accept(TargetStatus::kOk));
  }
}

TEST(TargetPolar, ADegradedEstimateSaysWhichWayItIsUncertain) {
  // Ahead at 6 m, sigma 0.05 m along the line of sight and 0.7 m across it (a range-only
  // robot far away), the frame turned 30 deg so that the axes are not the lines'.
  const double a = 30.0 * M_PI / 180.0;
  Eigen::Matrix2d rotation;
  rotation << std::cos(a), -std::sin(a), std::sin(a), std::cos(a);
  const Eigen::Vector2d position = rotation * Eigen::Vector2d(6.0, 0.0);
  const Eigen::Matrix2d covariance =
      rotation * Eigen::Vector2d(0.05 * 0.05, 0.7 * 0.7).asDiagonal() * rotation.transpose();
  const PolarSpread spread = polarSpread(position, covariance);
  EXPECT_NEAR(spread.range_sigma, 0.05, 1e-9);
  EXPECT_NEAR(spread.bearing_sigma, std::atan2(0.7, 6.0), 1e-9);

  const control::TargetPolar t =
      targetPolar(TargetStatus::kDegraded, 6.0, a, spread, 1, std::nullopt, 1.0);
  EXPECT_TRUE(t.degraded);
  EXPECT_FALSE(t.mirror);
  EXPECT_EQ(t.range_sigma, spread.range_sigma);
  EXPECT_EQ(t.bearing_sigma, spread.bearing_sigma);
  EXPECT_TRUE(targetPolar(TargetStatus::kDegraded, 6.0, a, spread, 2, std::nullopt, 1.0).mirror);
}

TEST(TargetPolar, AnUnknownSpreadIsInfinite) {
  const double inf = std::numeric_limits<double>::infinity();
  for (const PolarSpread s :
       {polarSpread(Eigen::Vector2d::Zero(), Eigen::Matrix2d::Identity()),
        polarSpread(Eigen::Vector2d(1.0, 0.0), Eigen::Matrix2d::Constant(std::nan(""))),
        polarSpread(Eigen::Vector2d(inf, 0.0), Eigen::Matrix2d::Identity())}) {
    EXPECT_EQ(s.range_sigma, inf);
    EXPECT_EQ(s.bearing_sigma, inf);
  }
}

}  // namespace
}  // namespace control
}  // namespace radio_follow
