// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/sim/world.hpp"

#include <cmath>

#include "radio_follow/common/param_error.hpp"

namespace radio_follow {
namespace sim {
namespace {

bool rateOk(double hz) {
  return std::isfinite(hz) && hz > 0.0 && hz <= 1000.0;
}

double uniform(Rng& rng, double hi) {
  return std::uniform_real_distribution<double>(0.0, hi)(rng);
}

}  // namespace

void WorldConfig::load(const ParamSource& p) {
  std::string profile_name = toString(profile);
  p.param("sensor_profile", profile_name, profile_name);
  profile = parseSensorProfile(profile_name, "~sensor_profile");
  int hardware = static_cast<int>(hardware_seed);
  p.param("hardware_seed", hardware, hardware);
  require(hardware >= 0, "~hardware_seed", hardware, "an integer >= 0");
  hardware_seed = static_cast<std::uint64_t>(hardware);
  p.param("robot/max_linear", robot.max_linear, robot.max_linear);
  p.param("robot/max_angular", robot.max_angular, robot.max_angular);
  p.param("robot/max_linear_accel", robot.max_linear_accel, robot.max_linear_accel);
  p.param("robot/max_linear_decel", robot.max_linear_decel, robot.max_linear_decel);
  p.param("robot/max_angular_accel", robot.max_angular_accel, robot.max_angular_accel);
  p.param("twr_rate", rates.twr_hz, rates.twr_hz);
  p.param("aoa_rate", rates.aoa_hz, rates.aoa_hz);
  p.param("tdoa_rate", rates.tdoa_hz, rates.tdoa_hz);
  p.param("twr_table_bias", twr.use_table_bias, twr.use_table_bias);
  p.param("twr_sigma_scale", twr.sigma_scale, twr.sigma_scale);
  p.param("twr_dropout", twr.dropout_probability, twr.dropout_probability);
  p.param("aoa_table_bias", aoa.use_table_bias, aoa.use_table_bias);
  p.param("aoa_sigma_scale", aoa.sigma_scale, aoa.sigma_scale);
  p.param("aoa_dropout", aoa.dropout_probability, aoa.dropout_probability);
  p.param("aoa_max_range", aoa.max_range, aoa.max_range);
  p.param("tdoa_sigma", tdoa_sigma, tdoa_sigma);
  int reference = static_cast<int>(tdoa_reference);
  p.param("tdoa_reference", reference, reference);
  require(reference >= 0, "~tdoa_reference", reference, "an anchor index >= 0");
  tdoa_reference = static_cast<std::size_t>(reference);
}

void WorldConfig::validate() const {
  robot.validate();
  require(rateOk(rates.twr_hz), "twr_rate", rates.twr_hz, "a rate in (0, 1000] Hz");
  require(rateOk(rates.aoa_hz), "aoa_rate", rates.aoa_hz, "a rate in (0, 1000] Hz");
  require(rateOk(rates.tdoa_hz), "tdoa_rate", rates.tdoa_hz, "a rate in (0, 1000] Hz");
  require(twr.sigma_scale >= 0.0, "twr_sigma_scale", twr.sigma_scale, "a factor >= 0");
  require(twr.dropout_probability >= 0.0 && twr.dropout_probability <= 1.0, "twr_dropout",
          twr.dropout_probability, "a probability in [0, 1]");
  require(aoa.sigma_scale >= 0.0, "aoa_sigma_scale", aoa.sigma_scale, "a factor >= 0");
  require(aoa.dropout_probability >= 0.0 && aoa.dropout_probability <= 1.0, "aoa_dropout",
          aoa.dropout_probability, "a probability in [0, 1]");
  require(tdoa_sigma >= 0.0, "tdoa_sigma", tdoa_sigma, "a standard deviation >= 0 in m");
  for (std::size_t i = 0; i < twr.occlusions.size(); ++i) {
    const auto& o = twr.occlusions[i];
    const std::string name = "twr_occlusions[" + std::to_string(i) + "]";
    require(o.reflection_probability >= 0.0 && o.reflection_probability <= 1.0,
            name + ".probability", o.reflection_probability, "a probability in [0, 1]");
    require(o.reflection_extra >= 0.0, name + ".extra_range", o.reflection_extra, "metres >= 0");
  }
}

World::World(const Layout& layout, const Scenario& scenario, const WorldConfig& config)
    : layout_(layout),
      scenario_(scenario),
      config_(config),
      robot_(config.robot, scenario.robot_start),
      rng_(config.seed) {
  config_.validate();
  require(layout_.tdoa_anchors.empty() || config_.tdoa_reference < layout_.tdoa_anchors.size(),
          "tdoa_reference", config_.tdoa_reference, "an index into the layout's tdoa_anchors");
  for (std::size_t i = 0; i < layout_.twr_modules.size(); ++i) {
    const double period = 1.0 / config_.rates.twr_hz;
    twr_schedule_.push_back(Schedule{period, uniform(rng_, period)});
  }
  for (std::size_t i = 0; i < layout_.aoa_boards.size(); ++i) {
    const double period = 1.0 / config_.rates.aoa_hz;
    aoa_schedule_.push_back(Schedule{period, uniform(rng_, period)});
  }
  tdoa_schedule_ =
      Schedule{1.0 / config_.rates.tdoa_hz, uniform(rng_, 1.0 / config_.rates.tdoa_hz)};
  if (layout_.tdoa_anchors.size() >= 2) {
    // Each module's polls reach the anchors as blinks of its own, as often as the
    // person's device's replies.
    for (std::size_t i = 0; i < layout_.twr_modules.size(); ++i) {
      const double period = 1.0 / config_.rates.tdoa_hz;
      module_blink_schedule_.push_back(Schedule{period, uniform(rng_, period)});
    }
  }
  if (config_.profile == SensorProfile::kRealistic) {
    for (const TwrModule& m : layout_.twr_modules) {
      twr_hardware_.push_back(
          drawTwrHardware(config_.hardware_seed, m.id, layout_.target_anchor_id, config_.figures));
      twr_state_.emplace_back(config_.figures, config_.twr.sigma_scale);
    }
    for (const AoaBoard& b : layout_.aoa_boards) {
      aoa_state_.emplace_back(b, config_.hardware_seed, config_.figures);
    }
    tdoa_hardware_.emplace(layout_.tdoa_anchors, config_.hardware_seed, config_.figures);
  }
}

Eigen::Vector3d World::targetInWorld() const {
  const Pose2 p = scenario_.target.at(t_).pose;
  return Eigen::Vector3d(p.x, p.y, scenario_.target_height);
}

Eigen::Vector3d World::targetInRobot() const {
  const Pose2& r = robot_.pose();
  const Eigen::Vector3d w = targetInWorld();
  const double dx = w.x() - r.x;
  const double dy = w.y() - r.y;
  const double c = std::cos(r.yaw);
  const double s = std::sin(r.yaw);
  return Eigen::Vector3d(c * dx + s * dy, -s * dx + c * dy, w.z());
}

StepEvents World::step(double cmd_linear, double cmd_angular, double dt) {
  StepEvents events;
  if (!(dt > 0.0)) {
    return events;
  }
  robot_.step(cmd_linear, cmd_angular, dt);
  t_ += dt;
  // Sensors sample the world as it is at the end of the step; their report times are
  // their own schedule's, so several modules never report in lockstep.
  const Eigen::Vector3d target = targetInRobot();
  const bool realistic = config_.profile == SensorProfile::kRealistic;
  for (std::size_t i = 0; i < twr_schedule_.size(); ++i) {
    const TwrModule& module = layout_.twr_modules[i];
    for (Schedule& s = twr_schedule_[i]; s.next <= t_; s.next += s.period) {
      const auto range = realistic ? simulateRealisticTwr(module, twr_hardware_[i], config_.twr,
                                                          twr_state_[i], target, s.next, rng_)
                                   : simulateTwrRange(module, config_.twr, target, rng_);
      if (range) {
        events.twr.push_back(TwrEvent{s.next, i, *range});
      }
    }
  }
  for (std::size_t i = 0; i < aoa_schedule_.size(); ++i) {
    for (Schedule& s = aoa_schedule_[i]; s.next <= t_; s.next += s.period) {
      const auto sample = realistic ? aoa_state_[i].simulate(config_.aoa, target, s.next, rng_)
                                    : simulateAoa(layout_.aoa_boards[i], config_.aoa, target, rng_);
      if (sample) {
        events.aoa.push_back(AoaEvent{s.next, i, *sample});
      }
    }
  }
  if (layout_.tdoa_anchors.size() >= 2) {
    const auto blink = [&](const Eigen::Vector3d& from, double t) {
      return simulateBlink(tdoa_hardware_, layout_.tdoa_anchors, config_.tdoa_reference,
                           config_.tdoa_sigma, from, t, rng_);
    };
    const auto add = [&](std::vector<double> differences, double t,
                         std::optional<std::size_t> module) {
      if (!differences.empty()) {
        events.tdoa.push_back(TdoaEvent{t, std::move(differences), module});
      }
    };
    for (Schedule& s = tdoa_schedule_; s.next <= t_; s.next += s.period) {
      add(blink(target, s.next), s.next, std::nullopt);
    }
    for (std::size_t i = 0; i < module_blink_schedule_.size(); ++i) {
      for (Schedule& s = module_blink_schedule_[i]; s.next <= t_; s.next += s.period) {
        add(blink(layout_.twr_modules[i].position, s.next), s.next, i);
      }
    }
  }
  return events;
}

}  // namespace sim
}  // namespace radio_follow
