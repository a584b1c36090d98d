// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/control/rssi_model.hpp"

#include <cmath>
#include <stdexcept>

#include "radio_follow/common/param_error.hpp"

namespace radio_follow {
namespace control {

double RssiModel::distance(double rssi) const {
  return std::pow(10.0, (rssi_at_1m - rssi) / (10.0 * exponent));
}

void RssiModel::validate() const {
  require(std::isfinite(rssi_at_1m), "~rssi_at_1m", rssi_at_1m, "a finite RSSI in dBm");
  require(std::isfinite(exponent) && exponent > 0.0, "~rssi_exponent", exponent,
          "a path-loss exponent > 0");
}

RssiFit fitRssiModel(const std::vector<RssiSample>& samples) {
  // rssi = a + b * x with x = log10(d); a = rssi_at_1m, b = -10 n.
  double sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0;
  std::size_t n = 0;
  for (const auto& s : samples) {
    if (!(s.distance > 0.0) || !std::isfinite(s.rssi) || !std::isfinite(s.distance)) {
      throw std::invalid_argument("calibration sample with distance <= 0 or non-finite value");
    }
    const double x = std::log10(s.distance);
    sx += x;
    sy += s.rssi;
    sxx += x * x;
    sxy += x * s.rssi;
    ++n;
  }
  const double denom = static_cast<double>(n) * sxx - sx * sx;
  if (n < 2 || !(std::abs(denom) > 1e-12)) {
    throw std::invalid_argument("need samples at two or more distinct distances");
  }
  const double b = (static_cast<double>(n) * sxy - sx * sy) / denom;
  const double a = (sy - b * sx) / static_cast<double>(n);
  RssiFit fit;
  fit.model.rssi_at_1m = a;
  fit.model.exponent = -b / 10.0;
  fit.samples = n;
  double sum_sq = 0.0;
  for (const auto& s : samples) {
    const double r = s.rssi - (a + b * std::log10(s.distance));
    sum_sq += r * r;
  }
  fit.rms_residual_db = std::sqrt(sum_sq / static_cast<double>(n));
  return fit;
}

}  // namespace control
}  // namespace radio_follow
