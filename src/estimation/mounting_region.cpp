// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/estimation/mounting_region.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>

#include "radio_follow/common/geometry.hpp"
#include "radio_follow/common/param_error.hpp"
#include "radio_follow/common/param_keys.hpp"
#include "radio_follow/common/yaml_keys.hpp"

namespace radio_follow {
namespace estimation {
namespace {

constexpr double kEdgeTolerance = 1e-9;  // m: a point this close to an edge is on it

double signedArea(const Polygon& polygon) {
  double area = 0.0;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Eigen::Vector2d& a = polygon[i];
    const Eigen::Vector2d& b = polygon[(i + 1) % polygon.size()];
    area += a.x() * b.y() - b.x() * a.y();
  }
  return 0.5 * area;
}

bool inKeepOut(const MountingRegion& region, const Eigen::Vector2d& p) {
  return std::any_of(region.keep_out.begin(), region.keep_out.end(),
                     [&](const Polygon& zone) { return insidePolygon(zone, p); });
}

Polygon readPolygon(const YAML::Node& node, const std::string& name) {
  const std::string expected = "a list of at least 3 points [x, y] in metres";
  if (!node.IsDefined() || !node.IsSequence()) {
    throw ParamError(name, yamlValueString(node), expected);
  }
  Polygon polygon;
  for (const auto& item : node) {
    const std::vector<double> xy = yamlNumbers(item, name, expected);
    if (xy.size() != 2) {
      throw ParamError(name, yamlValueString(node), expected);
    }
    polygon.emplace_back(xy[0], xy[1]);
  }
  return polygon;
}

void requirePolygon(const Polygon& polygon, const std::string& name) {
  require(polygon.size() >= 3, name, polygon.size(), "at least 3 points [x, y] in metres");
  require(std::abs(signedArea(polygon)) > 1e-6, name, signedArea(polygon),
          "a polygon enclosing an area (its points are on one line)");
}

}  // namespace

bool insidePolygon(const Polygon& polygon, const Eigen::Vector2d& p) {
  bool inside = false;
  for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
    const Eigen::Vector2d& a = polygon[i];
    const Eigen::Vector2d& b = polygon[j];
    if (distanceToSegment(p, a, b) <= kEdgeTolerance) {
      return true;
    }
    // Even-odd ray casting along +x.
    if ((a.y() > p.y()) != (b.y() > p.y()) &&
        p.x() < (b.x() - a.x()) * (p.y() - a.y()) / (b.y() - a.y()) + a.x()) {
      inside = !inside;
    }
  }
  return inside;
}

std::string toString(PlacementObjective objective) {
  switch (objective) {
    case PlacementObjective::kMean:
      return "mean";
    case PlacementObjective::kMax:
      return "max";
    case PlacementObjective::kP90:
    default:
      return "p90";
  }
}

PlacementObjective parsePlacementObjective(const std::string& text, const std::string& name) {
  for (const auto o :
       {PlacementObjective::kMean, PlacementObjective::kP90, PlacementObjective::kMax}) {
    if (text == toString(o)) {
      return o;
    }
  }
  throw ParamError(name, paramValueString(text), "'mean', 'p90' or 'max'");
}

std::vector<Eigen::Vector3d> TargetArea::points() const {
  std::vector<Eigen::Vector3d> out;
  const double span = to - from;
  const bool circle = span >= 2.0 * kPi - 1e-9;
  // A closed sector keeps both edges; a circle would repeat its end.
  const int steps = static_cast<int>(std::floor(span / angle_step + 1e-9));
  const int count = circle ? steps : steps + 1;
  const double offset = circle ? 0.5 * angle_step : 0.0;
  for (double r = min_range; r <= max_range + 1e-9; r += range_step) {
    for (int k = 0; k < count; ++k) {
      const double a = from + offset + k * angle_step;
      out.emplace_back(r * std::cos(a), r * std::sin(a), height);
    }
  }
  return out;
}

