// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstddef>
#include <vector>

namespace radio_follow {
namespace estimation {

/// One raw range of a module with the true distance it should have read (from a
/// ground-truth system or a tape-measured point), m.
struct RangeSample {
  double raw = 0.0;
  double truth = 0.0;
};

/// A module's fitted range calibration: corrected = sum_k coefficients[k] * raw^k,
/// the Layout's TwrModule::calibration (lowest order first).
struct RangeCalibrationFit {
  std::vector<double> coefficients;
  std::size_t used = 0;      ///< samples in the final fit
  std::size_t rejected = 0;  ///< samples refused as outliers (NLOS, reflections)
  double rms_before = 0.0;   ///< RMS of raw - truth over the used samples, m
  double rms_after = 0.0;    ///< RMS of corrected - truth over the used samples, m
};

/// The calibration fits' outlier rule: a sample farther than this many robust standard
/// deviations (MAD) from the fit is refused, ...
constexpr double kCalibrationOutlierSigmas = 4.0;
/// ... and never a bearing within this of it, rad.
constexpr double kMinOutlierAngle = 0.1;

/// Least-squares fit of a range polynomial of `degree` (0: offset only, 1: offset and
/// scale) from raw ranges to true distances. Long outliers are removed iteratively:
/// samples beyond `outlier_sigmas` robust standard deviations (MAD) of the residuals
/// (at least `min_outlier_distance` m) are refused and the fit repeated.
/// Throws std::invalid_argument when the samples cannot determine the polynomial: fewer
/// than 5 * (degree + 1) of them, non-finite values, or (degree >= 1) true distances
/// spanning less than 1 m.
RangeCalibrationFit fitRangeCalibration(const std::vector<RangeSample>& samples, int degree = 1,
                                        double outlier_sigmas = kCalibrationOutlierSigmas,
                                        double min_outlier_distance = 0.2);

/// One azimuth an AoA board reported (board frame, package convention: counter-clockwise)
/// with the true azimuth of the tag in the board frame as mounted by the layout, rad.
struct AzimuthSample {
  double measured = 0.0;
  double truth = 0.0;
};

/// A board's fitted yaw offset: the board is mounted rotated by `yaw_offset` from the
/// layout's orientation (measured = truth - yaw_offset on average), so the layout's yaw
/// is corrected by adding it.
struct YawOffsetFit {
  double yaw_offset = 0.0;  ///< rad
  std::size_t used = 0;
  std::size_t rejected = 0;
  double residual_sigma = 0.0;  ///< rad, of the used samples after the correction
  double rms_before = 0.0;      ///< rad, RMS of truth - measured over the used samples
};

/// Robust circular mean of truth - measured. Samples farther than `outlier_sigmas`
/// robust standard deviations (at least `min_outlier_angle` rad) from it are refused.
/// Throws std::invalid_argument with fewer than 5 samples or non-finite ones.
YawOffsetFit fitYawOffset(const std::vector<AzimuthSample>& samples,
                          double outlier_sigmas = kCalibrationOutlierSigmas,
                          double min_outlier_angle = kMinOutlierAngle);

/// One elevation a board reported and the tag's true elevation in the board frame, rad.
using ElevationSample = AzimuthSample;

/// A board's fitted elevation offset (AoaBoard::elevation_offset): what it reads above
/// the truth on average.
struct ElevationOffsetFit {
  double elevation_offset = 0.0;  ///< rad, measured - truth
  std::size_t used = 0;
  std::size_t rejected = 0;
  double residual_sigma = 0.0;  ///< rad, of the used samples after the correction
};

/// Robust mean of measured - truth as fitYawOffset's: readings the wearer's body shadowed
/// (5-35 deg high) are refused as outliers. Throws std::invalid_argument with fewer than
/// 5 samples or non-finite ones.
ElevationOffsetFit fitElevationOffset(const std::vector<ElevationSample>& samples);

}  // namespace estimation
}  // namespace radio_follow
