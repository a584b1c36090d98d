// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <vector>

#include "radio_follow/common/angles.hpp"

namespace radio_follow {
namespace lab {

/// The solver benchmarks' targets (locator_montecarlo, trilateration_compare): 1-10 m away
/// in 12 directions, off the boards' seams and the layouts' axes, on the plane z = height.
inline std::vector<Eigen::Vector3d> targetGrid(double height) {
  std::vector<Eigen::Vector3d> points;
  for (int r = 1; r <= 10; ++r) {
    for (int k = 0; k < 12; ++k) {
      const double a = deg2rad(15.0 + 30.0 * k);
      points.emplace_back(r * std::cos(a), r * std::sin(a), height);
    }
  }
  return points;
}

}  // namespace lab
}  // namespace radio_follow
