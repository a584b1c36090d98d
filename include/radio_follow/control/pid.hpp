// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>

#include "radio_follow/common/param_table.hpp"

namespace radio_follow {
namespace control {

/// Gains and limits of one PID loop.
struct PidGains {
  double kp = 1.0;
  double ki = 0.0;
  double kd = 0.0;
  /// |ki * integral| never exceeds this (clamping anti-windup), output units.
  double integral_limit = 0.5;
  /// Time constant of the first-order low-pass on the derivative term, seconds;
  /// 0 = unfiltered. Filtering keeps sensor noise from turning into jerky commands.
  double derivative_time_constant = 0.1;
  /// Output saturation (symmetric), output units.
  double output_limit = 1.0;

  /// kp, ki, kd, integral_limit, derivative_time_constant (output_limit is the node's
  /// speed limit, not a parameter).
  static const ParamTable<PidGains>& table();
  /// Throws ParamError naming `prefix`.<field> for an unusable value.
  void validate(const std::string& prefix) const;
};

/// PID on an error signal with clamping anti-windup and a filtered derivative (on the
/// error). The integral only grows while the output is not saturated in the same
/// direction, so a long saturation does not leave a large overshoot behind.
class Pid {
 public:
  explicit Pid(const PidGains& gains = PidGains()) : gains_(gains) {}

  /// One step: `error` at this cycle, `dt` seconds since the previous one (> 0;
  /// non-positive `dt` returns the proportional term only and changes no state).
  double update(double error, double dt);

  /// Forgets integral and derivative history (used whenever the loop is not in charge,
  /// e.g. during a safety stop, so that it resumes without a kick).
  void reset();

  /// New gains (live tuning) without a kick: the integral is kept, re-scaled so that its
  /// contribution ki * integral stays the same, and clamped to the new integral_limit.
  void setGains(const PidGains& gains);

  const PidGains& gains() const { return gains_; }
  double integral() const { return integral_; }

 private:
  PidGains gains_;
  double integral_ = 0.0;
  double previous_error_ = 0.0;
  double filtered_derivative_ = 0.0;
  bool has_previous_ = false;
};

}  // namespace control
}  // namespace radio_follow
