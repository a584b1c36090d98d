// SPDX-License-Identifier: BSD-3-Clause
// The simulated RSSI stream (sim/rssi_channel.hpp) keeps the measured tables' mean and
// per-reading spread, is correlated in time, fades and drops readings as its figures say.
#include "radio_follow/sim/rssi_channel.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "radio_follow/models/sensor_tables.hpp"

namespace radio_follow {
namespace sim {
namespace {

struct ChannelStats {
  double mean = 0.0;
  double sigma = 0.0;
  double lag1 = 0.0;  ///< autocorrelation of consecutive readings
};

ChannelStats channelStats(const std::vector<double>& v) {
  ChannelStats s;
  for (double x : v) {
    s.mean += x;
  }
  s.mean /= static_cast<double>(v.size());
  double var = 0.0;
  double cov = 0.0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    var += (v[i] - s.mean) * (v[i] - s.mean);
    if (i + 1 < v.size()) {
      cov += (v[i] - s.mean) * (v[i + 1] - s.mean);
    }
  }
  s.sigma = std::sqrt(var / static_cast<double>(v.size()));
  s.lag1 = cov / var;
  return s;
}

std::vector<double> run(RssiChannel& channel, double distance, int n, Rng& rng, int* lost) {
  std::vector<double> out;
  for (int i = 0; i < n; ++i) {
    const auto r = channel.sample(distance, 0.0, i / channel.figures().rate, rng);
    if (r) {
      out.push_back(*r);
    } else if (lost) {
      ++*lost;
    }
  }
  return out;
}

TEST(RssiChannel, WithoutFadesKeepsTheTablesMeanAndSpreadAndIsCorrelated) {
  RssiChannelFigures f;
  f.fade_start = 0.0;
  f.dropout = 0.0;
  RssiChannel channel(AoaBoardKind::kXplrAoa1, f);
  Rng rng(3);
  const ChannelStats s = channelStats(run(channel, 2.0, 200000, rng, nullptr));
  const models::AoaError table = models::aoaError(AoaBoardKind::kXplrAoa1, 0.0, 2.0);
  // The shadowing's 2 s correlation leaves some 5000 independent readings: SE 0.05 dB.
  EXPECT_NEAR(s.mean, table.rssi_mean, 0.25);
  EXPECT_NEAR(s.sigma, table.rssi_sigma, 0.1);
  // Half the variance decays with a = exp(-0.1 / 2): lag-1 correlation 0.5 a = 0.48.
  EXPECT_NEAR(s.lag1, 0.5 * std::exp(-0.1 / f.shadow_tau), 0.02);
  EXPECT_DOUBLE_EQ(channel.mean(2.0, 0.0), table.rssi_mean);
}

TEST(RssiChannel, FadesPullTheMeanDownAndReadingsGetLost) {
  RssiChannelFigures f;  // defaults: 1 % fade starts, 5 readings, 10 dB mean depth
  RssiChannel channel(AoaBoardKind::kXplrAoa1, f);
  Rng rng(4);
  int lost = 0;
  const int n = 200000;
  const ChannelStats s = channelStats(run(channel, 2.0, n, rng, &lost));
  EXPECT_NEAR(static_cast<double>(lost) / n, f.dropout, 0.005);
  // Share of faded readings ~ 0.01 * 5 / (1 + 0.01 * 5) = 4.8 %, 10 dB deep on average.
  const double expected_drop = 0.048 * (f.fade_min + f.fade_mean_excess);
  const double table_mean = models::aoaError(AoaBoardKind::kXplrAoa1, 0.0, 2.0).rssi_mean;
  EXPECT_NEAR(table_mean - s.mean, expected_drop, 0.15);
}

TEST(RssiChannel, SameSeedSameReadings) {
  RssiChannel a(AoaBoardKind::kAntB10);
  RssiChannel b(AoaBoardKind::kAntB10);
  Rng ra(9);
  Rng rb(9);
  EXPECT_EQ(run(a, 3.0, 500, ra, nullptr), run(b, 3.0, 500, rb, nullptr));
}

}  // namespace
}  // namespace sim
}  // namespace radio_follow
