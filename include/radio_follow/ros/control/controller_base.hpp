// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <diagnostic_updater/diagnostic_updater.h>
#include <ros/callback_queue.h>
#include <ros/ros.h>
#include <sensor_msgs/LaserScan.h>
#include <std_msgs/Bool.h>
#include <std_srvs/SetBool.h>

#include <atomic>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "radio_follow/UwbRanges.h"
#include "radio_follow/config/layout.hpp"
#include "radio_follow/control/command_pipeline.hpp"
#include "radio_follow/control/controller_params.hpp"
#include "radio_follow/control/follower.hpp"
#include "radio_follow/control/follower_state.hpp"
#include "radio_follow/ros/common/callback_barrier.hpp"
#include "radio_follow/ros/common/output_diagnostic.hpp"
#include "radio_follow/ros/common/params.hpp"
#include "radio_follow/ros/common/wiring_debug.hpp"

namespace radio_follow {

template <typename Tuning, typename Params>
class ReconfigureServer;
class ControllerTuningConfig;

/// Queue of each range subscription: one per module line at 10 Hz, several seconds'
/// worth so that a burst after a reconnect is not dropped before the stop sees it.
constexpr std::uint32_t kRangeQueueSize = 100;

/// Parameters every controller shares (doc/nodes/velocity_controller.md lists them): the
/// command pipeline's (safety stop, scan gate, limits) and the node's wiring.
struct ControllerCommonParams : control::CommandPipelineParams {
  control::ControllerWiring wiring;
  /// The layout loaded from wiring.layout_file; nullopt without one.
  std::optional<Layout> layout;
  /// UwbRanges topics whose raw ranges feed the safety stop.
  std::vector<std::string> range_topics{"uwb_ranges"};

  void load(const ParamReader& private_nh);
  void validate() const;
};

/// The ROS side of the follower core (control::Follower) shared by the three
/// controllers: raw-range safety stop on its own thread (published from the range
/// callback, not only at the next tick), enable service and topic, status on change, the
/// laser scan, the tick and cmd_vel at a fixed rate, and a last zero command on
/// SIGINT/SIGTERM.
///
/// A derived node loads and validates its own parameters and its law, creates its
/// subscribers and then calls start(law); every tick runs the core (the safety verdict,
/// the law, the limits) and sends what it decides.
class ControllerBase {
 public:
  virtual ~ControllerBase();
  /// The process is dying (runNode's fatal handlers): sends zero cmd_vel without taking
  /// any lock, so that the robot is not left on its last command.
  void lastWords(const char* reason);
  ControllerBase(const ControllerBase&) = delete;
  ControllerBase& operator=(const ControllerBase&) = delete;

 protected:
  /// Loads and validates the common parameters (throws ParamError); subscribes nothing.
  /// `watch_ranges_default` decides whether ranges are watched when ~range_topics is unset.
  ControllerBase(ros::NodeHandle& nh, ros::NodeHandle& private_nh, bool watch_ranges_default);

  /// The node's private parameters: a derived node loads its own structs through it.
  const ParamReader& params() const { return params_in_; }
  /// Refuses (ParamError) any private parameter that neither the base nor the derived
  /// node read (a typo); call it once the derived node's parameters are loaded, before
  /// its first subscriber. start() refuses to run without it.
  void requireKnownParams();

  /// Creates the shared subscribers, service, publishers and timer; every tick runs
  /// `law` (owned by the derived node; it lives as long as the node).
  void start(control::FollowLaw& law);

  /// The robot's pose in the odometry frame for this tick's law, read before the core
  /// runs (the path follower's TF lookup); nullopt: unknown.
  virtual std::optional<Pose2> robotPose() { return std::nullopt; }
  /// After each tick, on the main thread (the path follower publishes its path).
  virtual void afterTick(const ros::Time& /*now*/) {}

