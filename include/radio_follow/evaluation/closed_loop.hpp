// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <yaml-cpp/yaml.h>

#include <deque>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "radio_follow/config/layout.hpp"
#include "radio_follow/control/command_pipeline.hpp"
#include "radio_follow/control/controller_params.hpp"
#include "radio_follow/control/follow_metrics.hpp"
#include "radio_follow/control/follower.hpp"
#include "radio_follow/control/path_follower.hpp"
#include "radio_follow/control/velocity_law.hpp"
#include "radio_follow/estimation/locator.hpp"
#include "radio_follow/estimation/locator_node_params.hpp"
#include "radio_follow/estimation/odometry_estimate.hpp"
#include "radio_follow/sim/obstacles.hpp"
#include "radio_follow/sim/simulator_params.hpp"
#include "radio_follow/sim/target_path.hpp"
#include "radio_follow/sim/world.hpp"

namespace radio_follow {
namespace evaluation {

/// A sensor that goes silent for a while (an unplugged cable, a flat battery): its
/// events are dropped from `at` for `duration` scenario seconds.
struct SensorOutage {
  std::string sensor;  ///< TWR module ID or AoA board ID of the layout
  double at = 0.0;     ///< s
  double duration = 0.0;
};

enum class FollowController { kVelocity, kPathFollower };

/// Everything a closed-loop run needs, as the nodes of follower.launch and
/// simulator.launch get it (loadClosedLoopConfig reads the same shipped files).
struct ClosedLoopConfig {
  /// Where the sensors are meant to be: the simulated world's layout.
  Layout layout;
  /// The layout the locator is given. Empty: ClosedLoop fills it with
  /// locatorLayoutFor(layout, world) (evaluation/calibration_run.hpp): it first runs the
  /// calibration run on this run's simulated hardware. Its calibrations are also the ones
  /// the safety stop corrects raw ranges with (pipeline, with calibrate_ranges), as on a
  /// robot whose nodes read one layout file.
  std::optional<Layout> locator_layout;
  sim::Scenario scenario;
  sim::WorldConfig world;
  double step_rate = sim::SimulatorParams().step_rate;      ///< simulator physics steps per s
  double cmd_timeout = sim::SimulatorParams().cmd_timeout;  ///< s without a command: base stops
  /// The laser scanner of a scenario with obstacles (simulator.yaml's `scan/*`): scanned
  /// at `scan.rate` as the ROS simulator publishes it and handed to the command pipeline,
  /// which uses it with the controller's `use_scan` (the node subscribes only then).
  sim::ScanConfig scan;
  /// The robot's footprint, a circle around its origin, m: its clearance to the
  /// scenario's obstacles is the origin's minus this, and below 0 is a collision, which
  /// ends the run. 0.2 m as in the homing benchmark: the shipped avoidance thresholds
  /// (seed 000's Table A1) fit a robot that size (config/controller_common.yaml).
  double robot_radius = 0.2;
  estimation::LocatorConfig locator;
  double locator_rate = estimation::LocatorNodeParams().rate;  ///< Hz
  /// The locator node's odom_frame is set: measurements carry the robot's odometry pose
  /// (the loop's TF), the particle estimator tracks in the odometry frame.
  bool locator_odometry = true;
  /// The locator node's tf_tolerance: a stamp newer than the newest odometry pose is
  /// placed with that pose when it is at most this much newer, s.
  double tf_tolerance = estimation::LocatorNodeParams().tf_tolerance;
  FollowController controller = FollowController::kVelocity;
  control::CommandPipelineParams pipeline;
  double controller_rate = control::ControllerWiring().rate;  ///< Hz
  control::VelocityLawParams law;
  control::PathFollowParams path;
  control::FollowSettings metrics;
  double evaluator_rate = control::FollowEvaluatorParams().rate;  ///< Hz, as the evaluator samples
  std::vector<SensorOutage> outages;

