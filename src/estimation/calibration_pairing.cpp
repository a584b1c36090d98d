// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/estimation/calibration_pairing.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "radio_follow/common/param_error.hpp"
#include "radio_follow/common/yaml_keys.hpp"
#include "radio_follow/estimation/aoa_selector.hpp"
#include "radio_follow/estimation/measurement_models.hpp"

namespace radio_follow {
namespace estimation {
namespace {

/// require() for a value already rendered as YAML (require would quote it as a string).
void requireYaml(bool ok, const std::string& name, const YAML::Node& node,
                 const std::string& expected) {
  if (!ok) {
    throw ParamError(name, yamlValueString(node), expected);
  }
}

double readSeconds(const YAML::Node& item, const std::string& key, const std::string& path) {
  const YAML::Node node = item[key];
  const std::string expected = "seconds from the recording's start, a finite number >= 0";
  double value = 0.0;
  try {
    value = node.IsDefined() && node.IsScalar() ? node.as<double>() : -1.0;
  } catch (const YAML::Exception&) {
    throw ParamError(path + key, yamlValueString(node), expected);
  }
  requireYaml(std::isfinite(value) && value >= 0.0, path + key, node, expected);
  return value;
}

Eigen::Vector3d readPosition(const YAML::Node& item, const std::string& path) {
  const YAML::Node node = item["position"];
  const std::string expected = "[x, y, z] in the layout's fixed frame, 3 finite metres";
  requireYaml(node.IsDefined() && node.IsSequence() && node.size() == 3, path + "position", node,
              expected);
  Eigen::Vector3d p;
  for (int k = 0; k < 3; ++k) {
    try {
      p[k] = node[k].as<double>();
    } catch (const YAML::Exception&) {
      throw ParamError(path + "position", yamlValueString(node), expected);
    }
  }
  requireYaml(p.allFinite(), path + "position", node, expected);
  return p;
}

}  // namespace

std::vector<TapePoint> parseTapePoints(const std::string& yaml_text, const std::string& origin) {
  YAML::Node root = loadConfigYaml(yaml_text, "points", origin);
  require(root.IsMap(), "points", origin,
          "a YAML mapping with `points: [{position: [x, y, z], from: s, until: s}, ...]`");
  requireYamlKeys(root, {"points"}, "");
  const YAML::Node list = root["points"];
  requireYaml(list.IsDefined() && list.IsSequence() && list.size() > 0, "points", list,
              "a non-empty list of {position: [x, y, z], from: s, until: s}");
  std::vector<TapePoint> points;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::string path = "points[" + std::to_string(i) + "].";
    requireYamlKeys(list[i], {"position", "from", "until"}, path);
    TapePoint p;
    p.position = readPosition(list[i], path);
    p.from = readSeconds(list[i], "from", path);
    p.until = readSeconds(list[i], "until", path);
    require(p.until > p.from, path + "until", p.until,
            "a time after `from` (" + paramValueString(p.from) + " s)");
    points.push_back(p);
  }
  std::vector<std::size_t> order(points.size());
  for (std::size_t i = 0; i < order.size(); ++i) {
    order[i] = i;
  }
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return points[a].from < points[b].from; });
  for (std::size_t k = 1; k < order.size(); ++k) {
    const TapePoint& earlier = points[order[k - 1]];
    const TapePoint& later = points[order[k]];
    // Two places at once: one of the windows is mistyped.
    require(later.from >= earlier.until, "points[" + std::to_string(order[k]) + "].from",
            later.from,
            "a window not overlapping points[" + std::to_string(order[k - 1]) + "] (until " +
                paramValueString(earlier.until) + " s)");
  }
  return points;
}

std::vector<TapePoint> loadTapePointsFile(const std::string& path) {
  return parseTapePoints(readConfigFile(path, "points", "a readable tape-points YAML file"), path);
}

CalibrationReference CalibrationReference::fromTrack(std::vector<TimedPosition> track,
                                                     double max_gap) {
  if (track.empty()) {
    throw std::invalid_argument("the ground-truth track holds no sample");
  }
  if (!(max_gap > 0.0)) {
    throw std::invalid_argument("max gap " + std::to_string(max_gap) + " s: expected > 0");
  }
  std::stable_sort(track.begin(), track.end(),
                   [](const TimedPosition& a, const TimedPosition& b) { return a.t < b.t; });
  CalibrationReference r;
  r.track_ = std::move(track);
  r.max_gap_ = max_gap;
  return r;
}

CalibrationReference CalibrationReference::fromPoints(std::vector<TapePoint> points) {
  CalibrationReference r;
  r.points_ = std::move(points);
  return r;
}