  /// Feeds the safety monitor with an input that says only whether the target is usable
  /// (a bearing, for homing). Returns false when it was refused (stamped in the future:
  /// the robot stops; TimePolicy).
  bool noteEstimate(const ros::Time& stamp, control::EstimateQuality quality);
  /// The locator's estimate (robot frame) into the core (control::Follower::onEstimate).
  control::EstimateUse noteEstimate(const ros::Time& stamp, TargetStatus status, double range,
                                    double bearing, const PolarSpread& spread, int hypotheses);
  /// The newest estimate's odometry-frame part, a track point
  /// (control::Follower::addTrackPoint); true when the law kept it.
  bool addTrackPoint(const ros::Time& stamp, const control::TrackPoint& point);

  const ControllerCommonParams& common() const { return common_; }

  /// Every subscriber and timer of a controller goes through it: a callback that throws
  /// stops the robot for hold_time (StopReason::kInternalFault) and the node goes on.
  CallbackBarrier barrier_;

  ros::NodeHandle nh_;
  ros::NodeHandle private_nh_;

 private:
  /// Warns at start when the layout's modules were never calibrated: the raw-range stop
  /// at safe_distance is only as right as their calibration.
  void warnUncalibrated() const;
  void onRanges(const std::string& topic, const UwbRanges::ConstPtr& msg);
  void onScan(const sensor_msgs::LaserScan::ConstPtr& msg);
  void onEnableTopic(const std_msgs::Bool::ConstPtr& msg);
  bool onEnableService(std_srvs::SetBool::Request& req, std_srvs::SetBool::Response& res);
  void setEnabled(bool enabled);
  void onTick(const ros::TimerEvent& event);
  void warnFutureEstimate(const ros::Time& stamp, const ros::Time& now) const;
  /// Handles SIGINT/SIGTERM (flag set by the signal handler): last zero, then shutdown.
  void onStopCheck(const ros::WallTimerEvent& event);
  /// Main thread: the law forgets its integrators (Follower::stop), the stop goes out.
  void stopNow(control::StopReason reason);
  /// Any thread, safety_mutex_ held: zero command and status, limiter reset. The law is
  /// the main thread's: it forgets its integrators at the next tick, which sees the stop.
  void publishStopLocked(control::StopReason reason);
  /// safety_mutex_ held: sends what the pipeline decided.
  void publishLocked(const control::PipelineResult& result);
  void publishCommand(const control::VelocityCommand& cmd);
  void publishStatus(control::FollowerState state, const std::string& text);
  void diagnose(diagnostic_updater::DiagnosticStatusWrapper& status);
  /// A respawned controller comes back disabled: true when a previous instance of this
  /// node left its running marker (it did not stop cleanly). Sets the marker.
  bool markRunning();
  void clearRunningMarker();

  ParamReader params_in_;
  /// Guards what the safety thread (range callbacks) and the main thread share: the
  /// follower core, the published state, common_ during live tuning.
  mutable std::mutex safety_mutex_;
  ros::CallbackQueue safety_queue_;
  std::unique_ptr<ros::AsyncSpinner> safety_spinner_;
  bool params_checked_ = false;
  ControllerCommonParams common_;
  control::Follower follower_;
  control::StatusTracker status_tracker_;
  control::FollowerState state_ = control::FollowerState::kDisabled;
  std::string status_text_;
  unsigned long stopped_ticks_ = 0;

  std::vector<ros::Subscriber> range_subs_;
  ros::Subscriber scan_sub_;
  ros::Subscriber enable_sub_;
  ros::ServiceServer enable_srv_;
  ros::Publisher cmd_pub_;
  ros::Publisher status_pub_;
  ros::Timer timer_;
  ros::WallTimer stop_check_timer_;
  diagnostic_updater::Updater diagnostics_;
  std::optional<OutputDiagnostic> cmd_diagnostic_;  ///< rate of cmd_vel, from start()
  /// First range per watched topic (debug log); keys fixed in start(), before the thread.
  std::map<std::string, FirstMessageLog> first_range_;
  FirstMessageLog first_estimate_;
  /// Live tuning of the safety thresholds and limits (doc/live_tuning.md), from start().
  /// Live tuning of common_ (controller_reconfigure.hpp).
  std::unique_ptr<ReconfigureServer<ControllerTuningConfig, ControllerCommonParams>> reconfigure_;
  bool shutting_down_ = false;
  std::atomic<bool> dying_{false};  ///< set by lastWords, on whichever thread dies
};

}  // namespace radio_follow