void MountingRegion::validate() const {
  require(!name.empty(), "name", name, "a non-empty name (the written layout's file name)");
  requirePolygon(outline, "outline");
  for (std::size_t i = 0; i < keep_out.size(); ++i) {
    requirePolygon(keep_out[i], "keep_out[" + std::to_string(i) + "]");
  }
  require(std::isfinite(grid_spacing) && grid_spacing >= 0.01, "grid_spacing", grid_spacing,
          "a candidate spacing of at least 0.01 m");
  require(twr_count >= 0 && twr_count <= 16, "twr_modules.count", twr_count, "0 to 16 modules");
  require(aoa_count >= 0 && aoa_count <= 16, "aoa_boards.count", aoa_count, "0 to 16 boards");
  require(twr_count + aoa_count >= 1, "twr_modules.count", twr_count,
          "at least one sensor (twr_modules.count + aoa_boards.count >= 1)");
  require(std::isfinite(twr_height), "twr_modules.height", twr_height, "a finite height in m");
  require(std::isfinite(twr_min_spacing) && twr_min_spacing >= 0.0, "twr_modules.min_spacing",
          twr_min_spacing, "a distance >= 0 m");
  require(std::isfinite(twr_min_off_line) && twr_min_off_line >= 0.0, "twr_modules.min_off_line",
          twr_min_off_line, "a distance >= 0 m");
  require(std::isfinite(aoa_height), "aoa_boards.height", aoa_height, "a finite height in m");
  require(std::isfinite(aoa_min_spacing) && aoa_min_spacing >= 0.0, "aoa_boards.min_spacing",
          aoa_min_spacing, "a distance >= 0 m");
  require(aoa_field_of_view > 0.0 && aoa_field_of_view <= kPi / 2.0, "aoa_boards.field_of_view_deg",
          rad2deg(aoa_field_of_view), "a half-angle in (0, 90] degrees");
  if (!aoa_mount.empty()) {
    requirePolygon(aoa_mount, "aoa_boards.mount_outline");
    for (const auto& p : aoa_mount) {
      require(insidePolygon(outline, p), "aoa_boards.mount_outline", p.transpose(),
              "points inside the outline (boards are on the robot)");
    }
  }
  require(!twr_count || !uwb_anchor_id.empty(), "target.uwb_anchor_id", uwb_anchor_id,
          "the target's UWB anchor ID when modules are placed");
  require(std::isfinite(target.min_range) && target.min_range > 0.0, "target.min_range",
          target.min_range, "a distance > 0 m");
  require(std::isfinite(target.max_range) && target.max_range >= target.min_range,
          "target.max_range", target.max_range, "a distance >= target.min_range in m");
  require(std::isfinite(target.range_step) && target.range_step > 0.0, "target.range_step",
          target.range_step, "a step > 0 m");
  require(std::isfinite(target.from) && target.from >= -2.0 * kPi, "target.from_deg",
          rad2deg(target.from), "an angle >= -360 deg");
  require(std::isfinite(target.to) && target.to > target.from &&
              target.to - target.from <= 2.0 * kPi + 1e-9,
          "target.to_deg", rad2deg(target.to), "an angle above from_deg, at most 360 deg beyond");
  require(std::isfinite(target.angle_step) && target.angle_step >= deg2rad(0.5),
          "target.angle_step_deg", rad2deg(target.angle_step), "a step of at least 0.5 deg");
  require(std::isfinite(target.height), "target.height", target.height, "a finite height in m");
  require(target.points().size() <= 20000, "target.angle_step_deg", rad2deg(target.angle_step),
          "at most 20000 target points (coarser range_step or angle_step_deg)");
}