CalibrationReference::Lookup CalibrationReference::at(double stamp, double since_start,
                                                      Eigen::Vector3d& position) const {
  if (!isTrack()) {
    for (const TapePoint& p : points_) {
      if (since_start >= p.from && since_start <= p.until) {
        position = p.position;
        return Lookup::kFound;
      }
    }
    return Lookup::kNoWindow;
  }
  const auto hi = std::lower_bound(track_.begin(), track_.end(), stamp,
                                   [](const TimedPosition& p, double t) { return p.t < t; });
  // Before the first or after the last sample: the nearest one, held, if close enough.
  if (hi == track_.begin() || hi == track_.end()) {
    const TimedPosition& edge = hi == track_.end() ? track_.back() : track_.front();
    if (std::abs(edge.t - stamp) > max_gap_) {
      return Lookup::kGap;
    }
    position = edge.position;
    return Lookup::kFound;
  }
  const TimedPosition& lo = *(hi - 1);
  if (std::min(stamp - lo.t, hi->t - stamp) > max_gap_) {
    return Lookup::kGap;
  }
  const double w = hi->t > lo.t ? (stamp - lo.t) / (hi->t - lo.t) : 1.0;
  position = lo.position + w * (hi->position - lo.position);
  return Lookup::kFound;
}

double trueAzimuth(const AoaBoard& board, const Eigen::Vector3d& tag) {
  const Eigen::Vector3d v = board.orientation.conjugate() * (tag - board.position);
  return std::atan2(v.y(), v.x());
}

double trueElevation(const AoaBoard& board, const Eigen::Vector3d& tag) {
  return predictBearing(tag, board.position, board.orientation.toRotationMatrix())(1);
}

CalibrationSamples pairWithReference(const std::vector<CalibrationMeasurement>& measurements,
                                     const Layout& layout, const CalibrationReference& reference) {
  CalibrationSamples out;
  for (const CalibrationMeasurement& m : measurements) {
    const TwrModule* module =
        m.kind == CalibrationMeasurement::Kind::kRange ? layout.findTwrModule(m.sensor) : nullptr;
    const AoaBoard* board =
        m.kind == CalibrationMeasurement::Kind::kBearing ? layout.findAoaBoard(m.sensor) : nullptr;
    if (module == nullptr && board == nullptr) {
      ++out.unknown_sensor;
      continue;
    }
    if (!std::isfinite(m.value)) {
      ++out.non_finite;
      continue;
    }
    Eigen::Vector3d tag;
    switch (reference.at(m.stamp, m.since_start, tag)) {
      case CalibrationReference::Lookup::kGap:
        ++out.gap_dropped;
        continue;
      case CalibrationReference::Lookup::kNoWindow:
        ++out.outside_windows;
        continue;
      case CalibrationReference::Lookup::kFound:
        break;
    }
    if (module != nullptr) {
      out.ranges[module->id].push_back({m.value, (tag - module->position).norm()});
      continue;
    }
    AoaCandidate cone;
    cone.position = board->position;
    cone.rotation = board->orientation.toRotationMatrix();
    cone.field_of_view = board->field_of_view;
    if (!inFieldOfView(cone, tag)) {
      ++out.outside_view;
      continue;
    }
    out.azimuths[board->id].push_back({m.value, trueAzimuth(*board, tag)});
    if (std::isfinite(m.elevation)) {
      out.elevations[board->id].push_back({m.elevation, trueElevation(*board, tag)});
    }
  }
  return out;
}

namespace {

/// Runs `fit` on a sensor's samples unless there are too few; a fit's refusal (a span
/// too short for a scale, ...) becomes the sensor's error, not the tool's.
template <typename Fit, typename Sample, typename FitFunction>
SensorCalibration<Fit> fitSensor(const std::string& id,
                                 const std::map<std::string, std::vector<Sample>>& by_sensor,
                                 std::size_t min_samples, FitFunction fit) {
  SensorCalibration<Fit> result;
  result.id = id;
  const auto found = by_sensor.find(id);
  result.paired = found == by_sensor.end() ? 0 : found->second.size();
  if (result.paired < min_samples) {
    result.error = std::to_string(result.paired) + " samples paired with the reference, " +
                   std::to_string(min_samples) + " needed";
    return result;
  }
  try {
    result.fit = fit(found->second);
  } catch (const std::invalid_argument& e) {
    result.error = e.what();
  }
  return result;
}

}  // namespace

std::size_t LayoutCalibration::fitted() const {
  std::size_t n = 0;
  for (const auto& m : modules) {
    n += m.fit.has_value();
  }
  for (const auto& b : boards) {
    n += b.fit.has_value();
  }
  return n;
}

LayoutCalibration fitLayoutCalibration(const CalibrationSamples& samples, const Layout& layout,
                                       int degree, std::size_t min_samples, bool fit_boards) {
  LayoutCalibration out;
  for (const TwrModule& m : layout.twr_modules) {
    out.modules.push_back(fitSensor<RangeCalibrationFit>(
        m.id, samples.ranges, min_samples,
        [degree](const std::vector<RangeSample>& s) { return fitRangeCalibration(s, degree); }));
  }
  for (const AoaBoard& b : fit_boards ? layout.aoa_boards : std::vector<AoaBoard>{}) {
    out.boards.push_back(fitSensor<YawOffsetFit>(
        b.id, samples.azimuths, min_samples,
        [](const std::vector<AzimuthSample>& s) { return fitYawOffset(s); }));
    out.elevations.push_back(
        fitSensor<ElevationOffsetFit>(b.id, samples.elevations, min_samples, fitElevationOffset));
  }
  return out;
}

}  // namespace estimation
}  // namespace radio_follow