  /// Throws ParamError naming the first unusable field.
  void validate() const;
};

/// Reads a run's configuration from the package's config directory exactly as the launch
/// files do: config/simulator.yaml, the layout and scenario by name, config/locator.yaml
/// (then `locator_overrides` if not empty), config/controller_common.yaml,
/// config/velocity_controller.yaml, config/path_follower.yaml for the path follower (then
/// the file `controller_params` if not empty, as follower.launch's `controller_params`
/// argument, then the mapping `controller_overrides` if given, e.g. `{use_scan: true}`).
/// Unknown keys in the controller parameters are refused as the nodes refuse them.
/// `profile` replaces simulator.yaml's sensor_profile when given. The simulated hardware
/// is the seed's (world.hardware_seed = seed), so runs over seeds are runs on as many
/// robots. Throws ParamError.
ClosedLoopConfig loadClosedLoopConfig(const std::string& config_dir, const std::string& layout,
                                      const std::string& scenario, FollowController controller,
                                      int seed, const std::string& controller_params = "",
                                      const std::string& locator_overrides = "",
                                      std::optional<sim::SensorProfile> profile = std::nullopt,
                                      const YAML::Node& controller_overrides = YAML::Node());

/// The whole follow loop in one process on simulated time: world and sensors (sim::World),
/// the locator, the controller's law and the command pipeline (safety stop, limits), and
/// the follow evaluator's metrics, each at its node's rate, in a fixed order within a
/// step. No threads, no wall clock: the same configuration and seed give bit-identical
/// metrics. What it leaves out of the ROS loop: transport latency (messages arrive in the
/// step they are sent), the drivers' parsing and reconnects (an outage is silence only).
class ClosedLoop {
 public:
  explicit ClosedLoop(const ClosedLoopConfig& config);
  ~ClosedLoop();
  ClosedLoop(const ClosedLoop&) = delete;
  ClosedLoop& operator=(const ClosedLoop&) = delete;

  /// Runs the scenario to its end, or to the first collision with an obstacle, and
  /// returns the evaluator's report.
  control::FollowReport run();
  /// One physics step (1 / step_rate s); false once the scenario is over or the robot has
  /// hit an obstacle.
  bool step();

  const control::FollowMetrics& metrics() const { return metrics_; }
  const sim::World& world() const { return world_; }
  /// The layout the locator runs with (calibrated with the realistic profile).
  const Layout& locatorLayout() const { return *config_.locator_layout; }
  const estimation::LocatorStats& locatorStats() const { return locator_.stats(); }
  /// One controller tick's command, on the simulator's clock (scenario time + 1 s, as
  /// the ROS simulator stamps).
  struct CommandSample {
    double t;
    control::VelocityCommand command;
    bool stopped;  ///< the safety layer forbade motion
  };
  const std::vector<CommandSample>& commands() const { return commands_; }

 private:
  struct Timer {
    double period;
    double next;
    bool due(double t);
  };
  struct PoseAt {
    double t;
    Pose2 pose;
  };

  bool silent(const std::string& sensor, double t) const;
  void feedSensors(const sim::StepEvents& events, double now);
  /// With obstacles: the footprint's clearance every step (a collision sets collided_),
  /// the scan to the pipeline at its rate.
  void watchObstacles(double now);
  void runLocator(double now);
  void runController(double now);
  void sample(double now);
  /// The robot's odometry pose at time t (linear interpolation, as TF does).
  /// poseAt() for the locator's measurements, when it tracks in the odometry frame.
  std::optional<Pose2> odometryAt(double t) const;
  std::optional<Pose2> poseAt(double t) const;

  ClosedLoopConfig config_;
  sim::World world_;
  estimation::Locator locator_;
  estimation::OdometryTrack odometry_track_;  ///< as locator_node's
  /// The controller node's law and core (the same classes the nodes run).
  std::unique_ptr<control::FollowLaw> law_;
  control::Follower follower_;
  control::FollowMetrics metrics_;
  Timer locator_timer_;
  Timer controller_timer_;
  Timer evaluator_timer_;
  Timer scan_timer_;
  sim::Rng scan_rng_;  ///< the scan's noise, apart from the world's (as the ROS simulator's)
  bool collided_ = false;
  std::optional<estimation::LocatorEstimate> estimate_;  ///< the newest one published
  double estimate_stamp_ = 0.0;
  control::VelocityCommand command_;
  double command_time_ = -1e9;
  std::deque<PoseAt> poses_;                              ///< odometry history (TF buffer)
  std::deque<std::pair<double, Eigen::Vector3d>> truth_;  ///< target in the robot frame
  std::vector<CommandSample> commands_;
};

}  // namespace evaluation
}  // namespace radio_follow
