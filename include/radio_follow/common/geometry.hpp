// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cmath>

namespace radio_follow {

/// Distance from `p` to the segment from `a` to `b` (to `a` when the two coincide).
inline double distanceToSegment(const Eigen::Vector2d& p, const Eigen::Vector2d& a,
                                const Eigen::Vector2d& b) {
  const Eigen::Vector2d ab = b - a;
  const double len2 = ab.squaredNorm();
  const double t = len2 > 0.0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  const Eigen::Vector2d closest = a + t * ab;
  return std::hypot(p.x() - closest.x(), p.y() - closest.y());
}

}  // namespace radio_follow
