// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <Eigen/Core>
#include <vector>

namespace radio_follow {
namespace estimation {

/// One sensor that informs the estimate, seen through its measurement's gradient.
///
/// Real UWB ranges and AoA bearings carry an error that changes over seconds (multipath
/// that moves slowly with the geometry, a calibration residual, a board's mounting yaw):
/// measured on real recordings, range errors keep an autocorrelation of 0.4-0.5 after
/// 1 s. A filter that treats every sample as independent averages that part away on
/// paper, not in fact, and its covariance shrinks far below its error (issue 14: NEES
/// 25 for 2 dimensions). `bias_sigma` is that slowly varying part of the sensor's error;
/// `white_sigma` is the sigma the filter weighs the sensor with.
struct InformingSensor {
  Eigen::Vector3d gradient = Eigen::Vector3d::Zero();  ///< d measurement / d position
  double white_sigma = 1.0;
  double bias_sigma = 0.0;
};

/// The position covariance that errors constant over the filter's memory leave in the
/// estimate, whatever the filtering:
///   P = J^+ M J^+,  J = sum g g^T / s_w^2,  M = sum g g^T s_b^2 / s_w^4,
/// the sandwich covariance of a least-squares fit weighted by 1 / s_w^2 whose
/// measurements carry independent errors of sigma s_b. Directions the sensors do not
/// observe (J rank-deficient: one range, collinear gradients) get nothing here: what
/// the estimate knows there comes from its prior, which its own covariance carries.
Eigen::Matrix3d correlatedErrorCovariance(const std::vector<InformingSensor>& sensors);

/// d range / d position of a range from `sensor` to `target` (planar: z ignored).
Eigen::Vector3d rangeGradient(const Eigen::Vector3d& sensor, const Eigen::Vector3d& target,
                              bool planar);
/// d azimuth / d position of a bearing from `sensor` to `target` (about the z axis).
Eigen::Vector3d azimuthGradient(const Eigen::Vector3d& sensor, const Eigen::Vector3d& target);

}  // namespace estimation
}  // namespace radio_follow
