// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/sim/target_path.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <random>
#include <sstream>

#include "radio_follow/common/angles.hpp"
#include "radio_follow/common/param_error.hpp"
#include "radio_follow/common/yaml_keys.hpp"

namespace radio_follow {
namespace sim {
namespace {

/// Arc legs are sampled every this many radians so interpolation stays on the arc.
constexpr double kArcStep = deg2rad(5.0);

void requireSpeed(double speed, const std::string& name) {
  require(std::isfinite(speed) && speed > 0.0 && speed < 20.0, name, speed,
          "a walking speed in (0, 20) m/s");
}

}  // namespace

TargetPath::TargetPath(const Pose2& start) {
  samples_.push_back(TargetSample{0.0, start, 0.0});
}

void TargetPath::append(const Pose2& pose, double speed, double distance) {
  const TargetSample& last = samples_.back();
  const double step =
      distance >= 0.0 ? distance : std::hypot(pose.x - last.pose.x, pose.y - last.pose.y);
  samples_.push_back(TargetSample{last.t + step / speed, pose, speed});
  length_ += step;
}

void TargetPath::walkTo(double x, double y, double speed) {
  requireSpeed(speed, "walk.speed");
  const Pose2& from = samples_.back().pose;
  const double heading = std::atan2(y - from.y, x - from.x);
  // Turn on the spot (zero duration), then walk.
  samples_.back().pose.yaw = heading;
  append(Pose2{x, y, heading}, speed);
}

void TargetPath::arc(double radius, double angle, double speed) {
  requireSpeed(speed, "arc.speed");
  require(std::isfinite(radius) && radius > 0.0, "arc.radius", radius, "a radius > 0 in m");
  const Pose2 start = samples_.back().pose;
  const double side = angle >= 0.0 ? 1.0 : -1.0;
  // Centre of the turn, to the left (positive angle) or right of the walking direction.
  const double cx = start.x - side * radius * std::sin(start.yaw);
  const double cy = start.y + side * radius * std::cos(start.yaw);
  const int steps = std::max(1, static_cast<int>(std::ceil(std::abs(angle) / kArcStep)));
  for (int i = 1; i <= steps; ++i) {
    const double heading = start.yaw + angle * i / steps;
    append(Pose2{cx + side * radius * std::sin(heading), cy - side * radius * std::cos(heading),
                 wrapAngleFast(heading)},
           speed, radius * std::abs(angle) / steps);
  }
}

void TargetPath::wait(double duration) {
  require(std::isfinite(duration) && duration >= 0.0, "wait", duration, "seconds >= 0");
  TargetSample still = samples_.back();
  still.t += duration;
  still.speed = 0.0;
  samples_.push_back(still);
}

void TargetPath::randomWalk(int steps, double step_length, double max_turn, double speed,
                            std::uint64_t seed) {
  require(steps > 0 && steps < 100000, "random_walk.steps", steps, "a count in [1, 100000)");
  require(std::isfinite(step_length) && step_length > 0.0, "random_walk.step_length", step_length,
          "a length > 0 in m");
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> turn(-max_turn, max_turn);
  for (int i = 0; i < steps; ++i) {
    const Pose2& from = samples_.back().pose;
    const double heading = from.yaw + turn(rng);
    walkTo(from.x + step_length * std::cos(heading), from.y + step_length * std::sin(heading),
           speed);
  }
}

void TargetPath::limitAcceleration(double accel) {
  require(std::isfinite(accel) && accel >= 0.0, "target.accel", accel, "m/s^2 >= 0");
  if (accel == 0.0 || samples_.size() < 2) {
    return;
  }
  // Short pieces, so that linear interpolation in time stays close to the ramped motion.
  constexpr double kPiece = 0.05;  // m
  std::vector<TargetSample> pieces{samples_.front()};
  std::vector<double> nominal;  // speed of the piece ending at pieces[i + 1]; 0 = a wait
  std::vector<double> lengths;
  for (std::size_t i = 1; i < samples_.size(); ++i) {
    const TargetSample& a = samples_[i - 1];
    const TargetSample& b = samples_[i];
    const double length = std::hypot(b.pose.x - a.pose.x, b.pose.y - a.pose.y);
    const double duration = b.t - a.t;
    if (length <= 0.0) {
      pieces.push_back(b);  // a wait (or a turn on the spot), kept as it is
      nominal.push_back(0.0);
      lengths.push_back(0.0);
      continue;
    }
    const int n = std::max(1, static_cast<int>(std::ceil(length / kPiece)));
    for (int k = 1; k <= n; ++k) {
      TargetSample s = b;
      s.pose.x = a.pose.x + (b.pose.x - a.pose.x) * k / n;
      s.pose.y = a.pose.y + (b.pose.y - a.pose.y) * k / n;
      pieces.push_back(s);
      nominal.push_back(length / duration);
      lengths.push_back(length / n);
    }
  }
  // Speed at each piece boundary: at most the slower neighbour, 0 next to a stand, then
  // reachable forwards and backwards at `accel` (v^2 = u^2 + 2 a d).
  const std::size_t n = pieces.size();
  std::vector<double> u(n, 0.0);
  for (std::size_t i = 1; i + 1 < n; ++i) {
    u[i] = std::min(nominal[i - 1], nominal[i]);
  }
  for (std::size_t i = 1; i < n; ++i) {
    u[i] = std::min(u[i], std::sqrt(u[i - 1] * u[i - 1] + 2.0 * accel * lengths[i - 1]));
  }
  for (std::size_t i = n - 1; i-- > 0;) {
    u[i] = std::min(u[i], std::sqrt(u[i + 1] * u[i + 1] + 2.0 * accel * lengths[i]));
  }
  // A piece at constant acceleration from u[i] to u[i + 1] takes 2 L / (u[i] + u[i + 1]).
  double t = pieces.front().t;
  std::vector<TargetSample> timed{pieces.front()};
  timed.front().speed = 0.0;
  for (std::size_t i = 1; i < n; ++i) {
    TargetSample s = pieces[i];
    if (lengths[i - 1] > 0.0) {
      t += 2.0 * lengths[i - 1] / std::max(u[i - 1] + u[i], 1e-9);
    } else {
      t += pieces[i].t - pieces[i - 1].t;
    }
    s.t = t;
    s.speed = u[i];
    timed.push_back(s);
  }
  samples_ = std::move(timed);
}

TargetSample TargetPath::at(double t) const {
  if (t <= samples_.front().t) {
    return samples_.front();
  }
  if (t >= samples_.back().t) {
    TargetSample end = samples_.back();
    end.t = t;
    end.speed = 0.0;
    return end;
  }
  const auto hi = std::upper_bound(samples_.begin(), samples_.end(), t,
                                   [](double time, const TargetSample& s) { return time < s.t; });
  const auto lo = hi - 1;
  const double span = hi->t - lo->t;
  const double w = span > 0.0 ? (t - lo->t) / span : 1.0;
  TargetSample s;
  s.t = t;
  s.pose.x = lo->pose.x + w * (hi->pose.x - lo->pose.x);
  s.pose.y = lo->pose.y + w * (hi->pose.y - lo->pose.y);
  s.pose.yaw = hi->pose.yaw;
  s.speed = hi->speed;
  return s;
}

namespace {

double number(const YAML::Node& node, const std::string& key, const std::string& path,
              const std::string& expected) {
  const YAML::Node value = node[key];
  try {
    if (value.IsDefined() && value.IsScalar()) {
      return value.as<double>();
    }
  } catch (const YAML::Exception&) {
  }
  throw ParamError(path + key, value.IsDefined() ? YAML::Dump(value) : "(missing)", expected);
}

double numberOr(const YAML::Node& node, const std::string& key, const std::string& path,
                const std::string& expected, double fallback) {
  return node[key].IsDefined() ? number(node, key, path, expected) : fallback;
}

Pose2 readPose(const YAML::Node& node, const std::string& path) {
  const std::string expected = "[x, y] in m or [x, y, yaw_deg]";
  if (!node.IsDefined() || !node.IsSequence() || node.size() < 2 || node.size() > 3) {
    throw ParamError(path, node.IsDefined() ? YAML::Dump(node) : "(missing)", expected);
  }
  try {
    Pose2 p{node[0].as<double>(), node[1].as<double>(), 0.0};
    if (node.size() == 3) {
      p.yaw = deg2rad(node[2].as<double>());
    }
    return p;
  } catch (const YAML::Exception&) {
    throw ParamError(path, YAML::Dump(node), expected);
  }
}

void addLeg(TargetPath& path, const YAML::Node& leg, const std::string& name, double speed,
            std::uint64_t seed) {
  requireYamlKeys(leg, {"to", "arc_deg", "radius", "wait", "random_walk", "speed"}, name);
  const double leg_speed = numberOr(leg, "speed", name, "a speed in m/s", speed);
  if (leg["to"].IsDefined()) {
    const Pose2 to = readPose(leg["to"], name + "to");
    path.walkTo(to.x, to.y, leg_speed);
  } else if (leg["arc_deg"].IsDefined()) {
    path.arc(number(leg, "radius", name, "a radius in m"),
             deg2rad(number(leg, "arc_deg", name, "a turn in degrees (+ = left)")), leg_speed);
  } else if (leg["wait"].IsDefined()) {
    path.wait(number(leg, "wait", name, "a duration in s"));
  } else if (leg["random_walk"].IsDefined()) {
    const YAML::Node rw = leg["random_walk"];
    const std::string rw_name = name + "random_walk.";
    requireYamlKeys(rw, {"steps", "step_length", "max_turn_deg"}, rw_name);
    path.randomWalk(static_cast<int>(number(rw, "steps", rw_name, "a step count")),
                    number(rw, "step_length", rw_name, "a length in m"),
                    deg2rad(numberOr(rw, "max_turn_deg", rw_name, "degrees", 45.0)), leg_speed,
                    seed);
  } else {
    throw ParamError(name.substr(0, name.size() - 1), YAML::Dump(leg),
                     "a leg with one of: to, arc_deg (+radius), wait, random_walk");
  }
}

std::vector<double> readRow(const YAML::Node& node, std::size_t size, const std::string& name,
                            const std::string& expected) {
  std::vector<double> row;
  try {
    if (node.IsSequence() && node.size() == size) {
      for (const auto& v : node)
        row.push_back(v.as<double>());
      return row;
    }
  } catch (const YAML::Exception&) {
  }
  throw ParamError(name, YAML::Dump(node), expected);
}

Obstacles readObstacles(const YAML::Node& node) {
  Obstacles o;
  if (!node.IsMap()) {
    throw ParamError("obstacles", YAML::Dump(node), "a mapping with 'circles' and/or 'walls'");
  }
  requireYamlKeys(node, {"circles", "walls"}, "obstacles.");
  const YAML::Node circles = node["circles"];
  for (std::size_t i = 0; circles.IsDefined() && circles.IsSequence() && i < circles.size(); ++i) {
    const auto r = readRow(circles[i], 3, "obstacles.circles[" + std::to_string(i) + "]",
                           "[x, y, radius] in m");
    require(r[2] > 0.0, "obstacles.circles[" + std::to_string(i) + "]", r[2], "a radius > 0 m");
    o.circles.push_back(CircleObstacle{r[0], r[1], r[2]});
  }
  const YAML::Node walls = node["walls"];
  for (std::size_t i = 0; walls.IsDefined() && walls.IsSequence() && i < walls.size(); ++i) {
    const auto w =
        readRow(walls[i], 4, "obstacles.walls[" + std::to_string(i) + "]", "[x1, y1, x2, y2] in m");
    o.walls.push_back(WallObstacle{w[0], w[1], w[2], w[3]});
  }
  return o;
}

}  // namespace

Scenario parseScenario(const std::string& yaml_text, const std::string& origin,
                       std::uint64_t seed) {
  YAML::Node root;
  try {
    root = YAML::Load(yaml_text);
  } catch (const YAML::Exception& e) {
    throw ParamError("scenario", "'" + origin + "'", std::string("valid YAML (") + e.what() + ")");
  }
  if (!root.IsMap() || !root["target"].IsMap()) {
    throw ParamError("scenario", "'" + origin + "'", "a mapping with a 'target' mapping");
  }
  requireYamlKeys(root, {"name", "robot_start", "target", "obstacles", "settle_time", "duration"},
                  "");
  requireYamlKeys(root["target"], {"start", "height", "speed", "legs", "accel"}, "target.");
  Scenario s;
  s.name = root["name"].IsDefined() ? root["name"].as<std::string>() : origin;
  if (root["robot_start"].IsDefined()) {
    s.robot_start = readPose(root["robot_start"], "robot_start");
  }
  const YAML::Node target = root["target"];
  s.target = TargetPath(readPose(target["start"], "target.start"));
  s.target_height = numberOr(target, "height", "target.", "a height in m", s.target_height);
  const double speed = numberOr(target, "speed", "target.", "a speed in m/s", 1.0);
  const YAML::Node legs = target["legs"];
  if (legs.IsDefined() && !legs.IsSequence()) {
    throw ParamError("target.legs", YAML::Dump(legs), "a list of legs");
  }
  for (std::size_t i = 0; legs.IsDefined() && i < legs.size(); ++i) {
    addLeg(s.target, legs[i], "target.legs[" + std::to_string(i) + "].", speed, seed + i);
  }
  s.target_accel = numberOr(target, "accel", "target.", "an acceleration in m/s^2", s.target_accel);
  s.target.limitAcceleration(s.target_accel);
  const YAML::Node obstacles = root["obstacles"];
  if (obstacles.IsDefined()) {
    s.obstacles = readObstacles(obstacles);
  }
  s.settle_time = numberOr(root, "settle_time", "", "seconds >= 0", s.settle_time);
  require(s.settle_time >= 0.0, "settle_time", s.settle_time, "seconds >= 0");
  s.duration = numberOr(root, "duration", "", "seconds > 0", s.target.duration() + s.settle_time);
  require(std::isfinite(s.duration) && s.duration > 0.0, "duration", s.duration, "seconds > 0");
  return s;
}

Scenario loadScenarioFile(const std::string& path, std::uint64_t seed) {
  std::ifstream file(path);
  if (!file) {
    throw ParamError("scenario_file", "'" + path + "'", "a readable scenario YAML file");
  }
  std::stringstream text;
  text << file.rdbuf();
  return parseScenario(text.str(), path, seed);
}

}  // namespace sim
}  // namespace radio_follow
