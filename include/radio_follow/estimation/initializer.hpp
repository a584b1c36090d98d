// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "radio_follow/config/layout.hpp"
#include "radio_follow/estimation/measurement_models.hpp"

namespace radio_follow {
namespace estimation {

/// Where the target may be when nothing is known yet.
struct InitializerConfig {
  /// 2D mode: the target lies on the plane z = height.
  bool planar = true;
  double height = kDefaultTargetHeight;
  /// Points on the circle of one range in the multi-start (the thesis used a ring too).
  int circle_points = 8;
  /// Distance assumed along a bearing, or around the robot, when no range exists, m.
  double default_range = kDefaultRange;
};

/// Closed-form linear least-squares trilateration (after seed 002 eqs 2-5): subtracting the
/// first squared-range equation from the others leaves a linear system in the position,
/// solved by its normal equations. In 2D mode the known height moves into the right-hand
/// side. Needs three modules not on one line (2D) or four not on one plane (3D); returns
/// nullopt for fewer or degenerate ones. The locator's initial guess.
std::optional<Eigen::Vector3d> trilaterate(const std::vector<RangeObservation>& ranges,
                                           const InitializerConfig& config);

/// Seed 002 eqs 2-8 as written: each squared-range equation minus the next one
/// (consecutive differences), solved by a Householder QR of A (R x = Q^T b) instead of
/// the normal equations, which square A's condition number. Same inputs, conditions and
/// degeneracy test as trilaterate(); compared in doc/rssi_filters.md.
std::optional<Eigen::Vector3d> trilaterateQr(const std::vector<RangeObservation>& ranges,
                                             const InitializerConfig& config);

/// Starting points for a multi-start solve when trilateration is impossible: the circle of
/// the first range around its module, plus the point at that range along every bearing
/// (the bearing usually wins, the circle covers a wrong bearing). Without ranges, points
/// at default_range along the bearings and on a circle around the origin (TDoA only).
std::vector<Eigen::Vector3d> multiStartCandidates(const ObservationSet& observations,
                                                  const InitializerConfig& config);

/// Unit direction of a bearing in the fixed frame.
Eigen::Vector3d bearingDirection(const BearingObservation& bearing);

}  // namespace estimation
}  // namespace radio_follow
