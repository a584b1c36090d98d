// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <limits>

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

/// How a planar position estimate is uncertain as seen from the origin: the 1-sigma
/// spread along the line of sight (range, m) and across it as an angle (bearing, rad).
/// A range-only robot with a small baseline is sure of the range and unsure of the
/// bearing; far away, a bearing spread of a few degrees is metres sideways.
struct PolarSpread {
  double range_sigma = std::numeric_limits<double>::infinity();
  double bearing_sigma = std::numeric_limits<double>::infinity();
};

/// The spread of `position` with `covariance` (xy, m^2) along and across the line of
/// sight from the origin. Unknown (both +inf) for a non-finite input or a position at
/// the origin, where no line of sight exists.
inline PolarSpread polarSpread(const Eigen::Vector2d& position, const Eigen::Matrix2d& covariance) {
  PolarSpread spread;
  const double range = position.norm();
  if (!position.allFinite() || !covariance.allFinite() || !(range > 1e-6)) {
    return spread;
  }
  const Eigen::Vector2d along = position / range;
  const Eigen::Vector2d across(-along.y(), along.x());
  spread.range_sigma = std::sqrt(std::max(0.0, along.dot(covariance * along)));
  spread.bearing_sigma = std::atan2(std::sqrt(std::max(0.0, across.dot(covariance * across))), range);
  return spread;
}

}  // namespace radio_follow
