// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/estimation/placement_advisor.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "radio_follow/common/angles.hpp"
#include "radio_follow/common/median.hpp"
#include "radio_follow/common/param_error.hpp"
#include "radio_follow/estimation/fisher.hpp"
#include "radio_follow/models/sensor_tables.hpp"

namespace radio_follow {
namespace estimation {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

std::string format(const char* pattern, double a, double b = 0.0, double c = 0.0) {
  char buffer[160];
  std::snprintf(buffer, sizeof(buffer), pattern, a, b, c);
  return buffer;
}

bool inBoardFieldOfView(const AoaBoard& board, const Eigen::Vector3d& p) {
  const Eigen::Vector3d v = p - board.position;
  const double n = v.norm();
  if (n < 1e-9) {
    return false;
  }
  const Eigen::Vector3d boresight = board.orientation * Eigen::Vector3d::UnitX();
  return boresight.dot(v) / n >= std::cos(board.field_of_view);
}

/// Singular values of the centred point cloud, largest first (dimension `dims`).
Eigen::VectorXd spread(const std::vector<Eigen::Vector3d>& points, int dims) {
  Eigen::MatrixXd a(static_cast<Eigen::Index>(points.size()), dims);
  Eigen::VectorXd mean = Eigen::VectorXd::Zero(dims);
  for (const auto& p : points) {
    mean += p.head(dims);
  }
  mean /= static_cast<double>(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    a.row(static_cast<Eigen::Index>(i)) = (points[i].head(dims) - mean).transpose();
  }
  return Eigen::JacobiSVD<Eigen::MatrixXd>(a).singularValues();
}

/// rms distance of the points from their best-fit affine subspace of dimension `rank`.
double offSubspaceRms(const std::vector<Eigen::Vector3d>& points, int dims, int rank) {
  const Eigen::VectorXd s = spread(points, dims);
  double sum = 0.0;
  for (Eigen::Index i = rank; i < s.size(); ++i) {
    sum += s(i) * s(i);
  }
  return std::sqrt(sum / static_cast<double>(points.size()));
}

Eigen::Vector3d ringPoint(double radius, double azimuth, double height) {
  return {radius * std::cos(azimuth), radius * std::sin(azimuth), height};
}

void fieldOfViewGaps(const Layout& layout, const AdvisorConfig& config,
                     std::vector<std::string>& warnings) {
  constexpr int kSteps = 720;
  std::vector<bool> seen(kSteps);
  for (int k = 0; k < kSteps; ++k) {
    const Eigen::Vector3d p =
        ringPoint(config.fov_gap_radius, 2.0 * kPi * k / kSteps, config.target_height);
    seen[static_cast<std::size_t>(k)] =
        std::any_of(layout.aoa_boards.begin(), layout.aoa_boards.end(),
                    [&](const AoaBoard& b) { return inBoardFieldOfView(b, p); });
  }
  if (std::none_of(seen.begin(), seen.end(), [](bool s) { return s; })) {
    warnings.push_back(format("no AoA board sees the target at %.1f m and %.2f m height",
                              config.fov_gap_radius, config.target_height));
    return;
  }
  // Start the scan at a seen direction so that a gap across 180 deg stays in one piece.
  int start = 0;
  while (!seen[static_cast<std::size_t>(start)]) {
    ++start;
  }
  for (int i = 0; i < kSteps;) {
    const int k = (start + i) % kSteps;
    if (seen[static_cast<std::size_t>(k)]) {
      ++i;
      continue;
    }
    int length = 0;
    while (i + length < kSteps && !seen[static_cast<std::size_t>((start + i + length) % kSteps)]) {
      ++length;
    }
    const double from = rad2deg(wrapAngle(2.0 * kPi * k / kSteps));
    const double to = rad2deg(wrapAngle(2.0 * kPi * (k + length - 1) / kSteps));
    warnings.push_back(
        format("no AoA board's field of view covers directions %.1f to %.1f deg "
               "at %.1f m: bearings are missing there",
               from, to, config.fov_gap_radius));
    i += length;
  }
}

}  // namespace

void AdvisorConfig::validate() const {
  require(std::isfinite(extent) && extent > 0.0, "extent", extent, "a positive size in metres");
  require(std::isfinite(resolution) && resolution > 0.0 && resolution <= extent, "resolution",
          resolution, "a positive cell size in metres, at most the extent");
  require(extent / resolution <= 2000.0, "resolution", resolution,
          "at most 2000 cells per half axis (extent / resolution)");
  require(std::isfinite(target_height), "height", target_height, "a finite height in metres");
  require(std::isfinite(tdoa_sigma) && tdoa_sigma > 0.0, "tdoa_sigma", tdoa_sigma,
          "a positive standard deviation in metres");
  require(!rings.empty(), "rings", rings.size(), "at least one ring radius");
  for (const double r : rings) {
    require(std::isfinite(r) && r > 0.0, "rings", r, "positive radii in metres");
  }
  require(ring_samples >= sectors, "ring_samples", ring_samples, "at least one point per sector");
  require(sectors >= 1 && sectors <= 360, "sectors", sectors, "1 to 360 sectors");
  require(weak_factor > 1.0, "weak_factor", weak_factor, "a factor above 1");
  require(min_module_spacing >= 0.0, "min_module_spacing", min_module_spacing, "metres >= 0");
  require(collinear_tolerance >= 0.0, "collinear_tolerance", collinear_tolerance, "metres >= 0");
  require(fov_gap_radius > 0.0, "fov_gap_radius", fov_gap_radius, "a positive radius in metres");
}

ObservationSet advisorObservations(const Layout& layout, const Eigen::Vector3d& p,
                                   const AdvisorConfig& config) {
  ObservationSet obs;
  for (const auto& module : layout.twr_modules) {
    RangeObservation z;
    z.module = module.position;
    z.range = (p - module.position).norm();
    z.sigma = models::uwbRangeError(z.range).sigma;
    obs.ranges.push_back(z);
  }
  for (const auto& board : layout.aoa_boards) {
    if (!inBoardFieldOfView(board, p)) {
      continue;
    }
    BearingObservation z;
    z.board = board.position;
    z.rotation = board.orientation.toRotationMatrix();
    const Eigen::Vector2d ae = predictBearing(p, z.board, z.rotation);
    z.azimuth = ae(0);
    z.elevation = ae(1);
    // The tables use the device's clockwise azimuth; their sigma is symmetric enough that
    // the sign matters little, but the lookup follows the simulator exactly.
    const double sigma =
        models::aoaError(board.kind, -z.azimuth, (p - board.position).norm()).azimuth_sigma;
    z.sigma_azimuth = sigma;
    z.sigma_elevation = sigma;
    z.use_elevation = config.use_elevation;
    obs.bearings.push_back(z);
  }
  for (std::size_t i = 1; i < layout.tdoa_anchors.size(); ++i) {
    TdoaObservation z;
    z.anchor_a = layout.tdoa_anchors[i].position;
    z.anchor_b = layout.tdoa_anchors[0].position;
    z.difference = (p - z.anchor_a).norm() - (p - z.anchor_b).norm();
    z.sigma = config.tdoa_sigma;
    obs.tdoas.push_back(z);
  }
  return obs;
}

PointBound boundAt(const Layout& layout, const Eigen::Vector3d& p, const AdvisorConfig& config) {
  const ObservationSet obs = advisorObservations(layout, p, config);
  PointBound bound;
  bound.bearings = static_cast<int>(obs.bearings.size());
  const auto crlb = positionCrlb(fisherInformation(obs, p), config.planar);
  if (!crlb) {
    bound.rms = kInf;
    bound.worst_axis = kInf;
    return bound;
  }
  bound.observable = true;
  bound.rms = std::sqrt(crlb->trace());
  bound.worst_axis = std::sqrt(
      std::max(0.0, Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(*crlb, Eigen::EigenvaluesOnly)
                        .eigenvalues()
                        .maxCoeff()));
  return bound;
}

BoundMap computeMap(const Layout& layout, const AdvisorConfig& config) {
  config.validate();
  BoundMap map;
  const int half = static_cast<int>(std::floor(config.extent / config.resolution + 1e-9));
  for (int i = -half; i <= half; ++i) {
    map.coordinates.push_back(i * config.resolution);
  }
  map.cells.reserve(map.coordinates.size() * map.coordinates.size());
  for (const double y : map.coordinates) {
    for (const double x : map.coordinates) {
      map.cells.push_back(boundAt(layout, {x, y, config.target_height}, config));
    }
  }
  return map;
}

std::vector<std::string> layoutWarnings(const Layout& layout, const AdvisorConfig& config) {
  std::vector<std::string> warnings;
  const auto& modules = layout.twr_modules;
  for (std::size_t i = 0; i < modules.size(); ++i) {
    for (std::size_t j = i + 1; j < modules.size(); ++j) {
      const double d = (modules[i].position - modules[j].position).norm();
      if (d < config.min_module_spacing) {
        warnings.push_back("TWR modules " + modules[i].id + " and " + modules[j].id +
                           format(" are %.2f m apart (< %.2f m): their ranges carry nearly "
                                  "the same direction information (thesis Section 4.9)",
                                  d, config.min_module_spacing));
      }
    }
  }
  std::vector<Eigen::Vector3d> positions;
  for (const auto& m : modules) {
    positions.push_back(m.position);
  }
  const bool bearings = !layout.aoa_boards.empty();
  // Ranges alone fix the target only up to a mirror image through the modules' line (2D)
  // or plane (3D); boards facing the target resolve the side, so only warn without them.
  if (!bearings && !modules.empty()) {
    if (modules.size() < 3 || offSubspaceRms(positions, 2, 1) < config.collinear_tolerance) {
      warnings.push_back(
          "the TWR modules are collinear in the ground plane (or fewer than 3): ranges cannot "
          "tell on which side of their line the target is (mirror ambiguity)");
    }
    if (!config.planar) {
      if (modules.size() < 4) {
        warnings.push_back(
            format("too few TWR modules for 3D: %.0f, need 4 not in one plane "
                   "(or AoA boards with elevation)",
                   static_cast<double>(modules.size())));
      } else if (offSubspaceRms(positions, 3, 2) < config.collinear_tolerance) {
        warnings.push_back(
            "the TWR modules lie in one plane: in 3D the target's height is mirrored through "
            "it and poorly observed near it; mount one module higher or lower");
      }
    }
  }
  if (!config.planar && bearings && !config.use_elevation && modules.size() < 4) {
    warnings.push_back("3D without elevation needs 4 TWR modules not in one plane");
  }
  if (bearings) {
    fieldOfViewGaps(layout, config, warnings);
  }
  return warnings;
}

PlacementSummary summarize(const Layout& layout, const AdvisorConfig& config) {
  config.validate();
  PlacementSummary summary;
  summary.warnings = layoutWarnings(layout, config);
  const double width = 2.0 * kPi / config.sectors;
  std::vector<double> sector_ratio(static_cast<std::size_t>(config.sectors), 0.0);
  for (const double radius : config.rings) {
    std::vector<double> observable;
    std::vector<double> sector_worst(static_cast<std::size_t>(config.sectors), 0.0);
    RingSummary ring;
    ring.radius = radius;
    int unobservable = 0;
    for (int k = 0; k < config.ring_samples; ++k) {
      // Half a step off the axes: the board seams and the sector edges sit on them.
      const double azimuth = 2.0 * kPi * (k + 0.5) / config.ring_samples;
      const PointBound b =
          boundAt(layout, ringPoint(radius, azimuth, config.target_height), config);
      if (b.observable) {
        observable.push_back(b.rms);
      } else {
        ++unobservable;
      }
      const auto sector = static_cast<std::size_t>(std::floor((azimuth + 0.5 * width) / width)) %
                          sector_worst.size();
      sector_worst[sector] = std::max(sector_worst[sector], b.rms);
    }
    ring.median = median(observable);
    ring.worst = unobservable > 0 ? kInf : *std::max_element(observable.begin(), observable.end());
    ring.unobservable_fraction = static_cast<double>(unobservable) / config.ring_samples;
    for (std::size_t s = 0; s < sector_worst.size(); ++s) {
      const double ratio = observable.empty() ? kInf : sector_worst[s] / ring.median;
      sector_ratio[s] = std::max(sector_ratio[s], ratio);
    }
    if (unobservable > 0) {
      summary.warnings.push_back(
          format("the position is unobservable on %.0f%% of the %.1f m "
                 "ring",
                 100.0 * ring.unobservable_fraction, radius));
    }
    summary.rings.push_back(ring);
  }
  for (std::size_t s = 0; s < sector_ratio.size(); ++s) {
    SectorSummary sector;
    sector.centre_deg = rad2deg(wrapAngle(width * static_cast<double>(s)));
    sector.worst_ratio = sector_ratio[s];
    sector.weak = !(sector_ratio[s] <= config.weak_factor);
    summary.sectors.push_back(sector);
  }
  return summary;
}

}  // namespace estimation
}  // namespace radio_follow
