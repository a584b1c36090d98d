// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/estimation/calibration_fit.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>

namespace radio_follow {
namespace estimation {
namespace {

std::vector<RangeSample> readings(double bias, double slope, double sigma, double outlier_share,
                                  unsigned seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> noise(0.0, sigma);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<RangeSample> samples;
  for (double truth = 1.0; truth <= 8.0; truth += 1.0) {
    for (int k = 0; k < 100; ++k) {
      double raw = truth * (1.0 + slope) + bias + noise(rng);
      if (unit(rng) < outlier_share) {
        raw += 0.5 + 2.0 * unit(rng);  // a reflection: always long
      }
      samples.push_back({raw, truth});
    }
  }
  return samples;
}

TEST(FitRangeCalibration, RecoversBiasAndScale) {
  const RangeCalibrationFit fit = fitRangeCalibration(readings(0.2, 0.015, 0.06, 0.0, 1));
  ASSERT_EQ(fit.coefficients.size(), 2u);
  // corrected = (raw - bias) / (1 + slope)
  EXPECT_NEAR(fit.coefficients[1], 1.0 / 1.015, 0.005);
  EXPECT_NEAR(fit.coefficients[0], -0.2 / 1.015, 0.02);
  EXPECT_GT(fit.rms_before, 0.2);
  EXPECT_LT(fit.rms_after, 0.07);
}

TEST(FitRangeCalibration, LongOutliersAreRefusedNotFitted) {
  const RangeCalibrationFit fit = fitRangeCalibration(readings(0.2, 0.015, 0.06, 0.05, 2));
  EXPECT_NEAR(fit.coefficients[1], 1.0 / 1.015, 0.006);
  EXPECT_NEAR(fit.coefficients[0], -0.2 / 1.015, 0.03);
  EXPECT_GE(fit.rejected, 30u);  // ~40 outliers of 800, all at least 0.5 m long
  EXPECT_LT(fit.rms_after, 0.07);
}

TEST(FitRangeCalibration, RefusesWhatCannotDetermineIt) {
  std::vector<RangeSample> one_distance(50, RangeSample{3.2, 3.0});
  EXPECT_THROW(fitRangeCalibration(one_distance, 1), std::invalid_argument);
  EXPECT_NO_THROW(fitRangeCalibration(one_distance, 0));
  EXPECT_THROW(fitRangeCalibration(std::vector<RangeSample>(3, RangeSample{1, 1}), 0),
               std::invalid_argument);
  auto samples = readings(0.1, 0.0, 0.05, 0.0, 3);
  samples[4].raw = std::nan("");
  EXPECT_THROW(fitRangeCalibration(samples), std::invalid_argument);
  EXPECT_THROW(fitRangeCalibration(readings(0.1, 0.0, 0.05, 0.0, 3), 7), std::invalid_argument);
}

TEST(FitYawOffset, RecoversTheMountingErrorAcrossTheWrap) {
  std::mt19937_64 rng(4);
  std::normal_distribution<double> noise(0.0, 0.05);
  std::vector<AzimuthSample> samples;
  const double offset = 0.12;
  for (int k = 0; k < 200; ++k) {
    const double truth = 3.1 - 0.01 * k;  // crosses pi once measured
    samples.push_back({std::remainder(truth - offset + noise(rng), 2.0 * M_PI), truth});
  }
  samples.push_back({0.0, 2.0});  // a reflection
  const YawOffsetFit fit = fitYawOffset(samples);
  EXPECT_NEAR(fit.yaw_offset, offset, 0.01);
  EXPECT_EQ(fit.rejected, 1u);
  EXPECT_NEAR(fit.residual_sigma, 0.05, 0.01);
  // Before the correction the offset adds to the noise: sqrt(0.12^2 + 0.05^2) = 0.13.
  EXPECT_NEAR(fit.rms_before, 0.13, 0.01);
  EXPECT_THROW(fitYawOffset(std::vector<AzimuthSample>(4)), std::invalid_argument);
}

}  // namespace
}  // namespace estimation
}  // namespace radio_follow
