// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/evaluation/homing_trial.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <random>

#include "radio_follow/common/angles.hpp"
#include "radio_follow/common/yaml_params.hpp"
#include "radio_follow/control/command_pipeline.hpp"
#include "radio_follow/control/obstacle_avoidance.hpp"
#include "radio_follow/evaluation/simulated_scan.hpp"

namespace radio_follow {
namespace evaluation {

std::vector<HomingNoise> seed000NoiseConfigurations() {
  return {
      {"1: +-5 deg, +-5 %", deg2rad(5.0), 0.05, 0.0},
      {"2: +-5 deg, +-10 %", deg2rad(5.0), 0.10, 0.0},
      {"3: +-10 deg, +-10 %", deg2rad(10.0), 0.10, 0.0},
      {"4: +-10 deg, +-20 %", deg2rad(10.0), 0.20, 0.0},
      {"5: +-20 deg, +-1 m +-20 %", deg2rad(20.0), 0.20, 1.0},
  };
}

HomingResult runHomingTrial(const HomingStep& controller, double target_x, double target_y,
                            const HomingNoise& noise, const HomingTrialConfig& config,
                            std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  auto uniform = [&rng](double half) {
    return half > 0.0 ? std::uniform_real_distribution<double>(-half, half)(rng) : 0.0;
  };
  sim::UnicycleRobot robot(config.robot);
  const double dt = 1.0 / config.rate;
  HomingResult result;
  HomingCommand command;
  const bool obstacles = !config.obstacles.empty();
  result.min_clearance = std::numeric_limits<double>::infinity();
  std::normal_distribution<double> scan_noise(0.0, config.scan.sigma);
  // False (and the run over) once the robot touches an obstacle.
  auto clear = [&]() {
    if (obstacles) {
      const Pose2& pose = robot.pose();
      result.min_clearance =
          std::min(result.min_clearance,
                   sim::clearance(config.obstacles, pose.x, pose.y) - config.robot_radius);
      result.collided = result.min_clearance < 0.0;
    }
    return !result.collided;
  };
  double t = 0.0;
  for (; t <= config.time_limit; t += dt) {
    if (!clear()) {
      break;
    }
    const Pose2& pose = robot.pose();
    const double dx = target_x - pose.x;
    const double dy = target_y - pose.y;
    const double distance = std::hypot(dx, dy);
    HomingMeasurement m;
    m.t = t;
    m.odom = pose;
    m.bearing = wrapAngleFast(std::atan2(dy, dx) - pose.yaw + uniform(noise.angle));
    m.distance = std::max(
        0.0, distance + uniform(noise.distance_fraction * distance + noise.distance_offset));
    command = controller(m);
    if (command.arrived) {
      break;
    }
    control::VelocityCommand cmd{command.linear, command.angular};
    if (obstacles && config.use_scan) {
      cmd = control::avoidObstacles(
          cmd,
          simulatedScanSectors(config.obstacles, config.scan, pose, config.avoidance.side_threshold,
                               scan_noise, rng),
          config.avoidance);
    }
    robot.step(cmd.linear, cmd.angular, dt);
  }
  result.time = std::min(t, config.time_limit);
  if (command.arrived) {
    // The law now commands zero; the base brakes at its deceleration limit and comes to
    // rest a little further on. The robot's final position is where it stands, as a tape
    // measure would find it, not where the law decided to stop.
    for (double braking = 0.0;
         (robot.linear() != 0.0 || robot.angular() != 0.0) && braking < config.time_limit;
         braking += dt) {
      robot.step(0.0, 0.0, dt);
      if (!clear()) {
        break;
      }
    }
  }
  const Pose2& end = robot.pose();
  result.final_error = std::hypot(target_x - end.x, target_y - end.y);
  result.success =
      !result.collided && command.arrived && result.final_error < config.success_radius;
  const double straight = std::hypot(end.x, end.y);
  result.net_velocity = result.time > 0.0 ? straight / result.time : 0.0;
  result.path_efficiency = robot.odometer() > 0.0 ? straight / robot.odometer() : 0.0;
  result.goal_error = command.goal_x && command.goal_y
                          ? std::hypot(*command.goal_x - target_x, *command.goal_y - target_y)
                          : std::numeric_limits<double>::quiet_NaN();
  return result;
}

HomingNodeParams loadHomingNodeParams(const std::string& config_dir,
                                      const std::vector<std::string>& overlays) {
  std::vector<std::string> files{config_dir + "/controller_common.yaml",
                                 config_dir + "/homing_controller.yaml"};
  files.insert(files.end(), overlays.begin(), overlays.end());
  const YamlParams source = YamlParams::fromFiles(files);
  HomingNodeParams params;
  params.pipeline.load(source, nullptr);
  params.law.load(source, params.pipeline.limits);
  // Read by the node's ROS wrapper (wiring, rate, tag filter), not by the law.
  for (const char* key : {"cmd_vel_topic", "rate", "start_enabled", "layout_file", "range_topics",
                          "tag_id", "distance_range_topic"}) {
    source.allow(key);
  }
  source.requireAllKnown();
  params.pipeline.validate();
  params.law.validate();
  return params;
}

sim::Obstacles homingObstacleCourse(double start_x, double start_y, double target_x,
                                    double target_y, int count, double half_size, double keep_clear,
                                    std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const Eigen::Vector2d start(start_x, start_y);
  const Eigen::Vector2d target(target_x, target_y);
  sim::Obstacles world;
  // Clear of the start and the target, measured to the obstacle's surface.
  auto clear = [&](const sim::Obstacles& candidate) {
    return sim::clearance(candidate, start.x(), start.y()) >= keep_clear &&
           sim::clearance(candidate, target.x(), target.y()) >= keep_clear;
  };
  auto draw = [&](const Eigen::Vector2d& centre) {
    sim::Obstacles one;
    if (unit(rng) < 0.6) {
      one.circles.push_back({centre.x(), centre.y(), 0.15 + 0.35 * unit(rng)});
    } else {
      const double length = 1.0 + 2.0 * unit(rng);
      const double angle = kPi * unit(rng);
      const Eigen::Vector2d half = 0.5 * length * Eigen::Vector2d(std::cos(angle), std::sin(angle));
      one.walls.push_back({centre.x() - half.x(), centre.y() - half.y(), centre.x() + half.x(),
                           centre.y() + half.y()});
    }
    return one;
  };
  auto add = [&world](const sim::Obstacles& one) {
    world.circles.insert(world.circles.end(), one.circles.begin(), one.circles.end());
    world.walls.insert(world.walls.end(), one.walls.begin(), one.walls.end());
  };
  // One across the direct path, somewhere in its middle half, so every run must avoid.
  for (int attempt = 0; attempt < 100; ++attempt) {
    const sim::Obstacles one = draw(start + (0.25 + 0.5 * unit(rng)) * (target - start));
    if (clear(one)) {
      add(one);
      break;
    }
  }
  for (int placed = 0, attempt = 0; placed + 1 < count && attempt < 100 * count; ++attempt) {
    const Eigen::Vector2d centre(half_size * (2.0 * unit(rng) - 1.0),
                                 half_size * (2.0 * unit(rng) - 1.0));
    const sim::Obstacles one = draw(centre);
    if (clear(one)) {
      add(one);
      ++placed;
    }
  }
  return world;
}

HomingStep homingControllerStep(const control::HomingControllerParams& params) {
  auto law = std::make_shared<control::HomingController>(params);
  return [law](const HomingMeasurement& m) {
    law->onOdometry(m.odom, m.t, m.t);
    law->onRange(m.distance, m.t);
    law->onBearing(m.bearing, std::numeric_limits<double>::quiet_NaN(), m.t);
    const control::HomingOutput out = law->compute(m.t);
    HomingCommand c;
    c.linear = out.command.linear;
    c.angular = out.command.angular;
    c.arrived = out.state == control::FollowerState::kArrived;
    if (const auto& goal = law->goal()) {
      c.goal_x = goal->x();
      c.goal_y = goal->y();
    }
    return c;
  };
}

std::vector<std::pair<double, double>> homingTargets(int per_quadrant, double half_size,
                                                     double min_distance, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> coordinate(0.0, half_size);
  std::vector<std::pair<double, double>> targets;
  const int signs[4][2] = {{1, 1}, {-1, 1}, {-1, -1}, {1, -1}};
  for (const auto& sign : signs) {
    for (int i = 0; i < per_quadrant;) {
      const double x = sign[0] * coordinate(rng);
      const double y = sign[1] * coordinate(rng);
      if (std::hypot(x, y) >= min_distance) {
        targets.emplace_back(x, y);
        ++i;
      }
    }
  }
  return targets;
}

HomingSummary summarize(const std::vector<HomingResult>& results) {
  HomingSummary s;
  s.runs = static_cast<int>(results.size());
  int successes = 0;
  s.min_clearance = std::numeric_limits<double>::infinity();
  for (const auto& r : results) {
    s.min_clearance = std::min(s.min_clearance, r.min_clearance);
    s.collisions += r.collided;
    if (!r.success) {
      continue;
    }
    ++successes;
    s.time += r.time;
    s.net_velocity += r.net_velocity;
    s.goal_error += r.goal_error;
    s.final_error += r.final_error;
    s.path_efficiency += r.path_efficiency;
  }
  s.success_rate = s.runs > 0 ? double(successes) / s.runs : 0.0;
  if (successes > 0) {
    s.time /= successes;
    s.net_velocity /= successes;
    s.goal_error /= successes;
    s.final_error /= successes;
    s.path_efficiency /= successes;
  }
  return s;
}

}  // namespace evaluation
}  // namespace radio_follow
