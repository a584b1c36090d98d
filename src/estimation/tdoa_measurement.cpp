// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/estimation/tdoa_measurement.hpp"

#include "radio_follow/estimation/particle_tracker.hpp"

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

MeasurementFit weigh(const TdoaReading& r, ParticleFilter& filter, const TrackerContext& c) {
  RangeLikelihood model = c.config.tdoa;
  model.sigma = r.sigma;
  return weighTdoa(filter, c.pose.toFixed(c.layout.tdoa_anchors[r.anchor_a].position),
                   c.pose.toFixed(c.layout.tdoa_anchors[r.anchor_b].position), r.difference, model);
}

std::optional<InformingSensor> informing(const TdoaReading& r, const Eigen::Vector3d& position,
                                         const TrackerContext& c) {
  InformingSensor s;
  s.gradient = rangeGradient(c.pose.toFixed(c.layout.tdoa_anchors[r.anchor_a].position), position,
                             c.config.filter.planar) -
               rangeGradient(c.pose.toFixed(c.layout.tdoa_anchors[r.anchor_b].position), position,
                             c.config.filter.planar);
  s.white_sigma = r.sigma;
  s.bias_sigma = c.config.tdoa_bias_sigma;
  return s;
}

}  // namespace estimation
}  // namespace radio_follow
