// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/config/layout.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <set>
#include <sstream>

#include "radio_follow/common/angles.hpp"
#include "radio_follow/common/param_error.hpp"
#include "radio_follow/common/param_keys.hpp"
#include "radio_follow/common/yaml_keys.hpp"

namespace radio_follow {
namespace {

bool finite(const Eigen::Vector3d& v) {
  return v.allFinite();
}

std::string describe(const YAML::Node& node) {
  return yamlValueString(node);
}

Eigen::Vector3d readVector3(const YAML::Node& parent, const std::string& key,
                            const std::string& path, const std::string& unit) {
  const std::string expected = "a list of 3 finite numbers [x, y, z] in " + unit;
  const std::vector<double> v = yamlNumbers(parent[key], path + key, expected);
  if (v.size() != 3) {
    throw ParamError(path + key, describe(parent[key]), expected);
  }
  return Eigen::Vector3d(v[0], v[1], v[2]);
}

AoaBoardKind parseKind(const std::string& text, const std::string& name) {
  if (text == "xplr_aoa_1") {
    return AoaBoardKind::kXplrAoa1;
  }
  if (text == "ant_b10") {
    return AoaBoardKind::kAntB10;
  }
  throw ParamError(name, paramValueString(text), "'xplr_aoa_1' or 'ant_b10'");
}

std::string itemPath(const std::string& list, std::size_t index) {
  return list + "[" + std::to_string(index) + "].";
}

}  // namespace

double TwrModule::correctRange(double raw_range) const {
  double result = 0.0;
  for (auto it = calibration.rbegin(); it != calibration.rend(); ++it) {
    result = result * raw_range + *it;
  }
  return result;
}

std::vector<std::string> uncalibratedModules(const Layout& layout) {
  std::vector<std::string> ids;
  for (const auto& m : layout.twr_modules) {
    if (m.calibration == std::vector<double>{0.0, 1.0}) {
      ids.push_back(m.id);
    }
  }
  return ids;
}

std::string uwbNamespace(const std::string& module_id) {
  return "uwb/" + module_id;
}

std::string aoaNamespace(const std::string& board_id) {
  return "aoa/" + board_id;
}

SensorTopics conventionalTopics(const Layout& layout) {
  SensorTopics topics;
  for (const auto& m : layout.twr_modules) {
    topics.uwb.push_back(uwbNamespace(m.id) + "/ranges");
  }
  for (const auto& b : layout.aoa_boards) {
    topics.aoa.push_back(aoaNamespace(b.id) + "/bearing");
  }
  if (!layout.tdoa_anchors.empty()) {
    topics.tdoa.push_back("tdoa/measurements");
  }
  return topics;
}

std::vector<Eigen::Vector2d> layoutFootprint(const Layout& layout, double margin) {
  // The hull of the sensors grown by the margin is the hull of small polygons around
  // each sensor: 8 points on a circle of radius margin / cos(pi / 8) contain the circle.
  std::vector<Eigen::Vector2d> points;
  const double r = margin / std::cos(kPi / 8.0);
  auto add = [&](const Eigen::Vector3d& p) {
    for (int k = 0; k < 8; ++k) {
      const double a = kPi / 8.0 + kPi / 4.0 * k;
      points.emplace_back(p.x() + r * std::cos(a), p.y() + r * std::sin(a));
    }
  };
  for (const auto& m : layout.twr_modules) {
    add(m.position);
  }
  for (const auto& b : layout.aoa_boards) {
    add(b.position);
  }
  // Andrew's monotone chain.
  std::sort(points.begin(), points.end(), [](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
  });
  auto cross = [](const Eigen::Vector2d& o, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
  };
  std::vector<Eigen::Vector2d> hull(2 * points.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], points[i]) <= 0.0) {
      --k;
    }
    hull[k++] = points[i];
  }
  for (std::size_t i = points.size(), lower = k + 1; i-- > 1;) {
    while (k >= lower && cross(hull[k - 2], hull[k - 1], points[i - 1]) <= 0.0) {
      --k;
    }
    hull[k++] = points[i - 1];
  }
  hull.resize(k > 1 ? k - 1 : k);  // the last point repeats the first
  return hull;
}

std::string toString(AoaBoardKind kind) {
  return kind == AoaBoardKind::kAntB10 ? "ant_b10" : "xplr_aoa_1";
}

