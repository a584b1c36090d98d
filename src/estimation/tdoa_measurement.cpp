// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/estimation/tdoa_measurement.hpp"

namespace radio_follow {
namespace estimation {

MeasurementFit weighTdoa(ParticleFilter& filter, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                         double difference, const RangeLikelihood& model) {
  ParticleFilter::Workspace& w = filter.workspace();
  const Eigen::ArrayXf& x = filter.localX();
  const Eigen::ArrayXf& y = filter.localY();
  const Eigen::ArrayXf& z = filter.localZ();
  const Eigen::Vector3f p = filter.local(a);
  const Eigen::Vector3f q = filter.local(b);
  w.lx = ((x - p.x()).square() + (y - p.y()).square() + (z - p.z()).square()).sqrt();
  w.ly = ((x - q.x()).square() + (y - q.y()).square() + (z - q.z()).square()).sqrt();
  w.inlier = static_cast<float>(difference) - (w.lx - w.ly);
  model.evaluate(w.inlier, &w.inlier, &w.outlier);
  return filter.applyLikelihood(w.inlier, w.outlier);
}

}  // namespace estimation
}  // namespace radio_follow
