// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <optional>

#include "radio_follow/config/layout.hpp"
#include "radio_follow/sim/sensor_profile.hpp"

namespace radio_follow {
namespace sim {

/// How one board's RSSI stream errs over time, on top of the measured tables.
/// The tables (models::aoaError: thesis Tables 3.2-3.7) give the mean and the spread of
/// single readings at a distance and azimuth; they say nothing of how the error evolves.
/// These figures split that spread into slow shadowing and fast fading and add what a
/// static measurement does not show: a person's body or a passing reflector fading the
/// signal for a second, and lost advertisements. They are assumptions, not measurements
/// (doc/rssi_filters.md, "The simulated RSSI").
struct RssiChannelFigures {
  double rate = 10.0;          ///< readings per second (seed 002: a 100 ms period)
  double shadow_share = 0.5;   ///< share of the table's variance that is slow shadowing
  double shadow_tau = 2.0;     ///< s, time constant of the shadowing (Gauss-Markov)
  double fade_start = 0.01;    ///< chance per reading that a fade starts
  double fade_continue = 0.8;  ///< chance a fade lasts one more reading (mean 5)
  double fade_min = 4.0;       ///< dB, the shallowest fade
  double fade_mean_excess = 6.0;  ///< dB, mean depth beyond fade_min (exponential)
  double dropout = 0.1;           ///< chance a reading is lost
};

/// One board's RSSI readings of one tag: the table's mean at the true distance and
/// azimuth, plus shadowing (time-correlated), fast fading (white), fades (bursts of
/// several readings, several dB weaker) and dropouts. The table's per-reading sigma is
/// the total of shadowing and fast fading, so a single reading spreads as measured.
class RssiChannel {
 public:
  explicit RssiChannel(AoaBoardKind kind, const RssiChannelFigures& figures = {});

  /// The reading at time `t` (s) of a tag `distance` (m) away at `azimuth` (rad, the
  /// tables' device convention), or nothing (dropout). Readings come in time order.
  std::optional<double> sample(double distance, double azimuth, double t, Rng& rng);
  /// The noise-free reading: the tables' mean, dBm.
  double mean(double distance, double azimuth) const;
  const RssiChannelFigures& figures() const { return figures_; }

 private:
  AoaBoardKind kind_;
  RssiChannelFigures figures_;
  GaussMarkov shadow_;  ///< unit sigma; scaled by the table's sigma at each reading
  int fade_left_ = 0;
  double fade_depth_ = 0.0;
};

}  // namespace sim
}  // namespace radio_follow
