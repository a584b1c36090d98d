// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cmath>

namespace radio_follow {

constexpr double kPi = 3.14159265358979323846;

constexpr double deg2rad(double degrees) {
  return degrees * kPi / 180.0;
}
constexpr double rad2deg(double radians) {
  return radians * 180.0 / kPi;
}

/// Wraps an angle to (-pi, pi]. Templated so Ceres jets use the same code.
template <typename T>
T wrapAngle(const T& angle) {
  using std::atan2;
  using std::cos;
  using std::sin;
  return atan2(sin(angle), cos(angle));
}

/// Wraps an angle to (-pi, pi] for plain doubles without trigonometry; exact for
/// inputs that are already in range.
inline double wrapAngleFast(double angle) {
  if (angle > -kPi && angle <= kPi) {
    return angle;
  }
  double wrapped = std::fmod(angle + kPi, 2.0 * kPi);
  if (wrapped <= 0.0) {
    wrapped += 2.0 * kPi;
  }
  return wrapped - kPi;
}

}  // namespace radio_follow
