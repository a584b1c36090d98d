// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "radio_follow/config/layout.hpp"
#include "radio_follow/estimation/locator_types.hpp"
#include "radio_follow/estimation/measurement_models.hpp"

namespace radio_follow {
namespace estimation {

/// How the placement advisor evaluates a layout.
struct AdvisorConfig {
  double extent = 10.0;        ///< the map covers [-extent, extent]^2 around the robot, m
  double resolution = 0.25;    ///< map cell size, m
  /// Height of the tag above the fixed frame's origin, m.
  double target_height = kDefaultTargetHeight;
  bool planar = true;          ///< true: 2D bound (height known, the locator's 2D mode)
  /// Bearings carry an elevation (the locator's default).
  bool use_elevation = LocatorConfig().use_elevation;
  /// m, TDoA differences (the locator's default; no table in the simulator).
  double tdoa_sigma = LocatorConfig().tdoa_sigma;
  std::vector<double> rings{2.0, 4.0, 8.0};  ///< ring radii of the summary, m
  int ring_samples = 360;                    ///< points per ring
  int sectors = 16;                          ///< direction sectors, sector 0 centred ahead
  double weak_factor = 2.0;         ///< a sector is weak when its bound exceeds this x ring median
  double min_module_spacing = 0.3;  ///< m, thesis Section 4.9: closer TWR modules
  double collinear_tolerance = 0.02;  ///< m, rms distance from the best-fit line/plane
  double fov_gap_radius = 4.0;        ///< m, where board field-of-view gaps are sought

  /// Throws ParamError naming the first invalid field.
  void validate() const;
};

/// The noise-free observations the locator would use for a target at p, with the
/// simulator's measured sigmas: a range from every TWR module (sigma from the thesis's
/// Table 3.1 at that distance), the bearing of every board whose field of view contains p
/// (the locator's all_in_fov selection; azimuth sigma from Tables 3.2-3.7, the elevation
/// sigma equal to it as in the simulator), and the TDoA differences against the first
/// anchor (independent, with tdoa_sigma, as the locator treats them).
ObservationSet advisorObservations(const Layout& layout, const Eigen::Vector3d& p,
                                   const AdvisorConfig& config);

/// Cramer-Rao bound on the position error at one target position.
struct PointBound {
  bool observable = false;  ///< false: the Fisher information is singular there
  double rms = 0.0;         ///< sqrt(trace(CRLB)), m
  double worst_axis = 0.0;  ///< sqrt(largest eigenvalue of the CRLB), m
  int bearings = 0;         ///< boards with the target in their field of view
};

PointBound boundAt(const Layout& layout, const Eigen::Vector3d& p, const AdvisorConfig& config);

/// The bound over a square grid centred on the robot; cells row-major, y outer, x inner.
struct BoundMap {
  std::vector<double> coordinates;  ///< cell centres along x and along y (the same), m
  std::vector<PointBound> cells;
  const PointBound& at(std::size_t ix, std::size_t iy) const {
    return cells[iy * coordinates.size() + ix];
  }
};

BoundMap computeMap(const Layout& layout, const AdvisorConfig& config);

/// Bound statistics on one ring around the robot.
struct RingSummary {
  double radius = 0.0;
  double median = 0.0;  ///< of the rms bound over the observable points, m (NaN if none)
  double worst = 0.0;   ///< m; infinity when some point is unobservable
  double unobservable_fraction = 0.0;
};

/// One direction sector: its worst rms bound relative to the ring's median.
struct SectorSummary {
  double centre_deg = 0.0;  ///< direction of the sector's centre, CCW from ahead (+x)
  double worst_ratio =
      0.0;  ///< max over rings of (sector worst / ring median); inf if unobservable
  bool weak = false;
};

struct PlacementSummary {
  std::vector<RingSummary> rings;
  std::vector<SectorSummary> sectors;
  std::vector<std::string> warnings;
};

/// Ring and sector statistics plus the guideline warnings of the thesis (Section 4.9 and
/// Appendix C): TWR modules too close together, collinear or coplanar modules (mirror
/// ambiguity a range-only layout cannot resolve), too few modules for 3D, directions no
/// board sees, and unobservable directions.
PlacementSummary summarize(const Layout& layout, const AdvisorConfig& config);

/// The guideline warnings alone (part of summarize()).
std::vector<std::string> layoutWarnings(const Layout& layout, const AdvisorConfig& config);

}  // namespace estimation
}  // namespace radio_follow
