// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/estimation/mirror_axis.hpp"

#include <Eigen/Eigenvalues>

namespace radio_follow {
namespace estimation {

Eigen::Vector3d MirrorAxis::reflect(const Eigen::Vector3d& p) const {
  const Eigen::Vector2d d = p.head<2>() - centroid;
  Eigen::Vector3d mirrored = p;
  mirrored.head<2>() = centroid + 2.0 * d.dot(direction) * direction - d;
  return mirrored;
}

Eigen::Vector2d MirrorAxis::reflectVector(const Eigen::Vector2d& v) const {
  return 2.0 * v.dot(direction) * direction - v;
}

bool MirrorAxis::leftOf(const Eigen::Vector3d& p) const {
  const Eigen::Vector2d d = p.head<2>() - centroid;
  return direction.x() * d.y() - direction.y() * d.x() >= 0.0;
}

std::optional<MirrorAxis> mirrorAxis(const std::vector<Eigen::Vector3d>& modules) {
  if (modules.size() < 2) {
    return std::nullopt;
  }
  MirrorAxis axis;
  for (const auto& m : modules) {
    axis.centroid += m.head<2>();
  }
  axis.centroid /= static_cast<double>(modules.size());
  Eigen::Matrix2d scatter = Eigen::Matrix2d::Zero();
  for (const auto& m : modules) {
    const Eigen::Vector2d d = m.head<2>() - axis.centroid;
    scatter += d * d.transpose();
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eigen(scatter);
  axis.direction = eigen.eigenvectors().col(1);  // eigenvalues ascend: the largest spread
  axis.flatness = eigen.eigenvalues()(0) / eigen.eigenvalues()(1);
  return axis;
}

}  // namespace estimation
}  // namespace radio_follow
