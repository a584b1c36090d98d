// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <vector>

#include "radio_follow/config/layout.hpp"

namespace radio_follow {
namespace models {

/// Measured error of one UWB TWR range at a true distance (thesis Table 3.1).
struct RangeError {
  double bias = 0.0;   ///< mean(measured) - true, metres (negative: the modules read short)
  double sigma = 0.0;  ///< standard deviation, metres
};

/// Bias and sigma of DWM1001 two-way ranging, interpolated linearly in distance over
/// Table 3.1 (1-12 m) and held constant outside it.
RangeError uwbRangeError(double distance);

/// Measured behaviour of one AoA board at a true azimuth and distance.
struct AoaError {
  double azimuth_bias = 0.0;   ///< mean(measured) - true azimuth, radians
  double azimuth_sigma = 0.0;  ///< radians
  double rssi_mean = 0.0;      ///< dBm
  double rssi_sigma = 0.0;     ///< dB
};

/// The board's measured azimuth error and RSSI (thesis Tables 3.2-3.4 for XPLR-AOA-1,
/// 3.5-3.7 for ANT-B10), bilinearly interpolated over true azimuth (clamped to the
/// measured +-80 deg) and distance (1, 2, 4 m; clamped below 1 m). Beyond 4 m the
/// 4 m angle errors are held and the RSSI falls with a log-distance law (exponent 2).
/// `azimuth` is the device's convention as tabulated (radians); the tables are
/// interpreted as errors relative to the true angle, so sign conventions cancel.
AoaError aoaError(AoaBoardKind kind, double azimuth, double distance);

/// The table's azimuth grid limit, radians (80 deg).
double aoaTableAzimuthLimit();

}  // namespace models
}  // namespace radio_follow