void Layout::validate() const {
  require(!fixed_frame.empty(), "fixed_frame", fixed_frame, "a non-empty TF frame name");
  require(!twr_modules.empty() || !aoa_boards.empty() || !tdoa_anchors.empty(), "twr_modules",
          std::string("(none)"), "at least one sensor in twr_modules, aoa_boards or tdoa_anchors");
  require(twr_modules.empty() || !target_anchor_id.empty(), "target.uwb_anchor_id",
          target_anchor_id, "the target's UWB anchor ID (e.g. 'DA12') when twr_modules exist");

  std::set<std::string> frames;
  std::set<std::string> ids;
  for (std::size_t i = 0; i < twr_modules.size(); ++i) {
    const TwrModule& m = twr_modules[i];
    const std::string path = itemPath("twr_modules", i);
    require(!m.id.empty(), path + "id", m.id, "a non-empty module ID (e.g. '5722')");
    require(ids.insert("twr:" + m.id).second, path + "id", m.id, "an ID unique among twr_modules");
    require(!m.frame_id.empty(), path + "frame_id", m.frame_id, "a non-empty TF frame name");
    require(frames.insert(m.frame_id).second, path + "frame_id", m.frame_id,
            "a frame_id unique in the layout");
    require(finite(m.position), path + "position", m.position.transpose(), "finite metres");
    require(!m.calibration.empty(), path + "calibration", std::string("[]"),
            "polynomial coefficients [c0, c1, ...], at least one");
  }
  for (std::size_t i = 0; i < aoa_boards.size(); ++i) {
    const AoaBoard& b = aoa_boards[i];
    const std::string path = itemPath("aoa_boards", i);
    require(!b.id.empty(), path + "id", b.id, "a non-empty board name");
    require(ids.insert("aoa:" + b.id).second, path + "id", b.id, "an ID unique among aoa_boards");
    require(!b.frame_id.empty(), path + "frame_id", b.frame_id, "a non-empty TF frame name");
    require(frames.insert(b.frame_id).second, path + "frame_id", b.frame_id,
            "a frame_id unique in the layout");
    require(finite(b.position), path + "position", b.position.transpose(), "finite metres");
    require(b.field_of_view > 0.0 && b.field_of_view <= kPi / 2.0, path + "field_of_view_deg",
            rad2deg(b.field_of_view), "a half-angle in (0, 90] degrees");
    require(std::abs(b.elevation_offset) <= kMaxElevationOffset, path + "elevation_offset_deg",
            rad2deg(b.elevation_offset),
            "degrees within +-30 (a board mounted tilted: its pitch in rpy_deg)");
  }
  for (std::size_t i = 0; i < tdoa_anchors.size(); ++i) {
    const TdoaAnchor& a = tdoa_anchors[i];
    const std::string path = itemPath("tdoa_anchors", i);
    require(!a.id.empty(), path + "id", a.id, "a non-empty anchor ID");
    require(ids.insert("tdoa:" + a.id).second, path + "id", a.id,
            "an ID unique among tdoa_anchors");
    require(finite(a.position), path + "position", a.position.transpose(), "finite metres");
  }
  require(tdoa_anchors.empty() || tdoa_anchors.size() >= 2, "tdoa_anchors", tdoa_anchors.size(),
          "none, or at least 2 anchors (a difference needs two)");
  require(tdoa_anchors.empty() || !target_tdoa_tag_id.empty(), "target.tdoa_tag_id",
          target_tdoa_tag_id,
          "the target's TDoA tag ID (or target.uwb_anchor_id) when tdoa_anchors exist: without "
          "it every tag's blinks, the robot's own modules' too, would be taken for the person");
}

const TwrModule* Layout::findTwrModule(const std::string& id_or_frame) const {
  for (const auto& m : twr_modules) {
    if (m.id == normalizeId(id_or_frame) || m.frame_id == id_or_frame) {
      return &m;
    }
  }
  return nullptr;
}

const AoaBoard* Layout::findAoaBoard(const std::string& id_or_frame) const {
  for (const auto& b : aoa_boards) {
    if (b.id == id_or_frame || b.frame_id == id_or_frame) {
      return &b;
    }
  }
  return nullptr;
}

namespace {

template <typename Sensor>
std::size_t indexIn(const std::vector<Sensor>& list, const Sensor* found) {
  return found == nullptr ? kNoSensor : static_cast<std::size_t>(found - list.data());
}

}  // namespace

std::size_t Layout::twrModuleIndex(const std::string& id_or_frame) const {
  return indexIn(twr_modules, findTwrModule(id_or_frame));
}

std::size_t Layout::aoaBoardIndex(const std::string& id_or_frame) const {
  return indexIn(aoa_boards, findAoaBoard(id_or_frame));
}

std::size_t Layout::tdoaAnchorIndex(const std::string& id) const {
  return indexIn(tdoa_anchors, findTdoaAnchor(id));
}

bool Layout::isTargetTdoaTag(const std::string& tag_id) const {
  return !target_tdoa_tag_id.empty() && normalizeId(tag_id) == target_tdoa_tag_id;
}

const TdoaAnchor* Layout::findTdoaAnchor(const std::string& id) const {
  for (const auto& a : tdoa_anchors) {
    if (a.id == normalizeId(id)) {
      return &a;
    }
  }
  return nullptr;
}

