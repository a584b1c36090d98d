// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "radio_follow/common/angles.hpp"
#include "radio_follow/config/layout.hpp"

namespace radio_follow {
namespace estimation {

/// A polygon in the robot's xy-plane (base_link), vertices in either winding order.
using Polygon = std::vector<Eigen::Vector2d>;

/// True when p lies inside the polygon or on its boundary (within 1e-9 m).
bool insidePolygon(const Polygon& polygon, const Eigen::Vector2d& p);

/// What the optimised layout is judged by: a statistic of the position-error bound
/// sqrt(trace CRLB) over the target grid (doc/placement_advisor.md, "Optimisation").
enum class PlacementObjective {
  kMean,  ///< the mean bound
  kP90,   ///< the 90th percentile (nearest rank): weak sectors count, one bad point does not
  kMax,   ///< the worst point (seed 004's CRLB peak)
};
std::string toString(PlacementObjective objective);
/// "mean" / "p90" / "max"; throws ParamError naming `name` otherwise.
PlacementObjective parsePlacementObjective(const std::string& text, const std::string& name);

/// Where the person is expected: a sector of an annulus around the robot, sampled on rings.
struct TargetArea {
  double min_range = 1.5;             ///< m, first ring
  double max_range = 6.0;             ///< m, last ring (included when a whole step away)
  double range_step = 1.5;            ///< m between rings
  double from = -kPi;                 ///< rad, sector start (CCW from ahead, +x)
  double to = kPi;                    ///< rad, sector end
  double angle_step = deg2rad(10.0);  ///< rad between points on a ring
  double height = kDefaultTargetHeight;  ///< m, tag height in base_link

  /// The target grid: rings from min_range to max_range, points from `from` to `to`
  /// (a full circle without repeating its end), half a step off the sector's start so
  /// that no point sits exactly on a board's field-of-view edge along the robot's axes.
  std::vector<Eigen::Vector3d> points() const;
};

/// The user's mounting region for the placement optimiser (config/placement/*.yaml):
/// the robot's outline, keep-out zones, the candidate grid, how many TWR modules and AoA
/// boards, the CTU thesis's mounting rules (Section 3.3: modules spread and at least
/// `twr_min_spacing` apart; boards on an outline facing outward, not overlapping) and the
/// target area the bound is judged over.
struct MountingRegion {
  std::string name = "region";
  Polygon outline;                ///< the robot's top outline; every sensor inside it
  std::vector<Polygon> keep_out;  ///< no sensor inside or on the edge of one of these
  double grid_spacing = 0.1;      ///< m, candidate module grid and board step

  int twr_count = 3;
  double twr_height = 0.1;       ///< m, module antenna height in base_link
  double twr_min_spacing = 0.3;  ///< m between any two modules
  /// m: with 3 or more modules, their rms distance from their best-fit line in the ground
  /// plane is at least this. The CRLB is a local bound and misses the mirror image ranges
  /// from modules in one line allow (CTU thesis Section 3.3: not mounted in one line).
  double twr_min_off_line = 0.05;

  int aoa_count = 0;
  double aoa_height = 0.25;       ///< m, board centre height
  Polygon aoa_mount;              ///< boards sit on its edges facing outward; empty = outline
  double aoa_min_spacing = 0.13;  ///< m between board centres (a 12.6 cm board in its case)
  AoaBoardKind aoa_kind = AoaBoardKind::kXplrAoa1;
  double aoa_field_of_view = deg2rad(70.0);  ///< rad, half-angle (the layout's default)

  std::string uwb_anchor_id = "DA12";  ///< the target's anchor ID for the written layout
  TargetArea target;
  PlacementObjective objective = PlacementObjective::kP90;

  /// Throws ParamError naming the first invalid field (YAML names).
  void validate() const;
  /// The polygon boards are mounted on: aoa_mount, or the outline when that is empty.
  const Polygon& boardMount() const { return aoa_mount.empty() ? outline : aoa_mount; }
};

/// Reads a region from YAML text and validates it. A key the format does not have, a
/// value of the wrong type or out of range throws ParamError naming it, its value and
/// what is expected; `origin` names the source in messages.
MountingRegion parseMountingRegion(const std::string& yaml_text, const std::string& origin);
MountingRegion loadMountingRegionFile(const std::string& path);

/// A place a sensor can go: position in base_link and, for boards, the boresight's yaw.
struct MountCandidate {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  double yaw = 0.0;  ///< rad; boards face outward (the edge's outward normal)
};

/// Module candidates: the points of a square grid of `grid_spacing` starting at the
/// outline's bounding-box corner (min x, min y), inside or on the outline and outside every
/// keep-out zone, at twr_height.
std::vector<MountCandidate> moduleCandidates(const MountingRegion& region);
/// Board candidates: points along every edge of boardMount() about `grid_spacing` apart
/// (the middle of equal pieces of the edge), facing the edge's outward normal, at
/// aoa_height, outside every keep-out zone.
std::vector<MountCandidate> boardCandidates(const MountingRegion& region);

}  // namespace estimation
}  // namespace radio_follow
