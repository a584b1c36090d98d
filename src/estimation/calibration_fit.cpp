// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/estimation/calibration_fit.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "radio_follow/common/angles.hpp"

namespace radio_follow {
namespace estimation {
namespace {

/// 1.4826 * median absolute value: the standard deviation of Gaussian residuals, not
/// moved by a share of long outliers.
double robustSigma(std::vector<double> residuals) {
  if (residuals.empty()) {
    return 0.0;
  }
  for (double& r : residuals) {
    r = std::abs(r);
  }
  const auto middle = residuals.begin() + static_cast<std::ptrdiff_t>(residuals.size() / 2);
  std::nth_element(residuals.begin(), middle, residuals.end());
  return 1.4826 * *middle;
}

double evaluate(const std::vector<double>& c, double x) {
  double y = 0.0;
  for (auto it = c.rbegin(); it != c.rend(); ++it) {
    y = y * x + *it;
  }
  return y;
}

std::vector<double> leastSquares(const std::vector<RangeSample>& samples,
                                 const std::vector<bool>& use, int degree) {
  const auto n = static_cast<Eigen::Index>(std::count(use.begin(), use.end(), true));
  Eigen::MatrixXd a(n, degree + 1);
  Eigen::VectorXd b(n);
  Eigen::Index row = 0;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    if (!use[i]) {
      continue;
    }
    double power = 1.0;
    for (int k = 0; k <= degree; ++k) {
      a(row, k) = power;
      power *= samples[i].raw;
    }
    b(row++) = samples[i].truth;
  }
  const Eigen::VectorXd x = a.colPivHouseholderQr().solve(b);
  return std::vector<double>(x.data(), x.data() + x.size());
}

}  // namespace

RangeCalibrationFit fitRangeCalibration(const std::vector<RangeSample>& samples, int degree,
                                        double outlier_sigmas, double min_outlier_distance) {
  if (degree < 0 || degree > 3) {
    throw std::invalid_argument("range calibration degree " + std::to_string(degree) +
                                ": expected 0 to 3");
  }
  const std::size_t needed = 5 * static_cast<std::size_t>(degree + 1);
  if (samples.size() < needed) {
    throw std::invalid_argument("range calibration: " + std::to_string(samples.size()) +
                                " samples, at least " + std::to_string(needed) + " needed");
  }
  double lowest = samples.front().truth;
  double highest = lowest;
  for (const auto& s : samples) {
    if (!std::isfinite(s.raw) || !std::isfinite(s.truth)) {
      throw std::invalid_argument("range calibration: a sample is not finite");
    }
    lowest = std::min(lowest, s.truth);
    highest = std::max(highest, s.truth);
  }
  if (degree >= 1 && highest - lowest < 1.0) {
    throw std::invalid_argument("range calibration: true distances span " +
                                std::to_string(highest - lowest) +
                                " m; a scale needs at least 1 m (stand at several distances)");
  }

  std::vector<bool> use(samples.size(), true);
  RangeCalibrationFit fit;
  for (int iteration = 0; iteration < 10; ++iteration) {
    fit.coefficients = leastSquares(samples, use, degree);
    std::vector<double> residuals;
    for (std::size_t i = 0; i < samples.size(); ++i) {
      if (use[i]) {
        residuals.push_back(evaluate(fit.coefficients, samples[i].raw) - samples[i].truth);
      }
    }
    const double limit = std::max(min_outlier_distance, outlier_sigmas * robustSigma(residuals));
    bool changed = false;
    std::size_t kept = 0;
    std::vector<bool> next(samples.size());
    for (std::size_t i = 0; i < samples.size(); ++i) {
      next[i] = std::abs(evaluate(fit.coefficients, samples[i].raw) - samples[i].truth) <= limit;
      kept += next[i];
      changed = changed || next[i] != use[i];
    }
    if (!changed || kept < needed) {
      break;
    }
    use = std::move(next);
  }

  double before = 0.0;
  double after = 0.0;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    if (use[i]) {
      before += std::pow(samples[i].raw - samples[i].truth, 2);
      after += std::pow(evaluate(fit.coefficients, samples[i].raw) - samples[i].truth, 2);
      ++fit.used;
    }
  }
  fit.rejected = samples.size() - fit.used;
  fit.rms_before = std::sqrt(before / static_cast<double>(fit.used));
  fit.rms_after = std::sqrt(after / static_cast<double>(fit.used));
  return fit;
}

