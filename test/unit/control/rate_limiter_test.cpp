// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/control/rate_limiter.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "radio_follow/common/param_error.hpp"

namespace radio_follow {
namespace control {
namespace {

TEST(RateLimiter, RisesAtMostRiseTimesDt) {
  RateLimiter limiter(0.5, 1.0);
  EXPECT_NEAR(limiter.update(1.0, 0.1), 0.05, 1e-12);
  EXPECT_NEAR(limiter.update(1.0, 0.1), 0.10, 1e-12);
}

TEST(RateLimiter, FallsWithFallRate) {
  RateLimiter limiter(0.5, 1.0);
  limiter.reset(1.0);
  EXPECT_NEAR(limiter.update(0.0, 0.1), 0.9, 1e-12);
}

TEST(RateLimiter, SignChangeDeceleratesFirst) {
  RateLimiter limiter(0.5, 1.0);
  limiter.reset(0.05);
  EXPECT_NEAR(limiter.update(-1.0, 0.1), -0.05, 1e-12);  // fall rate across zero
}

TEST(RateLimiter, ReachesRequestExactly) {
  RateLimiter limiter(10.0, 10.0);
  EXPECT_DOUBLE_EQ(limiter.update(0.3, 0.1), 0.3);
}

TEST(RateLimiter, NonFiniteRequestMeansZero) {
  RateLimiter limiter(10.0, 10.0);
  limiter.reset(0.5);
  EXPECT_DOUBLE_EQ(limiter.update(std::numeric_limits<double>::quiet_NaN(), 1.0), 0.0);
}

TEST(CommandLimiter, SaturatesAndSmoothsBothAxes) {
  MotionLimits limits;
  limits.max_linear = 0.8;
  limits.max_angular = 0.5;
  limits.max_linear_accel = 100.0;
  limits.max_angular_accel = 100.0;
  CommandLimiter limiter(limits);
  const VelocityCommand out = limiter.update({5.0, -5.0}, 1.0);
  EXPECT_DOUBLE_EQ(out.linear, 0.8);
  EXPECT_DOUBLE_EQ(out.angular, -0.5);
}

TEST(CommandLimiter, AccelerationStaysWithinLimitOverManySteps) {
  MotionLimits limits;
  CommandLimiter limiter(limits);
  double previous = 0.0;
  for (int i = 0; i < 100; ++i) {
    const double v = limiter.update({5.0, 0.0}, 0.05).linear;
    EXPECT_LE(v - previous, limits.max_linear_accel * 0.05 + 1e-12);
    previous = v;
  }
  EXPECT_DOUBLE_EQ(previous, limits.max_linear);
}

TEST(CommandLimiter, NewLimitsApplyFromTheCurrentOutput) {
  CommandLimiter limiter{MotionLimits()};
  for (int i = 0; i < 40; ++i) {
    limiter.update({1.0, 0.0}, 0.1);  // accelerate to the 1 m/s default cap
  }
  MotionLimits slower;
  slower.max_linear = 0.5;
  slower.max_linear_decel = 2.0;
  limiter.setLimits(slower);
  // From 1.0 towards the new cap 0.5 at the new deceleration: 0.8 after 0.1 s, not a jump.
  EXPECT_NEAR(limiter.update({1.0, 0.0}, 0.1).linear, 0.8, 1e-12);
  EXPECT_NEAR(limiter.update({1.0, 0.0}, 0.2).linear, 0.5, 1e-12);
  MotionLimits invalid = slower;
  invalid.max_linear = -1.0;
  EXPECT_THROW(limiter.setLimits(invalid), ParamError);
  EXPECT_NEAR(limiter.update({1.0, 0.0}, 0.1).linear, 0.5, 1e-12);  // old limits kept
}

TEST(MotionLimits, ValidateRejectsZeroAcceleration) {
  MotionLimits limits;
  limits.max_linear_accel = 0.0;
  EXPECT_THROW(limits.validate(), ParamError);
  EXPECT_NO_THROW(MotionLimits().validate());
}

}  // namespace
}  // namespace control
}  // namespace radio_follow
