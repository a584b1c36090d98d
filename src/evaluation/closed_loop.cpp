// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/evaluation/closed_loop.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "radio_follow/common/angles.hpp"
#include "radio_follow/common/param_error.hpp"
#include "radio_follow/common/yaml_params.hpp"
#include "radio_follow/control/target_track.hpp"
#include "radio_follow/estimation/odometry_estimate.hpp"
#include "radio_follow/evaluation/calibration_run.hpp"
#include "radio_follow/evaluation/simulated_scan.hpp"
#include "radio_follow/evaluation/simulated_tdoa.hpp"

namespace radio_follow {
namespace evaluation {
namespace {

/// The simulator's clock reads this at the scenario's start (stamps are never zero).
constexpr double kClockStart = 1.0;
/// Seconds of odometry and ground truth kept (the TF buffer, the evaluator's history).
constexpr double kHistory = 2.0;

bool rateOk(double hz) {
  return std::isfinite(hz) && hz > 0.0 && hz <= 1000.0;
}

}  // namespace

void ClosedLoopConfig::validate() const {
  world.validate();
  require(std::isfinite(step_rate) && step_rate >= 10.0 && step_rate <= 10000.0, "step_rate",
          step_rate, "a rate in [10, 10000] Hz");
  require(std::isfinite(cmd_timeout) && cmd_timeout > 0.0, "cmd_timeout", cmd_timeout,
          "seconds > 0");
  scan.validate();
  require(std::isfinite(robot_radius) && robot_radius >= 0.0, "robot_radius", robot_radius,
          "a radius >= 0 in m");
  locator.validate();
  require(rateOk(locator_rate), "locator rate", locator_rate, "a rate in (0, 1000] Hz");
  pipeline.validate();
  require(rateOk(controller_rate), "controller rate", controller_rate, "a rate in (0, 1000] Hz");
  law.validate();
  path.validate();
  require(std::isfinite(tf_tolerance) && tf_tolerance >= 0.0 && tf_tolerance <= 1.0,
          "~tf_tolerance", tf_tolerance, "a tolerance in [0, 1] seconds");
  require(rateOk(evaluator_rate), "evaluator rate", evaluator_rate, "a rate in (0, 1000] Hz");
  if (locator_layout) {
    // The locator hears the world's sensors by ID: a calibrated layout of the same robot.
    locator_layout->validate();
    const auto ids = [](const Layout& l) {
      std::vector<std::string> out;
      for (const TwrModule& m : l.twr_modules) {
        out.push_back(m.id);
      }
      for (const AoaBoard& b : l.aoa_boards) {
        out.push_back(b.id);
      }
      for (const TdoaAnchor& a : l.tdoa_anchors) {
        out.push_back(a.id);
      }
      return out;
    };
    // The world's sensor indices are the locator's.
    require(ids(*locator_layout) == ids(layout), "locator_layout", std::string("(a layout)"),
            "the same TWR modules, AoA boards and TDoA anchors as the world's layout, in the "
            "same order");
  }
  for (const SensorOutage& o : outages) {
    const bool known = std::any_of(layout.twr_modules.begin(), layout.twr_modules.end(),
                                   [&](const TwrModule& m) { return m.id == o.sensor; }) ||
                       std::any_of(layout.aoa_boards.begin(), layout.aoa_boards.end(),
                                   [&](const AoaBoard& b) { return b.id == o.sensor; });
    require(known, "outage sensor", o.sensor, "a TWR module or AoA board ID of the layout");
    require(std::isfinite(o.at) && o.at >= 0.0 && std::isfinite(o.duration) && o.duration > 0.0,
            "outage of " + o.sensor, o.at, "a start >= 0 s and a duration > 0 s");
  }
}

ClosedLoopConfig loadClosedLoopConfig(const std::string& dir, const std::string& layout,
                                      const std::string& scenario, FollowController controller,
                                      int seed, const std::string& controller_params,
                                      const std::string& locator_overrides,
                                      std::optional<sim::SensorProfile> profile,
                                      const YAML::Node& controller_overrides) {
  require(seed >= 0, "seed", seed, "an integer >= 0");
  ClosedLoopConfig c;
  c.controller = controller;
  c.layout = loadLayoutFile(dir + "/layouts/" + layout + ".yaml");
  c.scenario = sim::loadScenarioFile(dir + "/scenarios/" + scenario + ".yaml",
                                     static_cast<std::uint64_t>(seed));

  // simulator.launch: config/simulator.yaml, seed from the launch.
  const YamlParams simulator = YamlParams::fromFile(dir + "/simulator.yaml");
  sim::SimulatorParams simulator_node;
  sim::SimulatorParams::table().load(simulator, simulator_node);
  c.world = simulator_node.world;
  c.world.seed = static_cast<std::uint64_t>(seed);
  // One robot per seed: nothing gets tuned to one simulated robot's hardware.
  c.world.hardware_seed = static_cast<std::uint64_t>(seed);
  if (profile) {
    c.world.profile = *profile;
  }
  c.step_rate = simulator_node.step_rate;
  c.cmd_timeout = simulator_node.cmd_timeout;
  c.scan = simulator_node.scan;  // the laser scan of scenarios with obstacles
  simulator.allow("unplug");     // the ROS node's serial devices
  const YAML::Node occlusions = simulator.root()["twr_occlusions"];
  simulator.allow("twr_occlusions");
  require(!occlusions.IsDefined() || occlusions.IsNull() || occlusions.size() == 0,
          "~twr_occlusions", std::string("(a list)"),
          "an empty list: the lockstep loop does not simulate occlusions (the ROS simulator "
          "does)");
  simulator.requireAllKnown();

  // follower.launch: the locator's file, then the overrides.
  std::vector<std::string> locator_files{dir + "/locator.yaml"};
  if (!locator_overrides.empty()) {
    locator_files.push_back(locator_overrides);
  }
  const YamlParams locator = YamlParams::fromFiles(locator_files);
  estimation::LocatorNodeParams locator_node;
  locator_node.load(locator);
  c.locator = locator_node.locator;
  c.locator_rate = locator_node.rate;
  c.locator_odometry = !locator_node.odom_frame.empty();
  c.tf_tolerance = locator_node.tf_tolerance;
  locator.requireAllKnown();

  // follower.launch: the controller's files in the same order.
  std::vector<std::string> files{dir + "/controller_common.yaml",
                                 dir + "/velocity_controller.yaml"};
  if (controller == FollowController::kPathFollower) {
    files.push_back(dir + "/path_follower.yaml");
  }
  if (!controller_params.empty()) {
    files.push_back(controller_params);
  }
  const YamlParams p = YamlParams::fromFiles(files).mergedWith(controller_overrides);
  c.pipeline.load(p, &c.layout);
  control::ControllerWiring wiring;
  control::ControllerWiring::table().load(p, wiring);
  c.controller_rate = wiring.rate;
  c.law = control::loadVelocityLawParams(p, c.pipeline);
  if (controller == FollowController::kPathFollower) {
    c.path.load(p);
    // The node's frames: the lockstep loop has one odometry frame and one robot.
    p.allow("base_frame");
    p.allow("odom_frame");
  }
  for (const char* key : {"range_topics", "law"}) {  // the node's topics and live tuning
    p.allow(key);
  }
  p.requireAllKnown();
  c.validate();
  return c;
}

bool ClosedLoop::Timer::due(double t) {
  if (t + 1e-9 < next) {
    return false;
  }
  while (next <= t + 1e-9) {
    next += period;
  }
  return true;
}

ClosedLoop::ClosedLoop(const ClosedLoopConfig& config)
    : config_([&] {
        config.validate();
        ClosedLoopConfig c = config;
        if (!c.locator_layout) {
          c.locator_layout = locatorLayoutFor(c.layout, c.world);
        }
        // A robot's nodes read one layout file: the safety stop corrects the raw ranges
        // with the same calibration the locator gets (control::CommandPipelineParams::load).
        if (c.pipeline.calibrate_ranges) {
          c.pipeline.calibrated_modules.clear();
          for (const TwrModule& module : c.locator_layout->twr_modules) {
            c.pipeline.calibrated_modules[module.id] = module;
          }
          c.pipeline.validate();
        }
        return c;
      }()),
      world_(config_.layout, config_.scenario, config_.world),
      locator_(*config_.locator_layout, config_.locator),
      law_(config_.controller == FollowController::kVelocity
               ? std::unique_ptr<control::FollowLaw>(new control::VelocityLaw(config_.law))
               : std::make_unique<control::PathFollowLaw>(config_.path, config_.law)),
      follower_(config_.pipeline),
      metrics_(config_.metrics),
      locator_timer_{1.0 / config_.locator_rate, kClockStart + 1.0 / config_.locator_rate},
      controller_timer_{1.0 / config_.controller_rate, kClockStart + 1.0 / config_.controller_rate},
      evaluator_timer_{1.0 / config_.evaluator_rate, kClockStart + 1.0 / config_.evaluator_rate},
      // The ROS simulator scans on its first step, with a generator of its own.
      scan_timer_{1.0 / config_.scan.rate, kClockStart},
      scan_rng_(config_.world.seed + 1) {
  follower_.setLaw(*law_);
  follower_.pipeline().setEnabled(true);  // start_enabled, as the demo and the experiments run
  poses_.push_back(PoseAt{kClockStart, world_.robot().pose()});
}

ClosedLoop::~ClosedLoop() = default;

control::FollowReport ClosedLoop::run() {
  while (step()) {
  }
  return metrics_.report();
}

bool ClosedLoop::step() {
  if (world_.finished() || collided_) {
    return false;
  }
  // The base stops by itself when its command stream stops.
  const bool fresh = world_.time() + kClockStart - command_time_ <= config_.cmd_timeout;
  const sim::StepEvents events = world_.step(
      fresh ? command_.linear : 0.0, fresh ? command_.angular : 0.0, 1.0 / config_.step_rate);
  const double now = kClockStart + world_.time();
  poses_.push_back(PoseAt{now, world_.robot().pose()});
  truth_.emplace_back(now, world_.targetInRobot());
  while (!poses_.empty() && poses_.front().t < now - kHistory) {
    poses_.pop_front();
  }
  while (!truth_.empty() && truth_.front().first < now - kHistory) {
    truth_.pop_front();
  }
  feedSensors(events, now);
  watchObstacles(now);
  if (locator_timer_.due(now)) {
    runLocator(now);
  }
  if (controller_timer_.due(now)) {
    runController(now);
  }
  if (evaluator_timer_.due(now)) {
    sample(now);
  }
  // A collision ends the run: the simulated base has no contact model and would drive on
  // through the obstacle.
  return !collided_;
}

void ClosedLoop::watchObstacles(double now) {
  const sim::Obstacles& obstacles = world_.scenario().obstacles;
  if (obstacles.empty()) {
    return;
  }
  const Pose2& pose = world_.robot().pose();
  const double clearance = sim::clearance(obstacles, pose.x, pose.y) - config_.robot_radius;
  metrics_.addClearance(now, clearance);
  collided_ = clearance < 0.0;
  if (scan_timer_.due(now)) {
    // The controller's scan callback: sectors and the scan's stamp (its pipeline ignores
    // them without use_scan, as the node then does not subscribe).
    std::normal_distribution<double> noise(0.0, config_.scan.sigma);
    control::CommandPipeline& pipeline = follower_.pipeline();
    pipeline.onScan(
        simulatedScanSectors(obstacles, config_.scan, pose,
                             pipeline.params().avoidance.side_threshold, noise, scan_rng_),
        now);
  }
}

bool ClosedLoop::silent(const std::string& sensor, double t) const {
  const double scenario_time = t - kClockStart;
  return std::any_of(config_.outages.begin(), config_.outages.end(), [&](const SensorOutage& o) {
    return o.sensor == sensor && scenario_time >= o.at && scenario_time < o.at + o.duration;
  });
}

void ClosedLoop::feedSensors(const sim::StepEvents& events, double now) {
  const Layout& layout = config_.layout;
  for (const sim::TwrEvent& e : events.twr) {
    const TwrModule& module = layout.twr_modules[e.module];
    const double stamp = kClockStart + e.t;
    if (silent(module.id, stamp)) {
      continue;
    }
    locator_.addRange(e.module, e.range, stamp, odometryAt(stamp));
    // The controller watches the same ranges (uwb/<id>/ranges) for its safety stop.
    follower_.pipeline().onRange(stamp, now, "uwb/" + module.id + "/ranges/" + module.id, module.id,
                                 layout.target_anchor_id, e.range);
  }
  for (const sim::AoaEvent& e : events.aoa) {
    const AoaBoard& board = layout.aoa_boards[e.board];
    const double stamp = kClockStart + e.t;
    if (silent(board.id, stamp)) {
      continue;
    }
    locator_.addBearing(e.board, e.sample.azimuth, e.sample.elevation, e.sample.rssi, stamp,
                        odometryAt(stamp));
  }
  for (const sim::TdoaEvent& e : events.tdoa) {
    const double stamp = kClockStart + e.t;
    // As LocatorInputs routes the driver's messages: the robot's own modules' blinks
    // calibrate the anchors, the target's are fused.
    feedTdoaBlink(locator_, layout, config_.world.tdoa_reference, e.differences, e.module,
                  config_.world.tdoa_sigma * config_.world.tdoa_sigma, stamp,
                  e.module ? std::nullopt : odometryAt(stamp));
  }
}

std::optional<Pose2> ClosedLoop::odometryAt(double t) const {
  return config_.locator_odometry ? poseAt(t) : std::nullopt;
}

std::optional<Pose2> ClosedLoop::poseAt(double t) const {
  if (poses_.empty()) {
    return std::nullopt;
  }
  if (t >= poses_.back().t) {
    // TF has nothing newer: the newest transform, when it is within tf_tolerance.
    return t - poses_.back().t <= config_.tf_tolerance ? std::optional<Pose2>(poses_.back().pose)
                                                       : std::nullopt;
  }
  if (t < poses_.front().t) {
    return std::nullopt;
  }
  const auto after = std::lower_bound(poses_.begin(), poses_.end(), t,
                                      [](const PoseAt& p, double time) { return p.t < time; });
  if (after == poses_.begin()) {
    return after->pose;
  }
  const PoseAt& a = *(after - 1);
  const PoseAt& b = *after;
  const double w = (t - a.t) / (b.t - a.t);
  Pose2 pose;
  pose.x = a.pose.x + w * (b.pose.x - a.pose.x);
  pose.y = a.pose.y + w * (b.pose.y - a.pose.y);
  pose.yaw = wrapAngle(a.pose.yaw + w * wrapAngle(b.pose.yaw - a.pose.yaw));
  return pose;
}

void ClosedLoop::runLocator(double now) {
  estimation::LocatorEstimate estimate = locator_.update(now);
  // Stamped with its newest measurement; LOST with the current time (locator_node).
  estimate_stamp_ = estimate.status == TargetStatus::kLost ? now : std::max(0.0, estimate.stamp);
  const double range = estimate.position.head<2>().norm();
  const double bearing = std::atan2(estimate.position.y(), estimate.position.x());
  // Every estimate gets its odometry-frame part, as locator_node fills every message's;
  // one no robot can act on makes the estimate LOST for the controller (estimateQuality).
  const std::optional<estimation::OdometryEstimate> odom =
      odometry_track_.update(estimate, [this](double t) { return odometryAt(t); });
  const Eigen::Vector3d unknown =
      Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
  const bool acted_on = !odom || control::plausibleOdometryPart(
                                     Eigen::Vector3d(odom->robot.x(), odom->robot.y(), 0.0),
                                     odom->position, odom->velocity.value_or(unknown));
  // The controller's estimate callback: the follower core, then the estimate's own
  // odometry-frame part.
  const control::EstimateUse use = follower_.onEstimate(
      estimate_stamp_, now, acted_on ? estimate.status : TargetStatus::kLost, range, bearing,
      polarSpread(estimate.position.head<2>(), estimate.covariance.topLeftCorner<2, 2>()),
      estimate.hypotheses);
  if (use == control::EstimateUse::kTrackPoint && odom) {
    std::optional<Eigen::Vector2d> velocity;
    if (odom->velocity) {
      velocity = odom->velocity->head<2>();
    }
    if (const auto point = control::trackPoint(odom->robot, odom->position.head<2>(), velocity)) {
      follower_.addTrackPoint(estimate_stamp_, *point);
    }
  }
  estimate_ = std::move(estimate);
}

void ClosedLoop::runController(double now) {
  // The path follower knows the robot's pose from TF; the velocity law does not ask.
  const control::PipelineResult result =
      follower_.tick(now, 1.0 / config_.controller_rate, poses_.back().pose);
  commands_.push_back(CommandSample{now, result.command, !result.moving});
  command_ = result.command;
  command_time_ = now;
}

void ClosedLoop::sample(double now) {
  const Pose2& pose = world_.robot().pose();
  control::FollowSample s;
  s.t = now;
  s.robot_x = pose.x;
  s.robot_y = pose.y;
  s.robot_yaw = pose.yaw;
  s.robot_speed = world_.robot().linear();
  s.cmd_linear = command_.linear;
  s.cmd_angular = command_.angular;
  const Eigen::Vector3d target = world_.targetInWorld();
  s.target_x = target.x();
  s.target_y = target.y();
  s.target_speed = world_.targetSpeed();
  s.truth_x = truth_.back().second.x();
  s.truth_y = truth_.back().second.y();
  if (estimate_) {
    s.estimate_status = toString(estimate_->status);
    if (hasPosition(estimate_->status) && estimate_stamp_ <= now &&
        now - estimate_stamp_ <= control::kSampleEstimateMaxAge) {
      // Compare with the truth closest to the estimate's stamp.
      const auto closest =
          std::min_element(truth_.begin(), truth_.end(), [&](const auto& a, const auto& b) {
            return std::abs(a.first - estimate_stamp_) < std::abs(b.first - estimate_stamp_);
          });
      s.truth_x = closest->second.x();
      s.truth_y = closest->second.y();
      s.estimate_x = estimate_->position.x();
      s.estimate_y = estimate_->position.y();
      const Eigen::Matrix3d& c = estimate_->covariance;
      s.estimate_covariance = std::array<double, 3>{c(0, 0), c(0, 1), c(1, 1)};
    }
  }
  metrics_.add(s);
}

}  // namespace evaluation
}  // namespace radio_follow
