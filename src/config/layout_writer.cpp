// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/config/layout_writer.hpp"

#include <yaml-cpp/yaml.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>

#include "radio_follow/common/angles.hpp"
#include "radio_follow/common/param_error.hpp"
#include "radio_follow/common/param_keys.hpp"
#include "radio_follow/config/layout.hpp"

namespace radio_follow {
namespace {

/// Six significant digits: 0.1 mm on a range offset, 1e-6 on a scale, far below what a
/// fit resolves, and no 0.10000000000000001 in a file people read.
std::string number(double value) {
  std::ostringstream out;
  out.precision(6);
  out << (std::abs(value) < 1e-12 ? 0.0 : value);
  return out.str();
}

YAML::Node flowNumbers(const std::vector<double>& values) {
  YAML::Node seq(YAML::NodeType::Sequence);
  for (double v : values) {
    seq.push_back(number(v));
  }
  seq.SetStyle(YAML::EmitterStyle::Flow);
  return seq;
}

/// Emits `node` as it was loaded: yaml-cpp's own `<<` unquotes strings, and a module ID
/// "5722" written bare is an integer to every other YAML reader.
void emit(YAML::Emitter& out, const YAML::Node& node) {
  switch (node.Type()) {
    case YAML::NodeType::Map:
      if (node.Style() == YAML::EmitterStyle::Flow) {
        out << YAML::Flow;
      }
      out << YAML::BeginMap;
      for (const auto& kv : node) {
        out << YAML::Key;
        emit(out, kv.first);
        out << YAML::Value;
        emit(out, kv.second);
      }
      out << YAML::EndMap;
      break;
    case YAML::NodeType::Sequence:
      if (node.Style() == YAML::EmitterStyle::Flow) {
        out << YAML::Flow;
      }
      out << YAML::BeginSeq;
      for (const auto& item : node) {
        emit(out, item);
      }
      out << YAML::EndSeq;
      break;
    case YAML::NodeType::Scalar:
      // yaml-cpp tags a quoted scalar "!" (non-specific) and a plain one "?".
      if (node.Tag() == "!") {
        out << YAML::DoubleQuoted;
      }
      out << node.Scalar();
      break;
    default:
      out << YAML::Null;
      break;
  }
}

double wrapDegrees(double deg) {
  return rad2deg(wrapAngle(deg2rad(deg)));
}

}  // namespace

Eigen::Vector3d rpyWithYawOffset(const Eigen::Vector3d& rpy_deg, double yaw_offset) {
  const Eigen::Vector3d rpy = deg2rad(1.0) * rpy_deg;
  const Eigen::Matrix3d r = (Eigen::AngleAxisd(rpy.z(), Eigen::Vector3d::UnitZ()) *
                             Eigen::AngleAxisd(rpy.y(), Eigen::Vector3d::UnitY()) *
                             Eigen::AngleAxisd(rpy.x(), Eigen::Vector3d::UnitX()) *
                             Eigen::AngleAxisd(yaw_offset, Eigen::Vector3d::UnitZ()))
                                .toRotationMatrix();
  // The board's z axis is the fixed frame's +-z: the turn is a yaw change only; keep the
  // file's roll and pitch digits (the general decomposition would rewrite them).
  const Eigen::Vector3d z = r.col(2);
  if (std::abs(std::abs(z.z()) - 1.0) < 1e-12) {
    return {rpy_deg.x(), rpy_deg.y(),
            wrapDegrees(rpy_deg.z() + rad2deg(z.z() > 0.0 ? yaw_offset : -yaw_offset))};
  }
  return rpyDegrees(r);
}

Eigen::Vector3d rpyDegrees(const Eigen::Matrix3d& r) {
  return {rad2deg(std::atan2(r(2, 1), r(2, 2))),
          rad2deg(std::asin(std::clamp(-r(2, 0), -1.0, 1.0))),
          rad2deg(std::atan2(r(1, 0), r(0, 0)))};
}

std::string writeLayout(const Layout& layout, const std::vector<std::string>& header_comment) {
  layout.validate();
  const auto vector = [](const Eigen::Vector3d& v) { return flowNumbers({v.x(), v.y(), v.z()}); };
  YAML::Emitter out;
  out.SetIndent(2);
  out << YAML::BeginMap << YAML::Key << "fixed_frame" << YAML::Value << layout.fixed_frame;
  out << YAML::Key << "target" << YAML::Value << YAML::BeginMap;
  out << YAML::Key << "uwb_anchor_id" << YAML::Value << YAML::DoubleQuoted
      << layout.target_anchor_id;
  out << YAML::Key << "aoa_tag_id" << YAML::Value << YAML::DoubleQuoted << layout.target_tag_id;
  if (layout.target_tdoa_tag_id != layout.target_anchor_id) {
    out << YAML::Key << "tdoa_tag_id" << YAML::Value << YAML::DoubleQuoted
        << layout.target_tdoa_tag_id;
  }
  out << YAML::EndMap;
  // Empty lists are left out (the keys are optional): yaml-cpp writes them as a lone "[]".
  if (!layout.twr_modules.empty()) {
    out << YAML::Key << "twr_modules" << YAML::Value << YAML::BeginSeq;
    for (const TwrModule& m : layout.twr_modules) {
      out << YAML::Flow << YAML::BeginMap;
      // Quoted: a module ID such as "0001" written bare is an integer to other YAML readers.
      out << YAML::Key << "id" << YAML::Value << YAML::DoubleQuoted << m.id;
      out << YAML::Key << "frame_id" << YAML::Value << m.frame_id;
      out << YAML::Key << "position" << YAML::Value << vector(m.position);
      out << YAML::Key << "calibration" << YAML::Value << flowNumbers(m.calibration);
      out << YAML::EndMap;
    }
    out << YAML::EndSeq;
  }
  if (!layout.aoa_boards.empty()) {
    out << YAML::Key << "aoa_boards" << YAML::Value << YAML::BeginSeq;
    for (const AoaBoard& b : layout.aoa_boards) {
      out << YAML::Flow << YAML::BeginMap;
      out << YAML::Key << "id" << YAML::Value << b.id;
      out << YAML::Key << "frame_id" << YAML::Value << b.frame_id;
      out << YAML::Key << "kind" << YAML::Value << toString(b.kind);
      out << YAML::Key << "position" << YAML::Value << vector(b.position);
      out << YAML::Key << "rpy_deg" << YAML::Value
          << vector(rpyDegrees(b.orientation.toRotationMatrix()));
      out << YAML::Key << "field_of_view_deg" << YAML::Value
          << flowNumbers({rad2deg(b.field_of_view)})[0];
      if (b.elevation_offset != 0.0) {
        out << YAML::Key << "elevation_offset_deg" << YAML::Value
            << flowNumbers({rad2deg(b.elevation_offset)})[0];
      }
      out << YAML::EndMap;
    }
    out << YAML::EndSeq;
  }
  if (!layout.tdoa_anchors.empty()) {
    out << YAML::Key << "tdoa_anchors" << YAML::Value << YAML::BeginSeq;
    for (const TdoaAnchor& a : layout.tdoa_anchors) {
      out << YAML::Flow << YAML::BeginMap;
      out << YAML::Key << "id" << YAML::Value << YAML::DoubleQuoted << a.id;
      out << YAML::Key << "position" << YAML::Value << vector(a.position);
      out << YAML::EndMap;
    }
    out << YAML::EndSeq;
  }
  out << YAML::EndMap;
  std::string text;
  for (const std::string& line : header_comment) {
    text += "# " + line + "\n";
  }
  text += std::string(out.c_str()) + "\n";
  parseLayout(text, "written layout");
  return text;
}

std::string writeCalibratedLayout(const std::string& yaml_text, const std::string& origin,
                                  const LayoutCalibrationUpdate& update,
                                  const std::vector<std::string>& header_comment) {
  parseLayout(yaml_text, origin);  // the input must be a valid layout: its errors first
  YAML::Node root = YAML::Load(yaml_text);
  std::set<std::string> modules_done;
  YAML::Node twr = root["twr_modules"];
  for (std::size_t i = 0; twr.IsSequence() && i < twr.size(); ++i) {
    const std::string id = normalizeId(twr[i]["id"].as<std::string>());
    const auto found = update.range_calibration.find(id);
    if (found != update.range_calibration.end()) {
      twr[i]["calibration"] = flowNumbers(found->second);
      modules_done.insert(id);
    }
  }
  std::set<std::string> boards_done;
  YAML::Node aoa = root["aoa_boards"];
  for (std::size_t i = 0; aoa.IsSequence() && i < aoa.size(); ++i) {
    const std::string id = aoa[i]["id"].as<std::string>();
    if (const auto elevation = update.elevation_offset.find(id);
        elevation != update.elevation_offset.end()) {
      aoa[i]["elevation_offset_deg"] = flowNumbers({rad2deg(elevation->second)})[0];
      boards_done.insert(id);
    }
    const auto found = update.yaw_offset.find(id);
    if (found == update.yaw_offset.end()) {
      continue;
    }
    Eigen::Vector3d rpy = Eigen::Vector3d::Zero();
    const YAML::Node old = aoa[i]["rpy_deg"];
    if (old.IsDefined() && !old.IsNull()) {
      rpy = {old[0].as<double>(), old[1].as<double>(), old[2].as<double>()};
    }
    const Eigen::Vector3d next = rpyWithYawOffset(rpy, found->second);
    YAML::Node written = flowNumbers({next.x(), next.y(), next.z()});
    for (int k = 0; k < 2 && old.IsDefined() && !old.IsNull(); ++k) {
      if (next[k] == rpy[k]) {
        written[k] = old[k];  // unchanged roll and pitch keep their digits
      }
    }
    aoa[i]["rpy_deg"] = written;
    boards_done.insert(id);
  }
  for (const auto& kv : update.range_calibration) {
    require(modules_done.count(kv.first) > 0, "twr_modules", kv.first,
            "a module of the layout " + origin);
  }
  for (const auto& kv : update.yaw_offset) {
    require(boards_done.count(kv.first) > 0, "aoa_boards", kv.first,
            "a board of the layout " + origin);
  }
  for (const auto& kv : update.elevation_offset) {
    require(boards_done.count(kv.first) > 0, "aoa_boards", kv.first,
            "a board of the layout " + origin);
  }

  YAML::Emitter out;
  out.SetIndent(2);
  emit(out, root);
  std::string text;
  for (const std::string& line : header_comment) {
    text += "# " + line + "\n";
  }
  text += std::string(out.c_str()) + "\n";
  parseLayout(text, origin + " (as written)");
  return text;
}

}  // namespace radio_follow
