// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <Eigen/Core>
#include <optional>
#include <vector>

namespace radio_follow {
namespace estimation {

/// The main axis (in the xy-plane) of a set of ranging modules: across it lies the other
/// solution the ranges of nearly collinear modules allow (Spot's three). The solver's
/// mirror test, the particle estimator's mirror hypothesis and the cold-start benchmark
/// all reflect across it.
struct MirrorAxis {
  Eigen::Vector2d centroid = Eigen::Vector2d::Zero();
  Eigen::Vector2d direction = Eigen::Vector2d::UnitX();  ///< unit, the largest spread
  /// Smallest over largest eigenvalue of the modules' scatter: 0 = exactly collinear.
  double flatness = 0.0;

  /// `p` reflected across the axis (z unchanged).
  Eigen::Vector3d reflect(const Eigen::Vector3d& p) const;
  /// A vector (a velocity) reflected: the axis's direction kept, the normal reversed.
  Eigen::Vector2d reflectVector(const Eigen::Vector2d& v) const;
  /// Which side of the axis `p` is on (true: left of `direction`, or on it).
  bool leftOf(const Eigen::Vector3d& p) const;
};

/// The axis of `modules` (positions in one frame); nothing with fewer than two.
std::optional<MirrorAxis> mirrorAxis(const std::vector<Eigen::Vector3d>& modules);

}  // namespace estimation
}  // namespace radio_follow
