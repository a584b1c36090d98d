// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/control/rssi_filter.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <type_traits>
#include <string>
#include <utility>
#include <vector>

#include "radio_follow/common/median.hpp"
#include "radio_follow/common/param_error.hpp"

namespace radio_follow {
namespace control {

void RssiWindowParams::validate() const {
  require(window >= 1, "~rssi_filter/window", window, "a window of >= 1 readings");
}

void RssiKalmanParams::validate() const {
  require(std::isfinite(process_noise) && process_noise > 0.0, "~rssi_filter/process_noise",
          process_noise, "a process noise variance > 0 dB^2 per reading");
  require(std::isfinite(measurement_noise) && measurement_noise > 0.0,
          "~rssi_filter/measurement_noise", measurement_noise,
          "a measurement noise variance > 0 dB^2");
}

double RssiKalmanParams::steadyStateGain() const {
  const double q = process_noise;
  const double prior = 0.5 * (q + std::sqrt(q * q + 4.0 * q * measurement_noise));
  return prior / (prior + measurement_noise);
}

RssiWindow::RssiWindow(const RssiWindowParams& params)
    : window_([&] {
        params.validate();
        return static_cast<std::size_t>(params.window);
      }()) {}

bool RssiWindow::push(double rssi) {
  if (!std::isfinite(rssi)) {
    ++refused_;
    return false;
  }
  values_.push_back(rssi);
  if (values_.size() > window_) {
    values_.pop_front();
  }
  return true;
}

std::optional<double> MovingMean::update(double rssi) {
  if (!window_.push(rssi)) {
    return std::nullopt;
  }
  // Summed afresh each time: a running sum drifts by rounding over a long run, and a
  // window is a few tens of readings.
  const auto& v = window_.values();
  return std::accumulate(v.begin(), v.end(), 0.0) / static_cast<double>(v.size());
}

std::optional<double> MovingMedian::update(double rssi) {
  if (!window_.push(rssi)) {
    return std::nullopt;
  }
  return median(std::vector<double>(window_.values().begin(), window_.values().end()));
}

RssiKalman::RssiKalman(const RssiKalmanParams& params)
    : params_([&] {
        params.validate();
        return params;
      }()) {}

std::optional<double> RssiKalman::update(double rssi) {
  if (!std::isfinite(rssi)) {
    ++refused_;
    return std::nullopt;
  }
  if (!state_) {
    // The first reading is the whole information: the state is it, with its variance.
    state_ = rssi;
    variance_ = params_.measurement_noise;
    gain_ = 1.0;
    return state_;
  }
  const double prior = variance_ + params_.process_noise;
  gain_ = prior / (prior + params_.measurement_noise);
  *state_ += gain_ * (rssi - *state_);
  variance_ = (1.0 - gain_) * prior;
  return state_;
}

void RssiKalman::reset() {
  state_.reset();
  variance_ = 0.0;
  gain_ = 0.0;
}

const ParamTable<RssiFilterParams>& RssiFilterParams::table() {
  using P = RssiFilterParams;
  using T = P::Type;
  static const ParamTable<P> t =
      ParamTable<P>()
          .addChoice("type", &P::type,
                     std::vector<std::pair<std::string, T>>{{"none", T::kNone},
                                                            {"mean", T::kMean},
                                                            {"median", T::kMedian},
                                                            {"kalman", T::kKalman}},
                     "Smoother of the RSSI before the log-distance model.")
          .include(ParamTable<RssiWindowParams>().add("window", &RssiWindowParams::window,
                                                      "readings", "Mean and median window.",
                                                      Range::atLeast(1)),
                   &P::window)
          .include(ParamTable<RssiKalmanParams>()
                       .add("process_noise", &RssiKalmanParams::process_noise, "dB^2",
                            "Kalman Q per reading.", Range::above(0.0))
                       .add("measurement_noise", &RssiKalmanParams::measurement_noise, "dB^2",
                            "Kalman R.", Range::above(0.0)),
                   &P::kalman);
  return t;
}

void RssiFilterParams::validate() const {
  window.validate();
  kalman.validate();
}

RssiFilter::RssiFilter(const RssiFilterParams& params) {
  params.validate();
  switch (params.type) {
    case RssiFilterParams::Type::kNone:
      break;
    case RssiFilterParams::Type::kMean:
      filter_ = MovingMean(params.window);
      break;
    case RssiFilterParams::Type::kMedian:
      filter_ = MovingMedian(params.window);
      break;
    case RssiFilterParams::Type::kKalman:
      filter_ = RssiKalman(params.kalman);
      break;
  }
}

std::optional<double> RssiFilter::update(double rssi) {
  if (std::holds_alternative<std::monostate>(filter_)) {
    if (!std::isfinite(rssi)) {
      ++passed_refused_;
      return std::nullopt;
    }
    return rssi;
  }
  return std::visit(
      [rssi](auto& f) -> std::optional<double> {
        if constexpr (std::is_same_v<std::decay_t<decltype(f)>, std::monostate>) {
          return std::nullopt;
        } else {
          return f.update(rssi);
        }
      },
      filter_);
}

void RssiFilter::reset() {
  std::visit(
      [](auto& f) {
        if constexpr (!std::is_same_v<std::decay_t<decltype(f)>, std::monostate>) {
          f.reset();
        }
      },
      filter_);
}

std::uint64_t RssiFilter::refused() const {
  return std::visit(
      [this](const auto& f) -> std::uint64_t {
        if constexpr (std::is_same_v<std::decay_t<decltype(f)>, std::monostate>) {
          return passed_refused_;
        } else {
          return f.refused();
        }
      },
      filter_);
}

}  // namespace control
}  // namespace radio_follow
