// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/control/pid.hpp"

#include <algorithm>
#include <cmath>

#include "radio_follow/common/param_error.hpp"

namespace radio_follow {
namespace control {

const ParamTable<PidGains>& PidGains::table() {
  static const ParamTable<PidGains> t =
      ParamTable<PidGains>()
          .add("kp", &PidGains::kp, "", "Proportional gain.", Range::atLeast(0.0))
          .add("ki", &PidGains::ki, "", "Integral gain.", Range::atLeast(0.0))
          .add("kd", &PidGains::kd, "", "Derivative gain.", Range::atLeast(0.0))
          .add("integral_limit", &PidGains::integral_limit, "",
               "|ki * integral| never exceeds this (anti-windup), output units.",
               Range::atLeast(0.0))
          .add("derivative_time_constant", &PidGains::derivative_time_constant, "s",
               "Low-pass on the derivative term; 0 = unfiltered.", Range::atLeast(0.0));
  return t;
}

void PidGains::validate(const std::string& prefix) const {
  require(std::isfinite(kp) && kp >= 0.0, prefix + ".kp", kp, "a finite gain >= 0");
  require(std::isfinite(ki) && ki >= 0.0, prefix + ".ki", ki, "a finite gain >= 0");
  require(std::isfinite(kd) && kd >= 0.0, prefix + ".kd", kd, "a finite gain >= 0");
  require(std::isfinite(integral_limit) && integral_limit >= 0.0, prefix + ".integral_limit",
          integral_limit, "a finite limit >= 0");
  require(std::isfinite(derivative_time_constant) && derivative_time_constant >= 0.0,
          prefix + ".derivative_time_constant", derivative_time_constant, "seconds >= 0");
  require(std::isfinite(output_limit) && output_limit > 0.0, prefix + ".output_limit", output_limit,
          "a finite limit > 0");
}

void Pid::setGains(const PidGains& gains) {
  const double contribution = gains_.ki * integral_;
  gains_ = gains;
  if (gains_.ki > 0.0) {
    const double limited = std::clamp(contribution, -gains_.integral_limit, gains_.integral_limit);
    integral_ = limited / gains_.ki;
  } else {
    integral_ = 0.0;
  }
}

double Pid::update(double error, double dt) {
  const double proportional = gains_.kp * error;
  if (!(dt > 0.0) || !std::isfinite(error)) {
    return std::clamp(std::isfinite(proportional) ? proportional : 0.0, -gains_.output_limit,
                      gains_.output_limit);
  }

  if (has_previous_ && gains_.kd > 0.0) {
    const double raw = (error - previous_error_) / dt;
    const double alpha = dt / (gains_.derivative_time_constant + dt);
    filtered_derivative_ += alpha * (raw - filtered_derivative_);
  }
  previous_error_ = error;
  has_previous_ = true;

  double candidate_integral = integral_ + error * dt;
  if (gains_.ki > 0.0) {
    const double bound = gains_.integral_limit / gains_.ki;
    candidate_integral = std::clamp(candidate_integral, -bound, bound);
  }
  const double derivative = gains_.kd * filtered_derivative_;
  const double unsaturated = proportional + gains_.ki * candidate_integral + derivative;
  const double output = std::clamp(unsaturated, -gains_.output_limit, gains_.output_limit);
  // Conditional integration: keep the new integral unless the output is saturated and
  // integrating further would push it deeper into saturation.
  const bool winding_up = unsaturated != output && (error * unsaturated) > 0.0;
  if (!winding_up) {
    integral_ = candidate_integral;
  }
  return output;
}

void Pid::reset() {
  integral_ = 0.0;
  previous_error_ = 0.0;
  filtered_derivative_ = 0.0;
  has_previous_ = false;
}

}  // namespace control
}  // namespace radio_follow
