// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/estimation/range_measurement.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "radio_follow/common/angles.hpp"
#include "radio_follow/common/plausibility.hpp"
#include "radio_follow/estimation/fast_exp.hpp"
#include "radio_follow/estimation/locator.hpp"
#include "radio_follow/estimation/particle_tracker.hpp"

namespace radio_follow {
namespace estimation {
namespace {

/// The parts of a heavy-tailed range likelihood that do not depend on the error.
struct RangeTerms {
  double gauss;  ///< (1 - eps) / (sqrt(2 pi) sigma)
  double tail;   ///< 0.9 eps / L  (one-sided) or 0.45 eps / L (symmetric)
  double floor;  ///< 0.1 eps / (2 W)
  double inv_sigma;
  double inv_length;
};

RangeTerms rangeTerms(const RangeLikelihood& m) {
  const double eps = m.outlier_share;
  return {(1.0 - eps) / (std::sqrt(2.0 * kPi) * m.sigma),
          (m.one_sided ? 0.9 : 0.45) * eps / m.outlier_length, 0.1 * eps / (2.0 * m.floor_width),
          1.0 / m.sigma, 1.0 / m.outlier_length};
}

}  // namespace

double RangeLikelihood::operator()(double error) const {
  const RangeTerms k = rangeTerms(*this);
  const double z = error * k.inv_sigma;
  double tail = 0.0;
  if (!one_sided) {
    tail = k.tail * std::exp(-std::abs(error) * k.inv_length);
  } else if (error > 0.0) {
    tail = k.tail * std::exp(-error * k.inv_length);
  }
  return k.gauss * std::exp(-0.5 * z * z) + tail + k.floor;
}

void RangeLikelihood::evaluate(const Eigen::ArrayXf& error, Eigen::ArrayXf* inlier,
                               Eigen::ArrayXf* outlier) const {
  const RangeTerms k = rangeTerms(*this);
  const auto tail = static_cast<float>(k.tail);
  const auto inv_length = static_cast<float>(k.inv_length);
  const auto floor = static_cast<float>(k.floor);
  if (one_sided) {
    *outlier = tail * positiveStep(error) * fastExp(-error.max(0.0f) * inv_length) + floor;
  } else {
    *outlier = tail * fastExp(-error.abs() * inv_length) + floor;
  }
  *inlier = static_cast<float>(k.gauss) *
            fastExp(-0.5f * (error * static_cast<float>(k.inv_sigma)).square());
}

MeasurementFit weighRange(ParticleFilter& filter, const Eigen::Vector3d& module, double range,
                          const RangeLikelihood& model) {
  ParticleFilter::Workspace& w = filter.workspace();
  const Eigen::Vector3f m = filter.local(module);
  w.inlier = static_cast<float>(range) -
             ((filter.localX() - m.x()).square() + (filter.localY() - m.y()).square() +
              (filter.localZ() - m.z()).square())
                 .sqrt();
  model.evaluate(w.inlier, &w.inlier, &w.outlier);
  return filter.applyLikelihood(w.inlier, w.outlier);
}

MeasurementFit weigh(const RangeReading& r, ParticleFilter& filter, const TrackerContext& c) {
  RangeLikelihood model = c.config.of<RangeReading>().likelihood;
  model.sigma *= c.sigma_scale;
  return weighRange(filter, c.pose.toFixed(c.layout.twr_modules[r.module].position), r.range,
                    model);
}

std::optional<InformingSensor> informing(const RangeReading& r, const Eigen::Vector3d& position,
                                         const TrackerContext& c) {
  InformingSensor s;
  s.gradient = rangeGradient(c.pose.toFixed(c.layout.twr_modules[r.module].position), position,
                             c.config.filter.planar);
  s.white_sigma = c.config.of<RangeReading>().likelihood.sigma;
  s.bias_sigma = c.config.of<RangeReading>().bias_sigma;
  return s;
}

Decorrelation decorrelation(const RangeReading& /*r*/, const TrackerContext& c) {
  Decorrelation d;
  d.time = c.config.of<RangeReading>().decorrelation_time;
  return d;
}

SeedRing seedRing(const RangeReading& r, const TrackerContext& c) {
  SeedRing ring;
  ring.centre = c.layout.twr_modules[r.module].position;
  ring.radius = r.range;
  return ring;
}

Intake accept(RangeReading& r, const LocatorIntake& c) {
  // The drivers' bounds (plausibility.hpp), and 0 m is no range to solve with.
  if (r.module >= c.layout.twr_modules.size() || !plausibleRange(r.range) || r.range <= 0.0) {
    return Intake::kRefused;
  }
  r.range = c.layout.twr_modules[r.module].correctRange(r.range);
  return r.range > 0.0 ? Intake::kAccepted : Intake::kRefused;
}

void observe(const RangeReading& r, double t, const LocatorIntake& c, FreshMeasurements& fresh,
             LocatorEstimate& out) {
  RangeObservation z;
  z.module = c.layout.twr_modules[r.module].position;
  z.range = r.range;
  z.sigma = c.config.range_sigma;
  fresh.obs.ranges.push_back(z);
  fresh.newest = std::max(fresh.newest, t);
  out.ranges_used.push_back(r.module);
  out.ranges_m.push_back(z.range);
}

}  // namespace estimation
}  // namespace radio_follow
