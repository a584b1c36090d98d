// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstddef>
#include <cstdint>
#include <deque>
#include <optional>
#include <variant>

#include "radio_follow/common/param_table.hpp"

namespace radio_follow {
namespace control {

/// The RSSI smoothers of seed 002 Section 5 (arithmetic mean, median, Kalman estimator),
/// one reading at a time, in dBm. A reading that is not finite is refused and counted,
/// never averaged in: one NaN would otherwise poison a mean or a Kalman state for good.
/// They count readings, not seconds, as the paper does (one advertisement per 100 ms);
/// a homing robot's bearings arrive at a steady rate, so the two are proportional.

/// Window of the moving mean and the moving median.
struct RssiWindowParams {
  int window = 10;  ///< readings, >= 1 (1 = no smoothing)
  void validate() const;
};

/// The seed's 1-D Kalman estimator: a random-walk RSSI x_k = x_{k-1} + w, w ~ N(0, Q),
/// read as z_k = x_k + v, v ~ N(0, R). Only Q / R matters once started; R is also the
/// first reading's variance.
struct RssiKalmanParams {
  double process_noise = 1.0;       ///< Q, dB^2 per reading, > 0
  double measurement_noise = 25.0;  ///< R, dB^2, > 0 (gain 0.18 with Q = 1)
  void validate() const;
  /// Closed-form steady-state gain K = P / (P + R) with P = (Q + sqrt(Q^2 + 4 Q R)) / 2,
  /// the prior variance at the fixed point of the Riccati recursion.
  double steadyStateGain() const;
};

/// The last `window` finite readings, oldest first: what the mean and the median share.
class RssiWindow {
 public:
  /// Validates `params` (throws ParamError).
  explicit RssiWindow(const RssiWindowParams& params);
  /// Adds `rssi` (dropping the oldest beyond the window); false and counted when `rssi`
  /// is not finite, which leaves the window as it was.
  bool push(double rssi);
  const std::deque<double>& values() const { return values_; }
  void reset() { values_.clear(); }
  std::uint64_t refused() const { return refused_; }

 private:
  std::size_t window_;
  std::deque<double> values_;
  std::uint64_t refused_ = 0;
};

/// Arithmetic mean of the last `window` readings.
class MovingMean {
 public:
  explicit MovingMean(const RssiWindowParams& params) : window_(params) {}
  /// The mean including `rssi`; nullopt (state unchanged) when `rssi` is not finite.
  std::optional<double> update(double rssi);
  void reset() { window_.reset(); }
  std::uint64_t refused() const { return window_.refused(); }

 private:
  RssiWindow window_;
};

/// Median of the last `window` readings (mean of the two middle ones for an even count):
/// a fade shorter than half the window does not move it at all.
class MovingMedian {
 public:
  explicit MovingMedian(const RssiWindowParams& params) : window_(params) {}
  std::optional<double> update(double rssi);
  void reset() { window_.reset(); }
  std::uint64_t refused() const { return window_.refused(); }

 private:
  RssiWindow window_;
};

/// The 1-D Kalman estimator of RssiKalmanParams, started at the first reading.
class RssiKalman {
 public:
  explicit RssiKalman(const RssiKalmanParams& params);
  std::optional<double> update(double rssi);
  void reset();
  std::uint64_t refused() const { return refused_; }
  /// Gain of the last correction (0 before any).
  double gain() const { return gain_; }
  /// Posterior variance, dB^2 (0 before any reading).
  double variance() const { return variance_; }

 private:
  RssiKalmanParams params_;
  std::optional<double> state_;
  double variance_ = 0.0;
  double gain_ = 0.0;
  std::uint64_t refused_ = 0;
};

/// Which smoother feeds the log-distance model, and their parameters: the homing
/// controller's `rssi_filter/...` parameters (config/homing_controller.yaml).
struct RssiFilterParams {
  enum class Type { kNone, kMean, kMedian, kKalman };
  /// kalman: the smallest distance error in lab rssi_filter_compare, static and approaching
  /// (doc/rssi_filters.md).
  Type type = Type::kKalman;
  RssiWindowParams window;
  RssiKalmanParams kalman;

  /// type, window, process_noise, measurement_noise (bounds included).
  static const ParamTable<RssiFilterParams>& table();
  void validate() const;
};

/// The filter RssiFilterParams::type names; `none` passes finite readings through.
class RssiFilter {
 public:
  explicit RssiFilter(const RssiFilterParams& params);
  std::optional<double> update(double rssi);
  void reset();
  std::uint64_t refused() const;

 private:
  std::variant<std::monostate, MovingMean, MovingMedian, RssiKalman> filter_;
  std::uint64_t passed_refused_ = 0;  ///< type none
};

}  // namespace control
}  // namespace radio_follow