Layout parseLayout(const std::string& yaml_text, const std::string& origin) {
  YAML::Node root = loadConfigYaml(yaml_text, "layout", origin);
  if (!root.IsMap()) {
    throw ParamError("layout", paramValueString(origin),
                     "a YAML mapping with fixed_frame, target, "
                     "twr_modules, aoa_boards, tdoa_anchors");
  }

  requireYamlKeys(root, {"fixed_frame", "target", "twr_modules", "aoa_boards", "tdoa_anchors"}, "");
  Layout layout;
  const std::string default_frame = layout.fixed_frame;
  layout.fixed_frame =
      yamlScalar<std::string>(root, "fixed_frame", "", "a TF frame name", &default_frame);
  const YAML::Node target = root["target"];
  if (target.IsDefined() && !target.IsNull()) {
    requireYamlKeys(target, {"uwb_anchor_id", "aoa_tag_id", "tdoa_tag_id"}, "target.");
    const std::string empty;
    layout.target_anchor_id = normalizeId(
        yamlScalar<std::string>(target, "uwb_anchor_id", "target.", "an anchor ID", &empty));
    layout.target_tag_id =
        normalizeId(yamlScalar<std::string>(target, "aoa_tag_id", "target.", "a tag ID", &empty));
    layout.target_tdoa_tag_id = normalizeId(yamlScalar<std::string>(
        target, "tdoa_tag_id", "target.", "a tag ID", &layout.target_anchor_id));
  }

  const YAML::Node twr = root["twr_modules"];
  for (std::size_t i = 0; twr.IsSequence() && i < twr.size(); ++i) {
    const std::string path = itemPath("twr_modules", i);
    requireYamlKeys(twr[i], {"id", "frame_id", "position", "calibration"}, path);
    TwrModule m;
    m.id = normalizeId(yamlScalar<std::string>(twr[i], "id", path, "a module ID string"));
    const std::string default_frame_id = "uwb_" + m.id;
    m.frame_id =
        yamlScalar<std::string>(twr[i], "frame_id", path, "a TF frame name", &default_frame_id);
    m.position = readVector3(twr[i], "position", path, "metres");
    if (twr[i]["calibration"].IsDefined()) {
      m.calibration = yamlNumbers(twr[i]["calibration"], path + "calibration",
                                  "a list of polynomial coefficients [c0, c1, ...]");
    }
    layout.twr_modules.push_back(m);
  }

  const YAML::Node aoa = root["aoa_boards"];
  for (std::size_t i = 0; aoa.IsSequence() && i < aoa.size(); ++i) {
    const std::string path = itemPath("aoa_boards", i);
    requireYamlKeys(aoa[i],
                    {"id", "frame_id", "kind", "position", "rpy_deg", "field_of_view_deg",
                     "elevation_offset_deg"},
                    path);
    AoaBoard b;
    b.id = yamlScalar<std::string>(aoa[i], "id", path, "a board name");
    const std::string default_frame_id = "aoa_" + b.id;
    b.frame_id =
        yamlScalar<std::string>(aoa[i], "frame_id", path, "a TF frame name", &default_frame_id);
    const std::string default_kind = "xplr_aoa_1";
    b.kind = parseKind(yamlScalar<std::string>(aoa[i], "kind", path, "a board kind", &default_kind),
                       path + "kind");
    b.position = readVector3(aoa[i], "position", path, "metres");
    if (aoa[i]["rpy_deg"].IsDefined()) {
      const Eigen::Vector3d rpy = deg2rad(1.0) * readVector3(aoa[i], "rpy_deg", path, "degrees");
      b.orientation = Eigen::AngleAxisd(rpy.z(), Eigen::Vector3d::UnitZ()) *
                      Eigen::AngleAxisd(rpy.y(), Eigen::Vector3d::UnitY()) *
                      Eigen::AngleAxisd(rpy.x(), Eigen::Vector3d::UnitX());
    }
    const double default_fov = rad2deg(b.field_of_view);
    b.field_of_view = deg2rad(yamlScalar<double>(aoa[i], "field_of_view_deg", path,
                                                 "a half-angle in degrees", &default_fov));
    const double no_offset = 0.0;
    b.elevation_offset = deg2rad(yamlScalar<double>(aoa[i], "elevation_offset_deg", path,
                                                    "an angle in degrees", &no_offset));
    layout.aoa_boards.push_back(b);
  }

  const YAML::Node tdoa = root["tdoa_anchors"];
  for (std::size_t i = 0; tdoa.IsSequence() && i < tdoa.size(); ++i) {
    const std::string path = itemPath("tdoa_anchors", i);
    requireYamlKeys(tdoa[i], {"id", "position"}, path);
    TdoaAnchor a;
    a.id = normalizeId(yamlScalar<std::string>(tdoa[i], "id", path, "an anchor ID string"));
    a.position = readVector3(tdoa[i], "position", path, "metres");
    layout.tdoa_anchors.push_back(a);
  }

  for (const char* list : {"twr_modules", "aoa_boards", "tdoa_anchors"}) {
    const YAML::Node node = root[list];
    if (node.IsDefined() && !node.IsNull() && !node.IsSequence()) {
      throw ParamError(list, describe(node), "a list of sensors");
    }
  }
  layout.validate();
  return layout;
}

Layout loadLayoutFile(const std::string& path, const std::string& param) {
  return parseLayout(readConfigFile(path, param, "a readable layout YAML file"), path);
}

}  // namespace radio_follow
