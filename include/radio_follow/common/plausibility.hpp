// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cmath>

namespace radio_follow {

/// Physical limits of what the radio devices can report. A decoded value outside them is
/// not a measurement but a corrupted or misbehaving device (the parsers accept any finite
/// decimal, so a module writing 1e154 as 155 plain digits parses). The decoders reject
/// such lines/packets whole with their own "implausible" status, which the drivers count
/// as rejected; nothing of them reaches the locator, whose solver a single absurd value
/// would otherwise throw off (issue 12). The bounds are generous: they must never cut a
/// real reading, only the impossible ones.

/// Longest UWB range, m. The DW1000 reaches "up to 290 m @ 110 kbps" (DW1000 datasheet,
/// key features); the DWM1001 module, with its fixed 6.8 Mb/s configuration, is specified
/// for about 60 m. Any range a TWR module or a TDoA difference could carry is below this.
constexpr double kMaxUwbRange = 300.0;

/// Largest anchor or tag coordinate magnitude, m, per axis. A UWB network spans at most a
/// few ranges; 10 km also covers a network frame with a far-off origin (the DWM1001 stores
/// positions as int32 millimetres, so the format itself would allow 2147 km).
constexpr double kMaxCoordinate = 10000.0;

/// Smallest RSSI, dBm: the Bluetooth HCI lower bound (Core spec, LE Advertising Report:
/// -127 <= RSSI <= +20; -128 and 127 mean "not available").
constexpr double kMinRssi = -127.0;
/// Largest RSSI, dBm. The u-connectLocate manual gives the +UUDF RSSI fields as integers
/// ("RSSI of polarization 1/2", dBm) without a range; the reported values are negative,
/// and the receiver of the board's NINA-B4 (an nRF52833) is specified up to 0 dBm input
/// (PRX,MAX). The TDoA quality TLV's powers (DW1000 receive-level estimates, negative
/// dBm) are held to the same bounds.
constexpr double kMaxRssi = 0.0;

/// Largest angle-of-arrival magnitude, deg, azimuth and elevation alike: "in range -90 to
/// 90" (u-blox XPLR-AOA user guide, +UUDF defined values). The array cannot tell front from
/// back, so it never reports more.
constexpr double kMaxAoaAngleDeg = 90.0;

/// The DWM1001's position quality factor is a percentage (DWM1001 Firmware API Guide).
constexpr int kMinQuality = 0;
constexpr int kMaxQuality = 100;

/// Largest TDoA distance difference magnitude, m: |p - a| - |p - b| <= |a - b|, and two
/// anchors hear the same blink only within UWB range of it (kMaxUwbRange).
constexpr double kMaxDistanceDifference = kMaxUwbRange;

/// A range a module may report: finite and in [0, kMaxUwbRange].
inline bool plausibleRange(double range) {
  return std::isfinite(range) && range >= 0.0 && range <= kMaxUwbRange;
}

/// An anchor or tag coordinate: finite and |c| <= kMaxCoordinate.
inline bool plausibleCoordinate(double c) {
  return std::isfinite(c) && std::abs(c) <= kMaxCoordinate;
}

/// Largest odometry coordinate magnitude, m, per axis: a ground robot's odometry frame
/// starts where it was switched on; 1000 km is more than any mission drives, and keeps
/// squared distances far from overflow (a pose of 1.8e308 m made homing's goal inf).
constexpr double kMaxOdometryCoordinate = 1e6;

/// An odometry position coordinate: finite and |c| <= kMaxOdometryCoordinate.
inline bool plausibleOdometryCoordinate(double c) {
  return std::isfinite(c) && std::abs(c) <= kMaxOdometryCoordinate;
}

/// Largest ground speed of a followed person, m/s: a sprinter's; a tracked velocity
/// beyond it is no person's.
constexpr double kMaxTargetSpeed = 12.0;

/// A target's ground speed, m/s: finite, >= 0 and <= kMaxTargetSpeed.
inline bool plausibleTargetSpeed(double speed) {
  return std::isfinite(speed) && speed >= 0.0 && speed <= kMaxTargetSpeed;
}

/// A received signal strength, dBm: finite and in [kMinRssi, kMaxRssi].
inline bool plausibleRssi(double dbm) {
  return std::isfinite(dbm) && dbm >= kMinRssi && dbm <= kMaxRssi;
}

/// An azimuth or elevation as the AoA board reports it, degrees.
inline bool plausibleAoaAngleDeg(double degrees) {
  return std::isfinite(degrees) && std::abs(degrees) <= kMaxAoaAngleDeg;
}

/// An angle in radians that a direction can be given as: finite and within half a turn
/// either way. A board reports at most kMaxAoaAngleDeg; a bearing beyond pi (or NaN)
/// is no direction at all.
inline bool plausibleAngleRad(double radians) {
  return std::abs(radians) <= M_PI;  // false for NaN
}

/// A position quality factor.
inline bool plausibleQuality(long quality) {
  return quality >= kMinQuality && quality <= kMaxQuality;
}

/// A TDoA distance difference, m.
inline bool plausibleDistanceDifference(double d) {
  return std::isfinite(d) && std::abs(d) <= kMaxDistanceDifference;
}

/// A measurement variance: finite and positive (zero would claim a perfect measurement).
inline bool plausibleVariance(double variance) {
  return std::isfinite(variance) && variance > 0.0;
}

}  // namespace radio_follow
