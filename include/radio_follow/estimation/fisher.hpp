// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <Eigen/Core>
#include <optional>

#include "radio_follow/estimation/measurement_models.hpp"

namespace radio_follow {
namespace estimation {

/// Fisher information of the target position from independent Gaussian measurements:
/// sum of J^T J over the whitened residual Jacobians at the true position p
/// (Cramer-Rao bound literature, e.g. seed 004 eqs 4.47-4.51). Only the geometry and the
/// sigmas of `observations` are used, not the measured values.
Eigen::Matrix3d fisherInformation(const ObservationSet& observations, const Eigen::Vector3d& p);

/// Cramer-Rao lower bound on the covariance of an unbiased position estimator.
/// planar = true: z is known (2D mode), the bound is the inverse of the xy block and the
/// z row/column is zero. Returns nullopt when the information is singular (reciprocal
/// condition number below `min_rcond`): the position is not observable there.
std::optional<Eigen::Matrix3d> positionCrlb(const Eigen::Matrix3d& information, bool planar,
                                            double min_rcond = 1e-10);

}  // namespace estimation
}  // namespace radio_follow