namespace {

/// fitYawOffset's robust circular mean of truth - measured; `what` names the fit in
/// errors.
YawOffsetFit fitAngleOffset(const std::vector<AzimuthSample>& samples, const std::string& what,
                            double outlier_sigmas, double min_outlier_angle) {
  if (samples.size() < 5) {
    throw std::invalid_argument(what + ": " + std::to_string(samples.size()) +
                                " samples, at least 5 needed");
  }
  std::vector<double> errors;
  for (const auto& s : samples) {
    if (!std::isfinite(s.measured) || !std::isfinite(s.truth)) {
      throw std::invalid_argument(what + ": a sample is not finite");
    }
    errors.push_back(wrapAngle(s.truth - s.measured));
  }
  std::vector<bool> use(errors.size(), true);
  YawOffsetFit fit;
  for (int iteration = 0; iteration < 10; ++iteration) {
    double s = 0.0;
    double c = 0.0;
    for (std::size_t i = 0; i < errors.size(); ++i) {
      if (use[i]) {
        s += std::sin(errors[i]);
        c += std::cos(errors[i]);
      }
    }
    fit.yaw_offset = std::atan2(s, c);
    std::vector<double> residuals;
    for (std::size_t i = 0; i < errors.size(); ++i) {
      if (use[i]) {
        residuals.push_back(wrapAngle(errors[i] - fit.yaw_offset));
      }
    }
    const double limit = std::max(min_outlier_angle, outlier_sigmas * robustSigma(residuals));
    bool changed = false;
    std::size_t kept = 0;
    std::vector<bool> next(errors.size());
    for (std::size_t i = 0; i < errors.size(); ++i) {
      next[i] = std::abs(wrapAngle(errors[i] - fit.yaw_offset)) <= limit;
      kept += next[i];
      changed = changed || next[i] != use[i];
    }
    if (!changed || kept < 5) {
      break;
    }
    use = std::move(next);
  }
  double sum = 0.0;
  double before = 0.0;
  for (std::size_t i = 0; i < errors.size(); ++i) {
    if (use[i]) {
      sum += std::pow(wrapAngle(errors[i] - fit.yaw_offset), 2);
      before += std::pow(errors[i], 2);
      ++fit.used;
    }
  }
  fit.rejected = errors.size() - fit.used;
  fit.residual_sigma = std::sqrt(sum / static_cast<double>(fit.used));
  fit.rms_before = std::sqrt(before / static_cast<double>(fit.used));
  return fit;
}

}  // namespace

YawOffsetFit fitYawOffset(const std::vector<AzimuthSample>& samples, double outlier_sigmas,
                          double min_outlier_angle) {
  return fitAngleOffset(samples, "yaw offset", outlier_sigmas, min_outlier_angle);
}

ElevationOffsetFit fitElevationOffset(const std::vector<ElevationSample>& samples) {
  // The robust mean of truth - measured, on the samples with the two swapped.
  std::vector<AzimuthSample> swapped;
  for (const ElevationSample& s : samples) {
    swapped.push_back({s.truth, s.measured});
  }
  const YawOffsetFit mean =
      fitAngleOffset(swapped, "elevation offset", kCalibrationOutlierSigmas, kMinOutlierAngle);
  ElevationOffsetFit fit;
  fit.elevation_offset = mean.yaw_offset;
  fit.used = mean.used;
  fit.rejected = mean.rejected;
  fit.residual_sigma = mean.residual_sigma;
  return fit;
}

}  // namespace estimation
}  // namespace radio_follow
