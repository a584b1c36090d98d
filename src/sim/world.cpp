// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/sim/world.hpp"

#include <cmath>

#include "radio_follow/common/param_error.hpp"

namespace radio_follow {
namespace sim {
namespace {

double uniform(Rng& rng, double hi) {
  return std::uniform_real_distribution<double>(0.0, hi)(rng);
}

}  // namespace

const ParamTable<WorldConfig>& WorldConfig::table() {
  using W = WorldConfig;
  const Range rate = Range::aboveUpTo(0.0, 1000.0);
  const Range probability = Range::closed(0.0, 1.0);
  static const ParamTable<W> t =
      ParamTable<W>()
          .addChoice(
              "sensor_profile", &W::profile,
              std::vector<std::pair<std::string, SensorProfile>>{
                  {"ideal", SensorProfile::kIdeal}, {"realistic", SensorProfile::kRealistic}},
              "The sensors' errors: the thesis's tables with white noise, or real "
              "hardware's (doc/simulator.md).")
          .add("hardware_seed", &W::hardware_seed, "",
               "Which simulated robot (realistic profile): every module's and board's own "
               "errors.",
               Range::atLeast(0))
          .include(RobotLimits::table(), &W::robot, "robot/")
          .add("twr_rate", &W::rates, &SensorRates::twr_hz, "Hz", "Ranges per module.", rate)
          .add("aoa_rate", &W::rates, &SensorRates::aoa_hz, "Hz", "Bearings per board.", rate)
          .add("tdoa_rate", &W::rates, &SensorRates::tdoa_hz, "Hz", "Tag blinks.", rate)
          .add("twr_table_bias", &W::twr, &TwrNoise::use_table_bias, "",
               "Add Table 3.1's distance-dependent range bias.")
          .add("twr_sigma_scale", &W::twr, &TwrNoise::sigma_scale, "",
               "Multiplies Table 3.1's range sigma.", Range::atLeast(0.0))
          .add("twr_dropout", &W::twr, &TwrNoise::dropout_probability, "",
               "Chance a range epoch reports nothing.", probability)
          .add("aoa_table_bias", &W::aoa, &AoaNoise::use_table_bias, "",
               "Add the AoA tables' mean azimuth error.")
          .add("aoa_sigma_scale", &W::aoa, &AoaNoise::sigma_scale, "",
               "Multiplies the AoA tables' azimuth sigma.", Range::atLeast(0.0))
          .add("aoa_dropout", &W::aoa, &AoaNoise::dropout_probability, "",
               "Chance a bearing is lost.", probability)
          .add("aoa_max_range", &W::aoa, &AoaNoise::max_range, "m", "No bearings beyond.",
               Range::above(0.0))
          .add("tdoa_sigma", &W::tdoa_sigma, "m", "Noise of each TDoA distance difference.",
               Range::atLeast(0.0))
          .add("tdoa_reference", &W::tdoa_reference, "",
               "Index of the anchor differences are taken against.", Range::atLeast(0));
  return t;
}

void WorldConfig::load(const ParamSource& source) {
  table().load(source, *this);
}

void WorldConfig::validate() const {
  table().check(*this);
  for (std::size_t i = 0; i < twr.occlusions.size(); ++i) {
    const auto& o = twr.occlusions[i];
    const std::string name = "~twr_occlusions[" + std::to_string(i) + "]";
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
