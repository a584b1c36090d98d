// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/evaluation/experiment.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "radio_follow/common/param_error.hpp"
#include "radio_follow/common/yaml_params.hpp"

namespace radio_follow {
namespace evaluation {
namespace {

template <typename... Args>
std::string format(const char* pattern, Args... args) {
  char text[200];
  std::snprintf(text, sizeof(text), pattern, args...);
  return text;
}

std::optional<double> optionalNumber(const YamlParams& p, const std::string& name) {
  double value = std::numeric_limits<double>::quiet_NaN();
  p.param(name, value, value);
  return std::isnan(value) ? std::nullopt : std::optional<double>(value);
}

}  // namespace

std::vector<Experiment> loadExperiments(const std::string& path) {
  const YamlParams file = YamlParams::fromFile(path);
  std::vector<Experiment> experiments;
  std::string file_profile = "ideal";
  const YAML::Node file_profile_node = file.root()["sensor_profile"];
  if (file_profile_node.IsDefined()) {
    require(file_profile_node.IsScalar(), path + ": sensor_profile", YAML::Dump(file_profile_node),
            "'realistic' or 'ideal'");
    file_profile = file_profile_node.as<std::string>();
  }
  const sim::SensorProfile profile =
      sim::parseSensorProfile(file_profile, path + ": sensor_profile");
  for (const auto& entry : file.root()) {
    Experiment e;
    e.name = entry.first.as<std::string>();
    if (e.name == "sensor_profile") {
      continue;
    }
    const std::string where = path + ": " + e.name;
    // The controller parameters are the nodes' (checked as they load them), not the entry's.
    YAML::Node fields = YAML::Clone(entry.second);
    fields.remove("controller_params");
    const YamlParams p(fields);
    p.param("layout", e.layout, e.layout);
    p.param("scenario", e.scenario, e.scenario);
    p.param("locator_overrides", e.locator_overrides, e.locator_overrides);
    std::string controller = "velocity_controller";
    p.param("controller", controller, controller);
    require(controller == "velocity_controller" || controller == "path_follower",
            where + ".controller", controller, "velocity_controller or path_follower");
    e.controller = controller == "path_follower" ? FollowController::kPathFollower
                                                 : FollowController::kVelocity;
    require(!e.layout.empty() && !e.scenario.empty(), where, e.name,
            "a layout and a scenario name");
    std::string own_profile = sim::toString(profile);
    p.param("sensor_profile", own_profile, own_profile);
    e.sensor_profile = sim::parseSensorProfile(own_profile, where + ".sensor_profile");
    const YAML::Node controller_params = entry.second["controller_params"];
    if (controller_params.IsDefined()) {
      require(controller_params.IsMap(), where + ".controller_params",
              YAML::Dump(controller_params), "a mapping of controller parameters");
      e.controller_params = YAML::Clone(controller_params);
    }
    p.allow("outages");
    const YAML::Node outages = entry.second["outages"];
    for (std::size_t i = 0; outages && i < outages.size(); ++i) {
      const YAML::Node o = outages[i];
      require(o.IsSequence() && o.size() == 3, where + ".outages[" + std::to_string(i) + "]",
              YAML::Dump(o), "[sensor id, at s, duration s]");
      try {
        e.outages.push_back({o[0].as<std::string>(), o[1].as<double>(), o[2].as<double>()});
      } catch (const YAML::Exception&) {
        throw ParamError(where + ".outages[" + std::to_string(i) + "]", YAML::Dump(o),
                         "[sensor id, at s, duration s]");
      }
    }
    ExperimentCheck& c = e.check;
    c.min_gap_while_moving = optionalNumber(p, "check/min_gap_while_moving");
    c.min_gap_within_tolerance = optionalNumber(p, "check/min_gap_within_tolerance");
    c.max_estimate_error_median = optionalNumber(p, "check/max_estimate_error_median");
    c.max_path_deviation = optionalNumber(p, "check/max_path_deviation");
    c.max_path_deviation_beyond_estimate =
        optionalNumber(p, "check/max_path_deviation_beyond_estimate");
    c.resume_after = optionalNumber(p, "check/resume_after");
    c.min_clearance = optionalNumber(p, "check/min_clearance");
    std::vector<double> window;
    p.param("check/stop_window", window, window);
    if (!window.empty()) {
      require(window.size() == 2 && window[0] < window[1], where + ".check.stop_window",
              window.size(), "[from, until] in seconds");
      c.stop_window = std::make_pair(window[0], window[1]);
    }
    p.requireAllKnown();
    experiments.push_back(e);
  }
  return experiments;
}

std::vector<std::string> checkRun(const ExperimentCheck& check, const control::FollowReport& r,
                                  const std::vector<CommandAt>& commands) {
  std::vector<std::string> violations;
  if (check.min_gap_while_moving && !(r.min_gap_while_moving >= *check.min_gap_while_moving)) {
    violations.push_back(format("commanded to move %.3f m from the person (at least %.2f)",
                                r.min_gap_while_moving, *check.min_gap_while_moving));
  }
  if (check.min_gap_within_tolerance &&
      !(r.gap_within_tolerance >= *check.min_gap_within_tolerance)) {
    violations.push_back(format("gap held %.3f of the walk (at least %.2f)", r.gap_within_tolerance,
                                *check.min_gap_within_tolerance));
  }
  if (check.max_estimate_error_median &&
      !(r.estimate_error_median <= *check.max_estimate_error_median)) {
    violations.push_back(format("median estimate error %.3f m (at most %.2f)",
                                r.estimate_error_median, *check.max_estimate_error_median));
  }
  if (check.max_path_deviation && !(r.path_deviation_max <= *check.max_path_deviation)) {
    violations.push_back(format("path deviation %.3f m (at most %.2f)", r.path_deviation_max,
                                *check.max_path_deviation));
  }
  if (check.max_path_deviation_beyond_estimate &&
      !(r.path_deviation_max <= r.estimate_error_p95 + *check.max_path_deviation_beyond_estimate)) {
    violations.push_back(format("path deviation %.3f m (at most the estimate's p95 %.3f + %.2f)",
                                r.path_deviation_max, r.estimate_error_p95,
                                *check.max_path_deviation_beyond_estimate));
  }
  if (check.stop_window) {
    const auto [from, until] = *check.stop_window;
    int ticks = 0;
    double worst = 0.0;
    for (const CommandAt& c : commands) {
      if (c.t >= from && c.t <= until) {
        ++ticks;
        worst = std::max(worst, std::abs(c.linear));
      }
    }
    if (ticks == 0) {
      violations.push_back(format("no command in the stop window %.1f-%.1f s", from, until));
    } else if (worst != 0.0) {
      violations.push_back(
          format("told to move at %.3f m/s in the stop window (from %.1f s)", worst, from));
    }
  }
  if (check.min_clearance && !(r.min_clearance >= *check.min_clearance)) {
    violations.push_back(
        r.collided ? format("hit an obstacle at %.1f s (clearance %.3f m, at least %.2f)",
                            r.collision_time, r.min_clearance, *check.min_clearance)
                   : format("came %.3f m from an obstacle (at least %.2f)", r.min_clearance,
                            *check.min_clearance));
  }
  if (check.resume_after && !std::any_of(commands.begin(), commands.end(), [&](const CommandAt& c) {
        return c.t > *check.resume_after && c.linear > 0.1;
      })) {
    violations.push_back(format("never drove again after %.1f s", *check.resume_after));
  }
  return violations;
}

bool keptFollowing(const control::FollowReport& report, const control::FollowSettings& settings) {
  return !report.collided &&
         std::abs(report.final_gap - settings.follow_distance) <= settings.gap_tolerance;
}

ExperimentResult runExperiment(const Experiment& experiment, const std::string& config_dir,
                               int seed) {
  ClosedLoopConfig config = loadClosedLoopConfig(
      config_dir, experiment.layout, experiment.scenario, experiment.controller, seed, "",
      experiment.locator_overrides.empty() ? "" : config_dir + "/" + experiment.locator_overrides,
      experiment.sensor_profile, experiment.controller_params);
  config.outages = experiment.outages;
  ClosedLoop loop(config);
  ExperimentResult result;
  result.report = loop.run();
  std::vector<CommandAt> commands;
  for (const auto& c : loop.commands()) {
    commands.push_back({c.t, c.command.linear});
  }
  result.violations = checkRun(experiment.check, result.report, commands);
  result.violations.insert(result.violations.begin(), result.report.failures.begin(),
                           result.report.failures.end());
  result.kept_following = keptFollowing(result.report, config.metrics);
  return result;
}

}  // namespace evaluation
}  // namespace radio_follow
