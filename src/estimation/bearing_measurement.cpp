// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/estimation/bearing_measurement.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "radio_follow/common/plausibility.hpp"
#include "radio_follow/estimation/fast_exp.hpp"
#include "radio_follow/estimation/locator.hpp"
#include "radio_follow/estimation/particle_tracker.hpp"

namespace radio_follow {
namespace estimation {

MeasurementFit weighBearing(ParticleFilter& filter, const Eigen::Vector3d& board,
                            const Eigen::Matrix3d& rotation, double azimuth, double elevation,
                            const BearingLikelihood& m) {
  // Sigma factor: a board whose field of view does not contain the cloud's mean (the
  // estimate), mirrored to the board's front, is worth less, for every particle alike. A
  // factor that depended on each particle's own angle would pull a tracked cloud inside
  // the field of view, and one from the measured angle would trust the edge's biased
  // angles that read as inside. Mirrored, because the board hears a tag behind it as
  // well as its mirror image in front: the side is not the sigma's business (see
  // BearingLikelihood). So there are two concentrations, inside and outside, each with
  // its normalising constant; for a cold start's cloud around the robot each particle's
  // own mirrored angle decides.
  const Eigen::Matrix3d rt = rotation.transpose();
  const bool each_particle =
      m.field_of_view_test == BearingLikelihood::FieldOfViewTest::kEachParticle;
  double inside_factor = 1.0;
  if (!each_particle) {
    const Eigen::Vector3d centre = rt * (filter.mean() - board);
    const double centre_cos = std::abs(centre.x()) / std::max(1e-9, centre.head<2>().norm());
    inside_factor = centre_cos < std::cos(m.field_of_view) ? m.edge_sigma_factor : 1.0;
  }
  const double outside_factor = each_particle ? m.edge_sigma_factor : inside_factor;
  // |lx| < inside_cos * rho: outside (rho, the horizontal distance, > 0).
  const auto inside_cos = static_cast<float>(each_particle ? std::cos(m.field_of_view) : -1.0);
  const auto concentration = [](double sigma) { return 1.0 / (sigma * sigma); };
  const double az_inside = concentration(m.azimuth_sigma * inside_factor);
  const double az_outside = concentration(m.azimuth_sigma * outside_factor);
  const double el_inside = m.use_elevation ? concentration(m.elevation_sigma * inside_factor) : 0.0;
  const double el_outside =
      m.use_elevation ? concentration(m.elevation_sigma * outside_factor) : 0.0;
  // The von Mises normalisers sqrt(kappa / 2 pi), each angle's times its inlier share: the
  // azimuth's (1 - eps) against reflections from anywhere, the elevation's (1 - eps_e)
  // against shadowing, which lifts the elevation while the azimuth holds.
  const auto normaliser = [](double kappa, double share) {
    return (1.0 - share) * std::sqrt(kappa / (2.0 * kPi));
  };
  const double az_scale_inside = normaliser(az_inside, m.outlier_share);
  const double az_scale_outside = normaliser(az_outside, m.outlier_share);
  const double el_scale_inside = normaliser(el_inside, m.elevation_outlier_share);
  const double el_scale_outside = normaliser(el_outside, m.elevation_outlier_share);

  // Board-frame offsets of every particle: (lx, ly, lz) = R^T (p - board), lz when needed.
  ParticleFilter::Workspace& w = filter.workspace();
  const Eigen::ArrayXf& x = filter.localX();
  const Eigen::ArrayXf& y = filter.localY();
  const Eigen::ArrayXf& z = filter.localZ();
  const Eigen::Matrix3f r = rt.cast<float>();
  const Eigen::Vector3f b = filter.local(board);
  w.lx = r(0, 0) * (x - b.x()) + r(0, 1) * (y - b.y()) + r(0, 2) * (z - b.z());
  w.ly = r(1, 0) * (x - b.x()) + r(1, 1) * (y - b.y()) + r(1, 2) * (z - b.z());
  // Reciprocal square roots (one vector instruction and a Newton step) stand in for
  // square roots and divisions: rho = rho^2 / rho.
  w.rho2 = (w.lx.square() + w.ly.square()).max(1e-18f);  // squared horizontal distance
  w.inv_rho = w.rho2.rsqrt();
  // The per-particle constants blend by a 0/1 mask (1: outside) computed with arithmetic
  // (positiveStep()), which vectorises where a select is evaluated element by element.
  w.pick = positiveStep(inside_cos * w.rho2 * w.inv_rho - w.lx.abs());
  const auto blend = [&w](double outside, double inside) {
    return static_cast<float>(inside) + static_cast<float>(outside - inside) * w.pick;
  };
  // cos(measured - predicted) - 1 as dot products of unit vectors, |lx| the array's
  // front/back mirror: in ly for the azimuth, in lz for the elevation.
  w.ly = (w.lx.abs() * std::cos(static_cast<float>(azimuth)) +
          w.ly * std::sin(static_cast<float>(azimuth))) *
             w.inv_rho -
         1.0f;
  // log of the von Mises density without its normaliser: kappa (cos - 1).
  w.inlier =
      blend(az_scale_outside, az_scale_inside) * fastExp(blend(az_outside, az_inside) * w.ly);
  if (m.use_elevation) {
    w.lz = r(2, 0) * (x - b.x()) + r(2, 1) * (y - b.y()) + r(2, 2) * (z - b.z());
    w.lz = (w.rho2 * w.inv_rho * std::cos(static_cast<float>(elevation)) +
            w.lz * std::sin(static_cast<float>(elevation))) *
               (w.rho2 + w.lz.square()).rsqrt() -
           1.0f;
    // The elevation's own mixture: its von Mises or, shadowed, uniform over [-90, 90] deg.
    w.inlier *=
        blend(el_scale_outside, el_scale_inside) * fastExp(blend(el_outside, el_inside) * w.lz) +
        static_cast<float>(m.elevation_outlier_share / kPi);
  }
  // The field of view's prior on the side: behind (lx < 0) counts behind_weight.
  w.inlier *= 1.0f + static_cast<float>(m.behind_weight - 1.0) * positiveStep(-w.lx);
  const double uniform = 1.0 / (2.0 * kPi) / (m.use_elevation ? kPi : 1.0);
  return filter.applyLikelihood(w.inlier, m.outlier_share * uniform);
}

namespace {

/// Without a range the distance is the elevation's alone, and a real board's elevation is
/// biased (the floor's bounce, a body's shadow): its sigma grows by this factor.
constexpr double kUnrangedElevationFactor = 3.0;
/// Without a range, a board's bearings closer in time than this count as one: an
/// advertising interval's readings, one per channel, share the geometry's multipath, s.
constexpr double kUnrangedBearingDecorrelation = 0.1;
/// The most a bearing's sigma grows for its decorrelation: wider, a reflection tens of
/// degrees off would fit as well as the board's own error (at 20 Hz and 0.5 s, 16 deg).
constexpr double kMaxBearingSigmaScale = 2.0;

}  // namespace

MeasurementFit weigh(const BearingReading& r, ParticleFilter& filter, const TrackerContext& c) {
  const AoaBoard& board = c.layout.aoa_boards[r.board];
  BearingLikelihood model = c.config.of<BearingReading>().likelihood;
  model.field_of_view = board.field_of_view;
  // A cold start's cloud is spread around the robot: its mean says nothing about where
  // the target is, so each particle asks whether the board sees it.
  model.field_of_view_test = c.cold_start ? BearingLikelihood::FieldOfViewTest::kEachParticle
                                          : BearingLikelihood::FieldOfViewTest::kCloudMean;
  if (!c.boards_one_way) {
    // Boards that face several ways see the side themselves: no prior needed.
    model.behind_weight = 1.0;
  }
  model.azimuth_sigma *= c.sigma_scale;
  model.elevation_sigma *= c.sigma_scale;
  if (!c.ranged) {
    model.elevation_sigma *= kUnrangedElevationFactor;
  }
  const Eigen::Matrix3d yaw =
      Eigen::AngleAxisd(c.pose.yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  return weighBearing(filter, c.pose.toFixed(board.position),
                      yaw * board.orientation.toRotationMatrix(), r.azimuth, r.elevation, model);
}

std::optional<InformingSensor> informing(const BearingReading& r, const Eigen::Vector3d& position,
                                         const TrackerContext& c) {
  const AoaBoard& board = c.layout.aoa_boards[r.board];
  const Eigen::Vector3d local =
      board.orientation.conjugate() * (c.pose.fromFixed(position) - board.position);
  if (!(local.x() > std::cos(board.field_of_view) * local.head<2>().norm())) {
    return std::nullopt;
  }
  InformingSensor s;
  s.gradient = azimuthGradient(c.pose.toFixed(board.position), position);
  s.white_sigma = c.config.of<BearingReading>().likelihood.azimuth_sigma;
  s.bias_sigma = c.config.of<BearingReading>().bias_sigma;
  return s;
}

Decorrelation decorrelation(const BearingReading& /*r*/, const TrackerContext& c) {
  // A board's slowly varying error counted as independent readings would outweigh the
  // ranges; with no range the bearings are all the direction there is, and only one
  // advertising interval's readings (one per channel) count as one.
  Decorrelation d;
  const double time = c.config.of<BearingReading>().decorrelation_time;
  d.time = c.ranged ? time : std::min(time, kUnrangedBearingDecorrelation);
  d.max_scale = kMaxBearingSigmaScale;
  return d;
}

SeedRay seedRay(const BearingReading& r, const TrackerContext& c) {
  const AoaBoard& board = c.layout.aoa_boards[r.board];
  SeedRay ray;
  ray.origin = board.position;
  ray.orientation = board.orientation;
  ray.azimuth = r.azimuth;
  ray.elevation = r.elevation;
  return ray;
}

Intake accept(BearingReading& r, const LocatorIntake& c) {
  if (r.board >= c.layout.aoa_boards.size() || !plausibleAngleRad(r.azimuth) ||
      !plausibleAngleRad(r.elevation)) {
    return Intake::kRefused;
  }
  r.elevation = std::clamp(r.elevation - c.layout.aoa_boards[r.board].elevation_offset, -0.5 * kPi,
                           0.5 * kPi);
  return Intake::kAccepted;
}

void observe(const BearingReading& r, double t, const LocatorIntake& c, FreshMeasurements& fresh,
             LocatorEstimate& out) {
  const AoaBoard& board = c.layout.aoa_boards[r.board];
  AoaCandidate candidate;
  candidate.board = r.board;
  candidate.position = board.position;
  candidate.rotation = board.orientation.toRotationMatrix();
  candidate.field_of_view = board.field_of_view;
  candidate.rssi = r.rssi;
  fresh.boards.push_back(candidate);
  fresh.angles.emplace_back(r.azimuth, r.elevation);
  fresh.bearing_stamps.push_back(t);
  out.bearings_fresh.push_back(r.board);
  out.bearing_angles.emplace_back(r.azimuth, r.elevation);
}

}  // namespace estimation
}  // namespace radio_follow
