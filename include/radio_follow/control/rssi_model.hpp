// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <vector>

namespace radio_follow {
namespace control {

/// Log-distance path-loss model rssi(d) = rssi_at_1m - 10 n log10(d) (seed 002 eq 1,
/// seed 000 Figure 2): turns a BLE RSSI into a rough distance.
struct RssiModel {
  double rssi_at_1m = -55.0;  ///< dBm
  double exponent = 2.0;      ///< path-loss exponent n (2 in free space)

  /// Distance in metres for `rssi` (dBm).
  double distance(double rssi) const;
  void validate() const;
};

/// One calibration sample.
struct RssiSample {
  double distance = 0.0;  ///< m, > 0
  double rssi = 0.0;      ///< dBm
};

/// Least-squares fit result with its residual spread.
struct RssiFit {
  RssiModel model;
  double rms_residual_db = 0.0;
  std::size_t samples = 0;
};

/// Fits the model by linear least squares in log10(d). Throws std::invalid_argument
/// with fewer than two distinct positive distances.
RssiFit fitRssiModel(const std::vector<RssiSample>& samples);

}  // namespace control
}  // namespace radio_follow
