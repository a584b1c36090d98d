// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/control/rssi_model.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>

namespace radio_follow {
namespace control {
namespace {

TEST(RssiModel, DistanceInvertsModel) {
  RssiModel model;
  model.rssi_at_1m = -50.0;
  model.exponent = 2.0;
  EXPECT_NEAR(model.distance(-50.0), 1.0, 1e-12);
  EXPECT_NEAR(model.distance(-70.0), 10.0, 1e-9);
}

TEST(FitRssiModel, RecoversParametersFromNoisySamples) {
  std::mt19937 rng(5);
  std::normal_distribution<double> noise(0.0, 1.0);
  std::vector<RssiSample> samples;
  for (int rep = 0; rep < 20; ++rep) {
    for (double d : {0.5, 1.0, 2.0, 3.0, 5.0, 8.0}) {
      samples.push_back({d, -58.0 - 10.0 * 2.4 * std::log10(d) + noise(rng)});
    }
  }
  const RssiFit fit = fitRssiModel(samples);
  EXPECT_NEAR(fit.model.rssi_at_1m, -58.0, 0.5);
  EXPECT_NEAR(fit.model.exponent, 2.4, 0.1);
  EXPECT_NEAR(fit.rms_residual_db, 1.0, 0.2);
  EXPECT_EQ(fit.samples, samples.size());
}

TEST(FitRssiModel, RejectsDegenerateInput) {
  EXPECT_THROW(fitRssiModel({{1.0, -50.0}, {1.0, -52.0}}), std::invalid_argument);
  EXPECT_THROW(fitRssiModel({{0.0, -50.0}, {2.0, -52.0}}), std::invalid_argument);
}

}  // namespace
}  // namespace control
}  // namespace radio_follow
