// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/estimation/fisher.hpp"

#include <Eigen/Eigenvalues>

namespace radio_follow {
namespace estimation {

Eigen::Matrix3d fisherInformation(const ObservationSet& observations, const Eigen::Vector3d& p) {
  Eigen::Matrix3d info = Eigen::Matrix3d::Zero();
  observations.forEach([&](const auto& list) {
    for (const auto& z : list) {
      const auto j = residualJacobian(z, p);
      info += j.transpose() * j;
    }
  });
  return info;
}

std::optional<Eigen::Matrix3d> positionCrlb(const Eigen::Matrix3d& information, bool planar,
                                            double min_rcond) {
  Eigen::Matrix3d crlb = Eigen::Matrix3d::Zero();
  if (planar) {
    const Eigen::Matrix2d block = information.topLeftCorner<2, 2>();
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(block);
    const Eigen::Vector2d ev = eig.eigenvalues();
    if (!(ev(1) > 0.0) || ev(0) < min_rcond * ev(1)) {
      return std::nullopt;
    }
    crlb.topLeftCorner<2, 2>() =
        eig.eigenvectors() * ev.cwiseInverse().asDiagonal() * eig.eigenvectors().transpose();
    return crlb;
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(information);
  const Eigen::Vector3d ev = eig.eigenvalues();
  if (!(ev(2) > 0.0) || ev(0) < min_rcond * ev(2)) {
    return std::nullopt;
  }
  crlb = eig.eigenvectors() * ev.cwiseInverse().asDiagonal() * eig.eigenvectors().transpose();
  return crlb;
}

}  // namespace estimation
}  // namespace radio_follow