MountingRegion parseMountingRegion(const std::string& yaml_text, const std::string& origin) {
  const YAML::Node root = loadConfigYaml(yaml_text, "region", origin);
  requireYamlKeys(root,
                  {"name", "outline", "keep_out", "grid_spacing", "twr_modules", "aoa_boards",
                   "target", "objective"},
                  "");
  MountingRegion r;
  r.name = yamlScalar<std::string>(root, "name", "", "a name", &r.name);
  r.outline = readPolygon(root["outline"], "outline");
  const YAML::Node keep_out = root["keep_out"];
  if (keep_out.IsDefined() && !keep_out.IsNull()) {
    if (!keep_out.IsSequence()) {
      throw ParamError("keep_out", yamlValueString(keep_out), "a list of polygons");
    }
    for (std::size_t i = 0; i < keep_out.size(); ++i) {
      r.keep_out.push_back(readPolygon(keep_out[i], "keep_out[" + std::to_string(i) + "]"));
    }
  }
  r.grid_spacing = yamlScalar<double>(root, "grid_spacing", "", "metres", &r.grid_spacing);
  const std::string objective = toString(r.objective);
  r.objective = parsePlacementObjective(
      yamlScalar<std::string>(root, "objective", "", "mean, p90 or max", &objective), "objective");

  const YAML::Node twr = root["twr_modules"];
  if (twr.IsDefined() && !twr.IsNull()) {
    requireYamlKeys(twr, {"count", "height", "min_spacing", "min_off_line"}, "twr_modules.");
    r.twr_count = yamlScalar<int>(twr, "count", "twr_modules.", "a whole number", &r.twr_count);
    r.twr_height = yamlScalar<double>(twr, "height", "twr_modules.", "metres", &r.twr_height);
    r.twr_min_spacing =
        yamlScalar<double>(twr, "min_spacing", "twr_modules.", "metres", &r.twr_min_spacing);
    r.twr_min_off_line =
        yamlScalar<double>(twr, "min_off_line", "twr_modules.", "metres", &r.twr_min_off_line);
  }
  const YAML::Node aoa = root["aoa_boards"];
  if (aoa.IsDefined() && !aoa.IsNull()) {
    requireYamlKeys(
        aoa, {"count", "height", "mount_outline", "min_spacing", "kind", "field_of_view_deg"},
        "aoa_boards.");
    r.aoa_count = yamlScalar<int>(aoa, "count", "aoa_boards.", "a whole number", &r.aoa_count);
    r.aoa_height = yamlScalar<double>(aoa, "height", "aoa_boards.", "metres", &r.aoa_height);
    if (aoa["mount_outline"].IsDefined() && !aoa["mount_outline"].IsNull()) {
      r.aoa_mount = readPolygon(aoa["mount_outline"], "aoa_boards.mount_outline");
    }
    r.aoa_min_spacing =
        yamlScalar<double>(aoa, "min_spacing", "aoa_boards.", "metres", &r.aoa_min_spacing);
    const std::string kind = toString(r.aoa_kind);
    const std::string read = yamlScalar<std::string>(aoa, "kind", "aoa_boards.", "a kind", &kind);
    require(read == "xplr_aoa_1" || read == "ant_b10", "aoa_boards.kind", read,
            "'xplr_aoa_1' or 'ant_b10'");
    r.aoa_kind = read == "ant_b10" ? AoaBoardKind::kAntB10 : AoaBoardKind::kXplrAoa1;
    const double fov = rad2deg(r.aoa_field_of_view);
    r.aoa_field_of_view = deg2rad(yamlScalar<double>(aoa, "field_of_view_deg", "aoa_boards.",
                                                     "a half-angle in degrees", &fov));
  }
  const YAML::Node target = root["target"];
  if (target.IsDefined() && !target.IsNull()) {
    requireYamlKeys(target,
                    {"uwb_anchor_id", "min_range", "max_range", "range_step", "from_deg", "to_deg",
                     "angle_step_deg", "height"},
                    "target.");
    TargetArea& t = r.target;
    r.uwb_anchor_id = normalizeId(
        yamlScalar<std::string>(target, "uwb_anchor_id", "target.", "an ID", &r.uwb_anchor_id));
    t.min_range = yamlScalar<double>(target, "min_range", "target.", "metres", &t.min_range);
    t.max_range = yamlScalar<double>(target, "max_range", "target.", "metres", &t.max_range);
    t.range_step = yamlScalar<double>(target, "range_step", "target.", "metres", &t.range_step);
    const double from = rad2deg(t.from);
    const double to = rad2deg(t.to);
    const double step = rad2deg(t.angle_step);
    t.from = deg2rad(yamlScalar<double>(target, "from_deg", "target.", "degrees", &from));
    t.to = deg2rad(yamlScalar<double>(target, "to_deg", "target.", "degrees", &to));
    t.angle_step =
        deg2rad(yamlScalar<double>(target, "angle_step_deg", "target.", "degrees", &step));
    t.height = yamlScalar<double>(target, "height", "target.", "metres", &t.height);
  }
  r.validate();
  return r;
}

MountingRegion loadMountingRegionFile(const std::string& path) {
  return parseMountingRegion(readConfigFile(path, "region", "a readable region YAML file"), path);
}

std::vector<MountCandidate> moduleCandidates(const MountingRegion& region) {
  Eigen::Vector2d lo = region.outline.front();
  Eigen::Vector2d hi = lo;
  for (const auto& p : region.outline) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const double s = region.grid_spacing;
  std::vector<MountCandidate> out;
  // From the bounding box's corner: a rectangular outline a whole number of steps long
  // has its corners (where the thesis puts modules) among the candidates.
  for (long iy = 0; lo.y() + iy * s <= hi.y() + 1e-9; ++iy) {
    for (long ix = 0; lo.x() + ix * s <= hi.x() + 1e-9; ++ix) {
      const Eigen::Vector2d p(lo.x() + ix * s, lo.y() + iy * s);
      if (insidePolygon(region.outline, p) && !inKeepOut(region, p)) {
        MountCandidate c;
        c.position = {p.x(), p.y(), region.twr_height};
        out.push_back(c);
      }
    }
  }
  return out;
}

std::vector<MountCandidate> boardCandidates(const MountingRegion& region) {
  const Polygon& mount = region.boardMount();
  // Outward normal: the edge direction turned clockwise for a counter-clockwise polygon.
  const double turn = signedArea(mount) > 0.0 ? -1.0 : 1.0;
  std::vector<MountCandidate> out;
  for (std::size_t i = 0; i < mount.size(); ++i) {
    const Eigen::Vector2d a = mount[i];
    const Eigen::Vector2d edge = mount[(i + 1) % mount.size()] - a;
    const double length = edge.norm();
    if (length < 1e-9) {
      continue;
    }
    const Eigen::Vector2d normal = turn * Eigen::Vector2d(-edge.y(), edge.x()) / length;
    const long pieces = std::max(1L, std::lround(length / region.grid_spacing));
    for (long k = 0; k < pieces; ++k) {
      const Eigen::Vector2d p = a + edge * ((static_cast<double>(k) + 0.5) / pieces);
      if (inKeepOut(region, p)) {
        continue;
      }
      MountCandidate c;
      c.position = {p.x(), p.y(), region.aoa_height};
      c.yaw = std::atan2(normal.y(), normal.x());
      out.push_back(c);
    }
  }
  return out;
}

}  // namespace estimation
}  // namespace radio_follow
