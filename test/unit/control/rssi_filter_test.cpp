// SPDX-License-Identifier: BSD-3-Clause
// The RSSI smoothers of seed 002 (control/rssi_filter.hpp): step responses, the median's
// outlier rejection, the Kalman gain against its closed form, windows at their edges,
// non-finite readings refused, parameters validated by name.
#include "radio_follow/control/rssi_filter.hpp"

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <limits>
#include <string>

#include "radio_follow/common/param_error.hpp"
#include "radio_follow/common/yaml_params.hpp"

namespace radio_follow {
namespace control {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

RssiWindowParams windowOf(int n) {
  RssiWindowParams p;
  p.window = n;
  return p;
}

TEST(MovingMean, StepRisesLinearlyOverTheWindow) {
  MovingMean mean(windowOf(4));
  for (int i = 0; i < 4; ++i) {
    EXPECT_DOUBLE_EQ(*mean.update(-70.0), -70.0);
  }
  // -70 -> -50: each new reading replaces one old one, a quarter of the step each time.
  EXPECT_DOUBLE_EQ(*mean.update(-50.0), -65.0);
  EXPECT_DOUBLE_EQ(*mean.update(-50.0), -60.0);
  EXPECT_DOUBLE_EQ(*mean.update(-50.0), -55.0);
  EXPECT_DOUBLE_EQ(*mean.update(-50.0), -50.0);
}

TEST(MovingMean, AveragesWhatItHasBeforeTheWindowFills) {
  MovingMean mean(windowOf(10));
  EXPECT_DOUBLE_EQ(*mean.update(-60.0), -60.0);
  EXPECT_DOUBLE_EQ(*mean.update(-50.0), -55.0);
  mean.reset();
  EXPECT_DOUBLE_EQ(*mean.update(-40.0), -40.0);
}

TEST(MovingMedian, StepMovesAfterHalfTheWindow) {
  MovingMedian median(windowOf(5));
  for (int i = 0; i < 5; ++i) {
    median.update(-70.0);
  }
  EXPECT_DOUBLE_EQ(*median.update(-50.0), -70.0);
  EXPECT_DOUBLE_EQ(*median.update(-50.0), -70.0);
  EXPECT_DOUBLE_EQ(*median.update(-50.0), -50.0);  // 3 of 5 new: the whole step at once
}

TEST(MovingMedian, IgnoresAFadeShorterThanHalfTheWindowWhereTheMeanDoesNot) {
  MovingMedian median(windowOf(7));
  MovingMean mean(windowOf(7));
  const double readings[] = {-60, -61, -59, -60, -85, -88, -86, -60, -61, -59};
  double worst_median = 0.0;
  double worst_mean = 0.0;
  for (int i = 0; i < 10; ++i) {
    const double m = *median.update(readings[i]);
    const double a = *mean.update(readings[i]);
    if (i >= 4) {
      worst_median = std::max(worst_median, std::abs(m + 60.0));
      worst_mean = std::max(worst_mean, std::abs(a + 60.0));
    }
  }
  EXPECT_LE(worst_median, 1.0);  // three faded readings of seven: never the median
  EXPECT_GT(worst_mean, 10.0);
}

TEST(MovingMedian, EvenCountTakesTheMiddlePairsMean) {
  MovingMedian median(windowOf(4));
  median.update(-60.0);
  EXPECT_DOUBLE_EQ(*median.update(-50.0), -55.0);
  median.update(-40.0);
  EXPECT_DOUBLE_EQ(*median.update(-90.0), -55.0);  // {-90, -60, -50, -40}
}

TEST(RssiWindow, WindowOfOnePassesReadingsThrough) {
  MovingMean mean(windowOf(1));
  MovingMedian median(windowOf(1));
  for (const double r : {-60.0, -80.0, -45.0}) {
    EXPECT_DOUBLE_EQ(*mean.update(r), r);
    EXPECT_DOUBLE_EQ(*median.update(r), r);
  }
}

TEST(RssiWindow, WindowBelowOneIsRefusedByName) {
  try {
    MovingMean mean(windowOf(0));
    FAIL() << "window 0 accepted";
  } catch (const ParamError& e) {
    EXPECT_EQ(e.name(), "~rssi_filter/window");
    EXPECT_NE(std::string(e.what()).find("= 0"), std::string::npos) << e.what();
  }
  EXPECT_THROW(MovingMedian(windowOf(-3)), ParamError);
}

TEST(RssiKalman, GainConvergesToTheClosedForm) {
  RssiKalmanParams p;
  p.process_noise = 0.2;
  p.measurement_noise = 16.0;
  RssiKalman kalman(p);
  for (int i = 0; i < 500; ++i) {
    kalman.update(-60.0 + (i % 2 == 0 ? 3.0 : -3.0));
  }
  // Q = 0.2, R = 16: P = (0.2 + sqrt(0.04 + 12.8)) / 2 = 1.8916..., K = P / (P + R).
  const double prior = 0.5 * (0.2 + std::sqrt(0.04 + 4.0 * 0.2 * 16.0));
  EXPECT_NEAR(p.steadyStateGain(), prior / (prior + 16.0), 1e-15);
  EXPECT_NEAR(kalman.gain(), p.steadyStateGain(), 1e-9);
  EXPECT_NEAR(kalman.variance(), (1.0 - kalman.gain()) * prior, 1e-9);
}

TEST(RssiKalman, StepResponseIsGeometricWithTheSteadyGain) {
  RssiKalmanParams p;
  p.process_noise = 1.0;
  p.measurement_noise = 4.0;
  RssiKalman kalman(p);
  for (int i = 0; i < 200; ++i) {
    kalman.update(-70.0);
  }
  const double k = p.steadyStateGain();
  double expected = -70.0;
  for (int i = 0; i < 5; ++i) {
    expected += k * (-50.0 - expected);
    EXPECT_NEAR(*kalman.update(-50.0), expected, 1e-9);
  }
  // K = 0.39: 90 % of the step after five readings, where a mean of 10 needs nine.
  EXPECT_GT(expected, -52.0);
}

TEST(RssiKalman, StartsAtTheFirstReading) {
  RssiKalman kalman(RssiKalmanParams{});
  EXPECT_DOUBLE_EQ(*kalman.update(-66.0), -66.0);
  EXPECT_DOUBLE_EQ(kalman.variance(), RssiKalmanParams{}.measurement_noise);
  kalman.reset();
  EXPECT_DOUBLE_EQ(*kalman.update(-40.0), -40.0);
}

TEST(RssiKalman, NonPositiveNoiseIsRefusedByName) {
  RssiKalmanParams p;
  p.process_noise = 0.0;
  try {
    RssiKalman kalman(p);
    FAIL() << "process_noise 0 accepted";
  } catch (const ParamError& e) {
    EXPECT_EQ(e.name(), "~rssi_filter/process_noise");
  }
  p = RssiKalmanParams{};
  p.measurement_noise = kNaN;
  EXPECT_THROW(RssiKalman{p}, ParamError);
}

TEST(RssiFilter, EveryTypeRefusesNonFiniteReadingsAndKeepsItsState) {
  for (const auto type : {RssiFilterParams::Type::kNone, RssiFilterParams::Type::kMean,
                          RssiFilterParams::Type::kMedian, RssiFilterParams::Type::kKalman}) {
    RssiFilterParams p;
    p.type = type;
    RssiFilter filter(p);
    ASSERT_TRUE(filter.update(-60.0));
    EXPECT_FALSE(filter.update(kNaN));
    EXPECT_FALSE(filter.update(std::numeric_limits<double>::infinity()));
    EXPECT_EQ(filter.refused(), 2u);
    EXPECT_DOUBLE_EQ(*filter.update(-60.0), -60.0);  // the NaN did not enter the state
  }
}

TEST(RssiFilter, LoadsItsTableAndRefusesAnUnknownType) {
  RssiFilterParams p;
  RssiFilterParams::table().load(
      YamlParams(YAML::Load("{type: kalman, window: 7, process_noise: 0.5, measurement_noise: 9}")),
      p);
  EXPECT_EQ(p.type, RssiFilterParams::Type::kKalman);
  EXPECT_EQ(p.window.window, 7);
  EXPECT_DOUBLE_EQ(p.kalman.process_noise, 0.5);
  EXPECT_DOUBLE_EQ(p.kalman.measurement_noise, 9.0);
  try {
    RssiFilterParams::table().load(YamlParams(YAML::Load("{type: kalmann}")), p);
    FAIL() << "type kalmann accepted";
  } catch (const ParamError& e) {
    EXPECT_EQ(e.name(), "~type");
    EXPECT_NE(std::string(e.what()).find("none or mean or median or kalman"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace control
}  // namespace radio_follow
