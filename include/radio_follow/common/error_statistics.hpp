// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <vector>

// Error statistics of estimates against a truth: quantiles, NEES, sector and distance
// bands, headings. Used by the offline evaluation (locator_offline), the placement advisor
// and the lab's experiments.
namespace radio_follow {

/// Nearest-rank quantile (q in [0, 1]); NaN for no values.
double quantile(std::vector<double> values, double q);
/// Arithmetic mean; NaN for no values.
double mean(const std::vector<double>& values);

/// A number for a JSON document: 6 significant digits, `null` when not finite.
std::string jsonNumber(double v);
/// A JSON string literal (quotes, backslashes and control characters escaped).
std::string jsonString(const std::string& text);

/// The normalised estimation error squared e^T P^-1 e of a 2D error and its covariance;
/// nothing when P is not finite and positive definite (no covariance to judge).
std::optional<double> nees2d(const Eigen::Vector2d& error, const Eigen::Matrix2d& covariance);

/// Share of 2D normalised estimation errors squared (e^T P^-1 e) inside the 95 % ellipse,
/// i.e. at most the chi-square quantile with 2 degrees of freedom (5.991): 0.95 for a
/// consistent estimate; NaN for no values.
double shareInside95(const std::vector<double>& nees_2d);

/// Count, mean, median, 95th percentile and maximum of a set of errors.
struct ErrorSummary {
  std::size_t count = 0;
  double mean = 0.0;
  double median = 0.0;
  double p95 = 0.0;
  double max = 0.0;
};
ErrorSummary summarize(const std::vector<double>& errors);

/// Position errors of an estimator against a ground truth in the robot frame, overall,
/// by the direction of the target seen from the robot (8 sectors of 45 deg; sector 0 is
/// centred on the robot's front, counting counter-clockwise, as the thesis's Figures
/// 5.10-5.13 break the error down by direction) and by distance band.
class ErrorStatistics {
 public:
  static constexpr std::size_t kSectors = 8;
  /// Upper edges of the distance bands, m (the last band is open).
  static constexpr std::array<double, 3> kBandEdges{2.0, 4.0, 8.0};

  /// One estimate: the true target position in the robot frame (x forward, y left, m)
  /// and the error of the estimate (m). Non-finite samples are ignored.
  void add(double truth_x, double truth_y, double error);

  ErrorSummary overall() const { return summarize(all_); }
  ErrorSummary sector(std::size_t i) const { return summarize(sectors_.at(i)); }
  ErrorSummary band(std::size_t i) const { return summarize(bands_.at(i)); }
  /// Sector index of a direction (rad, CCW from the robot's x axis).
  static std::size_t sectorOf(double bearing);
  /// "0-2 m", ..., "8+ m".
  static std::string bandName(std::size_t i);

  /// The statistics as a JSON object (errors in metres; NaN as null).
  std::string toJson() const;

 private:
  std::vector<double> all_;
  std::array<std::vector<double>, kSectors> sectors_;
  std::array<std::vector<double>, kBandEdges.size() + 1> bands_;
};

/// How far from the target a robot that drives along `heading` (rad, robot frame) passes
/// it: the distance from `target` (xy, robot frame, m) to the ray from the origin along the
/// heading. The perpendicular distance when the target is ahead along the ray, its
/// distance from the origin when it is behind (the ray then leads away from it).
double missAtTarget(const Eigen::Vector2d& target, double heading);

/// An estimator's direction against the truth, by the estimate's status (OK, DEGRADED,
/// HEADING_ONLY): the absolute heading error (deg) and the miss at the target
/// (missAtTarget, m). A heading is all a layout without ranges gives, and what a robot
/// steers by, so it is judged on its own, beside the position error.
class HeadingStatistics {
 public:
  /// Non-finite samples are ignored.
  void add(const std::string& status, double heading_error_deg, double miss);

  /// Over every status ("") or one.
  ErrorSummary headingError(const std::string& status = "") const;
  ErrorSummary miss(const std::string& status = "") const;
  /// The statuses seen, in name order.
  std::vector<std::string> statuses() const;
  bool empty() const { return all_.heading.empty(); }

  /// {"all": {"count", "heading_error_deg": {median, p95, ...}, "miss_m": {...}},
  ///  "<status>": {...}, ...}; NaN as null.
  std::string toJson() const;

 private:
  struct Samples {
    std::vector<double> heading;
    std::vector<double> miss;
  };
  Samples all_;
  std::map<std::string, Samples> by_status_;
};

}  // namespace radio_follow
