// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/sim/rssi_channel.hpp"

#include <cmath>
#include <random>

#include "radio_follow/models/sensor_tables.hpp"

namespace radio_follow {
namespace sim {

RssiChannel::RssiChannel(AoaBoardKind kind, const RssiChannelFigures& figures)
    : kind_(kind), figures_(figures), shadow_(1.0, figures.shadow_tau) {}

double RssiChannel::mean(double distance, double azimuth) const {
  return models::aoaError(kind_, azimuth, distance).rssi_mean;
}

std::optional<double> RssiChannel::sample(double distance, double azimuth, double t, Rng& rng) {
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  // The shadowing and the fade run whether or not this reading arrives: a lost
  // advertisement does not pause the person's body.
  const double shadow = shadow_.sample(t, rng);
  if (fade_left_ > 0) {
    --fade_left_;
  } else if (uniform(rng) < figures_.fade_start) {
    fade_left_ = 1;
    while (uniform(rng) < figures_.fade_continue) {
      ++fade_left_;
    }
    fade_depth_ = figures_.fade_min +
                  std::exponential_distribution<double>(1.0 / figures_.fade_mean_excess)(rng);
    --fade_left_;
  } else {
    fade_depth_ = 0.0;
  }
  const double fast = std::normal_distribution<double>(0.0, 1.0)(rng);
  if (uniform(rng) < figures_.dropout) {
    return std::nullopt;
  }
  const models::AoaError table = models::aoaError(kind_, azimuth, distance);
  const double share = figures_.shadow_share;
  return table.rssi_mean +
         table.rssi_sigma * (std::sqrt(share) * shadow + std::sqrt(1.0 - share) * fast) -
         fade_depth_;
}

}  // namespace sim
}  // namespace radio_follow
