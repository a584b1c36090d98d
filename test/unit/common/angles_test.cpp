// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/common/angles.hpp"

#include <gtest/gtest.h>

#include <random>

namespace radio_follow {
namespace {

TEST(Angles, WrapKeepsInRangeValues) {
  EXPECT_DOUBLE_EQ(wrapAngleFast(0.5), 0.5);
  EXPECT_DOUBLE_EQ(wrapAngleFast(kPi), kPi);
  EXPECT_DOUBLE_EQ(wrapAngleFast(-kPi), kPi);
}

TEST(Angles, FastWrapAgreesWithAtan2WrapOverManyTurns) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> angle(-50.0, 50.0);
  for (int i = 0; i < 10000; ++i) {
    const double a = angle(rng);
    const double fast = wrapAngleFast(a);
    EXPECT_GT(fast, -kPi);
    EXPECT_LE(fast, kPi);
    // Same direction: compare on the circle, not as numbers (pi vs -pi).
    EXPECT_NEAR(std::cos(fast), std::cos(wrapAngle(a)), 1e-9);
    EXPECT_NEAR(std::sin(fast), std::sin(wrapAngle(a)), 1e-9);
  }
}

TEST(Angles, DegreeConversionRoundTrips) {
  EXPECT_DOUBLE_EQ(deg2rad(180.0), kPi);
  EXPECT_DOUBLE_EQ(rad2deg(deg2rad(37.5)), 37.5);
}

}  // namespace
}  // namespace radio_follow
