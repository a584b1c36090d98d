// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/evaluation/standing_experiments.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "radio_follow/common/angles.hpp"
#include "radio_follow/common/error_statistics.hpp"
#include "radio_follow/common/param_error.hpp"
#include "radio_follow/evaluation/calibration_run.hpp"
#include "radio_follow/evaluation/standing_robot.hpp"

namespace radio_follow {
namespace evaluation {

void StaticAccuracyParams::validate() const {
  require(!distances.empty(), "distances", distances.size(), "at least one distance");
  for (const double d : distances) {
    require(std::isfinite(d) && d > 0.0, "distances", d, "metres > 0");
  }
  require(directions >= 1, "directions", directions, "a count >= 1");
  require(std::isfinite(duration) && duration > settle, "duration", duration, "seconds > settle");
  require(std::isfinite(settle) && settle >= 0.0, "settle", settle, "seconds >= 0");
}

std::vector<StaticPoint> runStaticAccuracy(const Layout& layout, sim::WorldConfig world,
                                           const estimation::LocatorConfig& locator,
                                           const StaticAccuracyParams& params) {
  params.validate();
  world.hardware_seed = params.robot;
  const Layout calibrated = locatorLayoutFor(layout, world);
  sim::Rng rng(params.seed);
  std::vector<StaticPoint> points;
  for (const double distance : params.distances) {
    for (int k = 0; k < params.directions; ++k) {
      StaticPoint point;
      point.distance = distance;
      point.direction = wrapAngle(2.0 * kPi * k / params.directions);
      const Eigen::Vector3d target(distance * std::cos(point.direction),
                                   distance * std::sin(point.direction), locator.height);
      estimation::Locator estimator(calibrated, locator);
      StandingRobotSensors sensors(layout, world, params.robot, rng);
      const auto at_target = [&target](double) { return target; };
      Eigen::Vector2d sum = Eigen::Vector2d::Zero();
      Eigen::Vector2d sum_sq = Eigen::Vector2d::Zero();
      std::size_t used = 0;
      std::size_t updates = 0;
      for (double now = kLocatorUpdatePeriod; now <= params.duration + 1e-9; now += kLocatorUpdatePeriod) {
        sensors.feed(estimator, now, at_target, rng);
        const estimation::LocatorEstimate e = estimator.update(now);
        if (now < params.settle) {
          continue;
        }
        ++updates;
        if (!hasPosition(e.status)) {
          continue;
        }
        const Eigen::Vector2d p = e.position.head<2>();
        sum += p;
        sum_sq += p.cwiseAbs2();
        ++used;
      }
      if (used > 0) {
        const double n = static_cast<double>(used);
        const Eigen::Vector2d mean = sum / n;
        point.mean_error = (mean - target.head<2>()).norm();
        const Eigen::Vector2d var = (sum_sq / n - mean.cwiseAbs2()).cwiseMax(0.0);
        point.spread = std::sqrt(var.sum());
      } else {
        point.mean_error = std::nan("");
        point.spread = std::nan("");
      }
      point.usable = updates > 0 ? static_cast<double>(used) / static_cast<double>(updates) : 0.0;
      points.push_back(point);
    }
  }
  return points;
}

std::vector<WalkSample> runWalkAround(const Layout& layout, sim::WorldConfig world,
                                      const estimation::LocatorConfig& locator,
                                      const sim::TargetPath& path, double duration,
                                      const WalkAroundParams& params) {
  require(std::isfinite(duration) && duration > params.settle, "duration", duration,
          "seconds > settle");
  world.hardware_seed = params.robot;
  const Layout calibrated = locatorLayoutFor(layout, world);
  sim::Rng rng(params.seed);
  estimation::Locator estimator(calibrated, locator);
  StandingRobotSensors sensors(layout, world, params.robot, rng);
  const auto at_target = [&path, &locator](double t) {
    const Pose2 p = path.at(t).pose;
    return Eigen::Vector3d(p.x, p.y, locator.height);
  };
  std::vector<WalkSample> samples;
  for (double now = kLocatorUpdatePeriod; now <= duration + 1e-9; now += kLocatorUpdatePeriod) {
    sensors.feed(estimator, now, at_target, rng);
    const estimation::LocatorEstimate e = estimator.update(now);
    if (now < params.settle) {
      continue;
    }
    const Eigen::Vector3d truth = at_target(now);
    WalkSample s;
    s.t = now;
    s.direction = std::atan2(truth.y(), truth.x());
    s.distance = truth.head<2>().norm();
    s.usable = hasPosition(e.status);
    s.error = s.usable ? (e.position - truth).head<2>().norm() : std::nan("");
    const bool directed = s.usable || e.status == TargetStatus::kHeadingOnly;
    s.heading_error = directed
                          ? std::abs(wrapAngle(std::atan2(e.position.y(), e.position.x()) - s.direction))
                          : std::nan("");
    samples.push_back(s);
  }
  return samples;
}

std::size_t sectorOf(double direction, int sectors) {
  const double width = 2.0 * kPi / sectors;
  // Sector 0 is centred on straight ahead: shift by half a sector.
  double a = std::fmod(direction + 0.5 * width, 2.0 * kPi);
  if (a < 0.0) {
    a += 2.0 * kPi;
  }
  return std::min(static_cast<std::size_t>(a / width), static_cast<std::size_t>(sectors - 1));
}

namespace {

std::vector<DirectionSector> emptySectors(int sectors) {
  std::vector<DirectionSector> out(static_cast<std::size_t>(sectors));
  for (int k = 0; k < sectors; ++k) {
    double centre = 360.0 * k / sectors;
    out[static_cast<std::size_t>(k)].centre_deg = centre > 180.0 ? centre - 360.0 : centre;
  }
  return out;
}

}  // namespace

std::vector<DirectionSector> bySector(const std::vector<StaticPoint>& points, int sectors) {
  std::vector<DirectionSector> out = emptySectors(sectors);
  std::vector<double> usable_sum(out.size(), 0.0);
  for (const StaticPoint& p : points) {
    const std::size_t k = sectorOf(p.direction, sectors);
    DirectionSector& s = out[k];
    ++s.count;
    usable_sum[k] += p.usable;
    // A point without any estimate is the worst a sector can have.
    s.max_mean_error = std::isfinite(p.mean_error) ? std::max(s.max_mean_error, p.mean_error)
                                                   : std::numeric_limits<double>::infinity();
    s.max_spread = std::isfinite(p.spread) ? std::max(s.max_spread, p.spread)
                                           : std::numeric_limits<double>::infinity();
  }
  for (std::size_t k = 0; k < out.size(); ++k) {
    out[k].usable = out[k].count > 0 ? usable_sum[k] / static_cast<double>(out[k].count) : 0.0;
  }
  return out;
}

std::vector<DirectionSector> bySector(const std::vector<WalkSample>& samples, int sectors) {
  std::vector<DirectionSector> out = emptySectors(sectors);
  std::vector<std::vector<double>> errors(out.size());
  std::vector<std::vector<double>> headings(out.size());
  std::vector<std::size_t> seen(out.size(), 0);
  for (const WalkSample& w : samples) {
    const std::size_t k = sectorOf(w.direction, sectors);
    ++seen[k];
    if (w.usable) {
      errors[k].push_back(w.error);
    }
    if (std::isfinite(w.heading_error)) {
      headings[k].push_back(rad2deg(w.heading_error));
    }
  }
  for (std::size_t k = 0; k < out.size(); ++k) {
    out[k].count = errors[k].size();
    out[k].usable =
        seen[k] > 0 ? static_cast<double>(errors[k].size()) / static_cast<double>(seen[k]) : 0.0;
    if (!errors[k].empty()) {
      out[k].median_error = quantile(errors[k], 0.5);
      out[k].p95_error = quantile(errors[k], 0.95);
      out[k].max_mean_error = *std::max_element(errors[k].begin(), errors[k].end());
    }
    out[k].heading_median_deg = headings[k].empty() ? std::nan("") : quantile(headings[k], 0.5);
    out[k].heading_p95_deg = headings[k].empty() ? std::nan("") : quantile(headings[k], 0.95);
  }
  return out;
}

std::vector<DistanceRow> byDistance(const std::vector<StaticPoint>& points,
                                    const std::vector<double>& distances) {
  std::vector<DistanceRow> rows;
  for (const double d : distances) {
    DistanceRow row;
    row.distance = d;
    std::vector<double> errors;
    for (const StaticPoint& p : points) {
      if (p.distance != d) {
        continue;
      }
      const double error =
          std::isfinite(p.mean_error) ? p.mean_error : std::numeric_limits<double>::infinity();
      errors.push_back(error);
      row.max_mean_error = std::max(row.max_mean_error, error);
      row.max_spread =
          std::max(row.max_spread,
                   std::isfinite(p.spread) ? p.spread : std::numeric_limits<double>::infinity());
    }
    row.median_mean_error = quantile(errors, 0.5);
    rows.push_back(row);
  }
  return rows;
}

Layout twrOnly(const Layout& layout) {
  Layout out = layout;
  out.aoa_boards.clear();
  return out;
}

}  // namespace evaluation
}  // namespace radio_follow
