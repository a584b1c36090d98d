// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/models/sensor_tables.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

#include "radio_follow/common/angles.hpp"

namespace radio_follow {
namespace models {
namespace {

// Thesis Table 3.1: true distance, measured mean, standard deviation (metres).
constexpr std::array<std::array<double, 3>, 7> kUwbTable{{
    {1.0, 0.87, 0.025},
    {2.0, 1.92, 0.018},
    {4.0, 3.94, 0.018},
    {6.0, 5.89, 0.033},
    {8.0, 7.79, 0.019},
    {10.0, 9.74, 0.018},
    {12.0, 11.76, 0.033},
}};

/// One row of Tables 3.2-3.7: true azimuth (deg), measured mean (deg), sigma (deg),
/// RSSI mean (dBm), RSSI sigma (dB).
struct AoaRow {
  double azimuth;
  double mean;
  double sigma;
  double rssi_mean;
  double rssi_sigma;
};

/// The measurements of one board at one distance.
struct AoaDistanceTable {
  double distance;
  std::vector<AoaRow> rows;
};

const std::array<AoaDistanceTable, 3>& xplrTables() {
  static const std::array<AoaDistanceTable, 3> tables{{
      {1.0,
       {{-80, -64.16, 1.80, -51.90, 3.30},
        {-60, -55.65, 2.07, -48.83, 2.14},
        {-40, -40.09, 0.43, -45.31, 1.77},
        {-20, -18.69, 1.26, -48.25, 1.79},
        {0, 3.04, 1.94, -47.81, 2.29},
        {20, 21.04, 1.92, -47.37, 3.28},
        {40, 40.50, 2.21, -45.68, 3.62},
        {60, 60.80, 2.03, -46.81, 4.07},
        {80, 83.24, 6.73, -49.31, 4.64}}},
      {2.0,
       {{-80, -28.52, 4.24, -60.44, 8.91},
        {-60, -55.17, 4.36, -54.55, 6.72},
        {-40, -41.12, 2.14, -52.06, 5.27},
        {-20, -19.88, 3.51, -53.12, 5.06},
        {0, -0.10, 5.05, -54.33, 5.11},
        {20, 21.32, 2.29, -53.88, 5.41},
        {40, 35.48, 2.47, -53.76, 4.45},
        {60, 60.98, 7.25, -54.10, 5.24},
        {80, 66.22, 3.01, -57.20, 6.24}}},
      {4.0,
       {{-80, -6.27, 50.77, -56.96, 6.58},
        {-60, -47.78, 2.03, -54.88, 6.48},
        {-40, -39.02, 1.97, -54.58, 5.93},
        {-20, -20.93, 0.82, -55.55, 5.47},
        {0, -1.54, 2.07, -56.34, 4.90},
        {20, 20.43, 3.91, -56.89, 5.56},
        {40, 39.47, 3.27, -54.63, 5.91},
        {60, 53.82, 2.19, -55.01, 6.47},
        {80, 64.69, 4.19, -60.22, 8.56}}},
  }};
  return tables;
}

const std::array<AoaDistanceTable, 3>& antB10Tables() {
  static const std::array<AoaDistanceTable, 3> tables{{
      {1.0,
       {{-80, -48.34, 8.04, -66.22, 4.18},
        {-70, -52.92, 1.90, -67.08, 5.86},
        {-60, -44.66, 4.33, -67.14, 6.44},
        {-50, -40.82, 0.91, -66.35, 6.43},
        {-40, -34.63, 0.98, -63.71, 4.77},
        {-30, -28.52, 0.73, -61.90, 3.31},
        {-20, -20.95, 0.74, -60.36, 2.52},
        {-10, -11.90, 0.81, -58.82, 1.92},
        {0, -3.03, 0.62, -58.46, 1.79},
        {10, 7.15, 1.14, -59.18, 1.63},
        {20, 14.03, 1.28, -59.42, 1.79},
        {30, 24.33, 1.91, -59.66, 1.44},
        {40, 31.04, 2.09, -60.76, 1.93},
        {50, 41.09, 3.21, -62.76, 2.11},
        {60, 56.00, 2.33, -68.14, 5.14},
        {70, 55.92, 2.55, -65.45, 5.44},
        {80, 66.76, 3.64, -64.91, 3.24}}},
      {2.0,
       {{-80, -39.39, 1.35, -66.86, 5.95},
        {-70, -42.11, 1.96, -64.89, 4.16},
        {-60, -43.64, 1.86, -63.44, 4.79},
        {-50, -38.74, 1.40, -63.62, 5.62},
        {-40, -33.85, 1.17, -63.30, 5.26},
        {-30, -26.48, 0.84, -61.75, 4.01},
        {-20, -18.18, 0.91, -61.06, 3.72},
        {-10, -10.09, 0.61, -61.58, 3.99},
        {0, -1.98, 0.72, -62.15, 4.19},
        {10, 5.98, 1.12, -65.29, 4.47},
        {20, 14.67, 1.34, -64.72, 3.97},
        {30, 26.89, 2.14, -65.46, 4.37},
        {40, 37.53, 3.12, -65.43, 4.90},
        {50, 45.05, 3.77, -67.12, 5.26},
        {60, 52.97, 3.02, -67.57, 3.96},
        {70, 59.15, 4.60, -69.77, 4.15},
        {80, 54.44, 8.11, -69.53, 4.17}}},
      {4.0,
       {{-80, -23.81, 7.39, -68.85, 2.83},
        {-70, -28.18, 3.67, -68.93, 3.29},
        {-60, -36.01, 3.03, -69.66, 4.37},
        {-50, -31.29, 2.87, -70.06, 3.91},
        {-40, -28.69, 3.50, -69.77, 2.07},
        {-30, -23.57, 2.06, -69.30, 4.10},
        {-20, -18.77, 2.23, -69.26, 4.08},
        {-10, -13.06, 1.64, -69.59, 4.35},
        {0, -5.22, 1.68, -68.87, 4.50},
        {10, 3.43, 1.59, -69.86, 4.80},
        {20, 13.10, 2.00, -67.06, 1.69},
        {30, 19.92, 1.29, -67.25, 2.26},
        {40, 25.06, 1.72, -68.83, 4.26},
        {50, 33.80, 1.53, -69.34, 4.33},
        {60, 37.37, 1.60, -69.70, 4.25},
        {70, 37.23, 4.76, -70.48, 4.48},
        {80, 40.97, 4.06, -69.55, 3.07}}},
  }};
  return tables;
}

/// The table's values at one distance, interpolated over azimuth (degrees), as an
/// error relative to the true azimuth (degrees).
AoaRow interpolateAzimuth(const AoaDistanceTable& table, double azimuth_deg) {
  const auto& rows = table.rows;
  const double a = std::clamp(azimuth_deg, rows.front().azimuth, rows.back().azimuth);
  std::size_t i = 1;
  while (i + 1 < rows.size() && rows[i].azimuth < a) {
    ++i;
  }
  const AoaRow& lo = rows[i - 1];
  const AoaRow& hi = rows[i];
  const double w = (a - lo.azimuth) / (hi.azimuth - lo.azimuth);
  auto lerp = [w](double x, double y) { return x + w * (y - x); };
  return AoaRow{a, lerp(lo.mean - lo.azimuth, hi.mean - hi.azimuth), lerp(lo.sigma, hi.sigma),
                lerp(lo.rssi_mean, hi.rssi_mean), lerp(lo.rssi_sigma, hi.rssi_sigma)};
}

}  // namespace

RangeError uwbRangeError(double distance) {
  const double d = std::clamp(distance, kUwbTable.front()[0], kUwbTable.back()[0]);
  std::size_t i = 1;
  while (i + 1 < kUwbTable.size() && kUwbTable[i][0] < d) {
    ++i;
  }
  const auto& lo = kUwbTable[i - 1];
  const auto& hi = kUwbTable[i];
  const double w = (d - lo[0]) / (hi[0] - lo[0]);
  const double bias_lo = lo[1] - lo[0];
  const double bias_hi = hi[1] - hi[0];
  return RangeError{bias_lo + w * (bias_hi - bias_lo), lo[2] + w * (hi[2] - lo[2])};
}

double aoaTableAzimuthLimit() {
  return deg2rad(80.0);
}

AoaError aoaError(AoaBoardKind kind, double azimuth, double distance) {
  const auto& tables = kind == AoaBoardKind::kAntB10 ? antB10Tables() : xplrTables();
  const double az_deg = rad2deg(azimuth);
  const double d = std::max(distance, tables.front().distance);
  std::size_t i = 1;
  while (i + 1 < tables.size() && tables[i].distance < d) {
    ++i;
  }
  const AoaRow lo = interpolateAzimuth(tables[i - 1], az_deg);
  const AoaRow hi = interpolateAzimuth(tables[i], az_deg);
  const double w =
      std::min(1.0, (d - tables[i - 1].distance) / (tables[i].distance - tables[i - 1].distance));
  auto lerp = [w](double x, double y) { return x + w * (y - x); };
  AoaError e;
  e.azimuth_bias = deg2rad(lerp(lo.mean, hi.mean));
  e.azimuth_sigma = deg2rad(lerp(lo.sigma, hi.sigma));
  e.rssi_mean = lerp(lo.rssi_mean, hi.rssi_mean);
  e.rssi_sigma = lerp(lo.rssi_sigma, hi.rssi_sigma);
  const double far = tables.back().distance;
  if (d > far) {
    e.rssi_mean -= 20.0 * std::log10(d / far);
  }
  return e;
}

}  // namespace models
}  // namespace radio_follow
