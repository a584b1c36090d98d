// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/estimation/tdoa_measurement.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "radio_follow/common/plausibility.hpp"
#include "radio_follow/estimation/locator.hpp"
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
  RangeLikelihood model = c.config.of<TdoaReading>().likelihood;
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
  s.bias_sigma = c.config.of<TdoaReading>().bias_sigma;
  return s;
}

Intake accept(TdoaReading& r, const LocatorIntake& c) {
  const std::size_t anchors = c.layout.tdoa_anchors.size();
  if (r.anchor_a >= anchors || r.anchor_b >= anchors || r.anchor_a == r.anchor_b ||
      !plausibleDistanceDifference(r.difference)) {
    return Intake::kRefused;
  }
  if (c.tdoa_calibration.active()) {
    const std::optional<double> offset = c.tdoa_calibration.offset(r.anchor_a, r.anchor_b);
    if (!offset) {
      ++c.stats.tdoa_uncalibrated;  // an uncorrected offset would turn the heading
      return Intake::kHeld;
    }
    r.difference -= *offset;
  }
  if (!(r.sigma > 0.0 && std::isfinite(r.sigma))) {
    r.sigma = c.config.tdoa_sigma;
  }
  return Intake::kAccepted;
}

void observe(const TdoaReading& r, double t, const LocatorIntake& c, FreshMeasurements& fresh,
             LocatorEstimate& /*out*/) {
  TdoaObservation z;
  z.anchor_a = c.layout.tdoa_anchors[r.anchor_a].position;
  z.anchor_b = c.layout.tdoa_anchors[r.anchor_b].position;
  z.difference = r.difference;
  z.sigma = r.sigma;
  fresh.obs.tdoas.push_back(z);
  fresh.newest = std::max(fresh.newest, t);
}

}  // namespace estimation
}  // namespace radio_follow
