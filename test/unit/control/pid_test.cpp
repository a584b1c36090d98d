// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/control/pid.hpp"

#include <gtest/gtest.h>

#include "radio_follow/common/param_error.hpp"

namespace radio_follow {
namespace control {
namespace {

PidGains gains(double kp, double ki, double kd) {
  PidGains g;
  g.kp = kp;
  g.ki = ki;
  g.kd = kd;
  g.integral_limit = 10.0;
  g.derivative_time_constant = 0.0;
  g.output_limit = 100.0;
  return g;
}

TEST(Pid, ProportionalOnly) {
  Pid pid(gains(2.0, 0.0, 0.0));
  EXPECT_DOUBLE_EQ(pid.update(1.5, 0.1), 3.0);
  EXPECT_DOUBLE_EQ(pid.update(-0.5, 0.1), -1.0);
}

TEST(Pid, IntegralAccumulatesErrorTimesDt) {
  Pid pid(gains(0.0, 1.0, 0.0));
  pid.update(1.0, 0.5);
  EXPECT_DOUBLE_EQ(pid.update(1.0, 0.5), 1.0);
}

TEST(Pid, UnfilteredDerivativeIsErrorSlope) {
  Pid pid(gains(0.0, 0.0, 1.0));
  EXPECT_DOUBLE_EQ(pid.update(0.0, 0.1), 0.0);  // no history: no derivative kick
  EXPECT_NEAR(pid.update(0.2, 0.1), 2.0, 1e-12);
}

TEST(Pid, FilteredDerivativeIsSmallerThanRawSlope) {
  PidGains g = gains(0.0, 0.0, 1.0);
  g.derivative_time_constant = 0.1;
  Pid pid(g);
  pid.update(0.0, 0.1);
  const double first = pid.update(0.2, 0.1);
  EXPECT_NEAR(first, 1.0, 1e-12);          // alpha = dt / (tau + dt) = 0.5
  EXPECT_GT(pid.update(0.4, 0.1), first);  // converges towards the raw slope 2
}

TEST(Pid, IntegralClampedByLimit) {
  PidGains g = gains(0.0, 1.0, 0.0);
  g.integral_limit = 0.3;
  Pid pid(g);
  double out = 0.0;
  for (int i = 0; i < 100; ++i) {
    out = pid.update(1.0, 0.1);
  }
  EXPECT_NEAR(out, 0.3, 1e-12);
}

TEST(Pid, NoWindupWhileSaturated) {
  PidGains g = gains(1.0, 1.0, 0.0);
  g.output_limit = 1.0;
  Pid pid(g);
  for (int i = 0; i < 200; ++i) {
    EXPECT_LE(pid.update(5.0, 0.1), 1.0);
  }
  // The integral did not grow while the output was pinned at the limit, so a sign change
  // of the error reverses the output at once.
  EXPECT_LT(pid.integral(), 0.5);
  EXPECT_LT(pid.update(-1.0, 0.1), 0.0);
}

TEST(Pid, ResetForgetsHistory) {
  Pid pid(gains(0.0, 1.0, 1.0));
  pid.update(1.0, 0.1);
  pid.update(2.0, 0.1);
  pid.reset();
  EXPECT_DOUBLE_EQ(pid.integral(), 0.0);
  EXPECT_NEAR(pid.update(1.0, 0.1), 0.1, 1e-12);  // no derivative kick from stale history
}

TEST(Pid, NonPositiveDtChangesNothing) {
  Pid pid(gains(1.0, 1.0, 0.0));
  EXPECT_DOUBLE_EQ(pid.update(2.0, 0.0), 2.0);
  EXPECT_DOUBLE_EQ(pid.integral(), 0.0);
}

TEST(PidGains, ValidateRejectsNegativeGainAndZeroLimit) {
  PidGains g;
  g.kp = -1.0;
  EXPECT_THROW(g.validate("~linear_pid"), ParamError);
  g = PidGains();
  g.output_limit = 0.0;
  EXPECT_THROW(g.validate("~linear_pid"), ParamError);
  EXPECT_NO_THROW(PidGains().validate("~linear_pid"));
}

TEST(Pid, NewGainsKeepTheIntegralContributionWithoutAKick) {
  PidGains gains;
  gains.kp = 0.0;
  gains.ki = 0.5;
  gains.kd = 0.0;
  gains.integral_limit = 1.0;
  Pid pid(gains);
  for (int i = 0; i < 20; ++i) {
    pid.update(1.0, 0.05);  // integral 1.0, contribution 0.5
  }
  const double before = pid.update(0.0, 0.05);
  gains.ki = 1.0;
  pid.setGains(gains);
  EXPECT_NEAR(pid.update(0.0, 0.05), before, 1e-12);  // same output after the change
  gains.integral_limit = 0.2;
  pid.setGains(gains);
  EXPECT_NEAR(pid.update(0.0, 0.05), 0.2, 1e-12);  // clamped to the new limit
  gains.ki = 0.0;
  pid.setGains(gains);
  EXPECT_NEAR(pid.update(0.0, 0.05), 0.0, 1e-12);
}

}  // namespace
}  // namespace control
}  // namespace radio_follow
