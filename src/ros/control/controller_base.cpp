// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/ros/control/controller_base.hpp"

#include <geometry_msgs/Twist.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <csignal>

#include "radio_follow/FollowerStatus.h"
#include "radio_follow/common/param_error.hpp"
#include "radio_follow/common/param_keys.hpp"
#include "radio_follow/common/plausibility.hpp"
#include "radio_follow/common/time_policy.hpp"
#include "radio_follow/config/layout.hpp"
#include "radio_follow/ros/common/params.hpp"
#include "radio_follow/ros/common/wiring_debug.hpp"
#include "radio_follow/ros/control/controller_reconfigure.hpp"

namespace radio_follow {
namespace {

// roscpp's own SIGINT handler shuts the node down before a last message can be sent, so
// controllers install this one. A signal handler can only reach static storage: this
// flag is the single piece of it, written by the handler and read by the timer.
std::atomic<bool> stop_requested{false};

void requestStop(int /*signal*/) {
  stop_requested = true;
}

/// The private parameter a running controller sets and a clean stop deletes; a new
/// instance that finds it replaces one that died (respawn) and comes back disabled.
constexpr char kRunningMarker[] = "running";

}  // namespace

void ControllerCommonParams::load(const ParamReader& pnh) {
  control::ControllerWiring::table().load(pnh, wiring);
  layout.reset();
  if (!wiring.layout_file.empty()) {
    layout = loadLayoutFile(wiring.layout_file);
    range_topics = conventionalTopics(*layout).uwb;  // ~range_topics below still wins
  }
  pnh.param("range_topics", range_topics, range_topics);
  control::CommandPipelineParams::load(pnh, layout ? &*layout : nullptr);
}

void ControllerCommonParams::validate() const {
  requireGraphName("~cmd_vel_topic", wiring.cmd_vel_topic);
  control::ControllerWiring::table().check(wiring);
  for (const auto& topic : range_topics) {
    requireGraphName("~range_topics", topic);
  }
  control::CommandPipelineParams::validate();
}

ControllerBase::ControllerBase(ros::NodeHandle& nh, ros::NodeHandle& private_nh,
                               bool watch_ranges_default)
    : nh_(nh),
      private_nh_(private_nh),
      params_in_(private_nh),
      common_([&] {
        ControllerCommonParams p;
        if (!watch_ranges_default) {
          p.range_topics.clear();
        }
        allowTuning<ControllerTuningConfig>(params_in_);
        params_in_.own("law");  // the follow law's live-tuning server (doc/live_tuning.md)
        params_in_.allow(kRunningMarker);  // set by the node itself (markRunning)
        p.load(params_in_);
        p.safety.watch_ranges = !p.range_topics.empty();
        p.validate();
        return p;
      }()),
      follower_(common_) {
  // The clock decides how far ahead a stamp may be (time_policy.hpp): a few ms between
  // wall clocks, a scheduling delay times the time factor between simulated ones.
  follower_.pipeline().setFutureTolerance(futureStampTolerance(ros::Time::isSimTime()));
  warnUncalibrated();
}

void ControllerBase::warnUncalibrated() const {
  if (!common_.layout || !common_.safety.watch_ranges) {
    return;
  }
  std::string ids;
  for (const std::string& id : uncalibratedModules(*common_.layout)) {
    ids += (ids.empty() ? "" : ", ") + id;
  }
  if (!ids.empty()) {
    ROS_WARN(
        "%s: module(s) %s of %s are uncalibrated (calibration [0, 1]): real modules are off "
        "by 0.1-0.3 m, and one that reads long stops the robot that much inside "
        "safe_distance. Fit them with calibrate_layout (doc/calibration.md).",
        ros::this_node::getName().c_str(), ids.c_str(), common_.wiring.layout_file.c_str());
  }
}

ControllerBase::~ControllerBase() {
  // The safety thread calls into this object: end it before any member goes.
  range_subs_.clear();
  if (safety_spinner_) {
    safety_spinner_->stop();
  }
}

void ControllerBase::requireKnownParams() {
  params_in_.requireAllKnown();
  params_checked_ = true;
}

void ControllerBase::lastWords(const char* /*reason*/) {
  dying_ = true;  // from here on no other thread sends a motion command
  if (cmd_pub_) {
    cmd_pub_.publish(geometry_msgs::Twist());
  }
}

bool ControllerBase::markRunning() {
  const bool replaced = private_nh_.hasParam(kRunningMarker);
  private_nh_.setParam(kRunningMarker, true);
  return replaced;
}

void ControllerBase::clearRunningMarker() {
  private_nh_.deleteParam(kRunningMarker);
}

void ControllerBase::start(control::FollowLaw& law) {
  if (!params_checked_) {
    throw std::logic_error("ControllerBase::start() before requireKnownParams()");
  }
  follower_.setLaw(law);
  cmd_pub_ = nh_.advertise<geometry_msgs::Twist>(common_.wiring.cmd_vel_topic, 1);
  // A callback that throws (a stamp no ros::Time arithmetic can hold, a bug) stops the
  // robot at once and for hold_time; the node keeps running and keeps publishing.
  barrier_.setFaultAction([this](const std::string& /*where*/, const std::string& /*what*/) {
    const std::lock_guard<std::mutex> lock(safety_mutex_);
    follower_.pipeline().onFault(ros::Time::now().toSec());
    publishStopLocked(control::StopReason::kInternalFault);
  });
  status_pub_ = private_nh_.advertise<FollowerStatus>("status", 10, true);
  debugAdvertised(status_pub_);
  // The safety path has its own queue and thread: a range below safe_distance stops the
  // robot however long an estimate callback or a TF lookup takes on the main queue.
  for (const auto& topic : common_.range_topics) {
    first_range_[topic];  // before the safety thread reads the map
    ros::SubscribeOptions options = ros::SubscribeOptions::create<UwbRanges>(
        topic, kRangeQueueSize,
        [this, topic](const UwbRanges::ConstPtr& msg) {
          barrier_.run(topic, [&] { onRanges(topic, msg); });
        },
        ros::VoidPtr(), &safety_queue_);
    options.transport_hints = ros::TransportHints().tcpNoDelay();
    range_subs_.push_back(nh_.subscribe(options));
    debugSubscribed(range_subs_.back());
  }
  if (!range_subs_.empty()) {
    safety_spinner_ = std::make_unique<ros::AsyncSpinner>(1, &safety_queue_);
    safety_spinner_->start();
  }
  if (common_.use_scan) {
    scan_sub_ = barrier_.subscribe(nh_, "scan", 1, &ControllerBase::onScan, this);
    debugSubscribed(scan_sub_);
  }
  enable_sub_ = barrier_.subscribe(private_nh_, "enable", 10, &ControllerBase::onEnableTopic, this);
  debugSubscribed(enable_sub_);
  enable_srv_ = private_nh_.advertiseService("set_enabled", &ControllerBase::onEnableService, this);

  // The node and what it drives: two controllers on one robot differ in both.
  diagnostics_.setHardwareID(ros::this_node::getName() + " -> " + cmd_pub_.getTopic());
  diagnostics_.add("controller", this, &ControllerBase::diagnose);
  // cmd_vel goes out every tick; a stop from the range callback comes on top of that.
  OutputDiagnostic::Bounds bounds;
  bounds.min_hz = common_.wiring.rate;
  bounds.max_hz = 2.0 * common_.wiring.rate;
  cmd_diagnostic_.emplace(diagnostics_, "controller output", cmd_pub_, bounds, false);

  std::signal(SIGINT, requestStop);
  std::signal(SIGTERM, requestStop);

  reconfigure_ =
      makeControllerReconfigure(private_nh_, common_, [this](const ControllerCommonParams& params) {
        const std::lock_guard<std::mutex> lock(safety_mutex_);
        // Validated by the caller; the law checks the new limits first and throws to
        // refuse: no partial update.
        follower_.setCommon(params);
        common_ = params;
      });

  if (markRunning() && common_.wiring.start_enabled) {
    ROS_WARN(
        "%s: starting disabled although start_enabled is true: a previous %s did not stop "
        "cleanly (crashed or was killed, and was respawned). Enable it when the robot is "
        "safe: rosservice call %s true",
        ros::this_node::getName().c_str(), ros::this_node::getName().c_str(),
        enable_srv_.getService().c_str());
    setEnabled(false);
  } else {
    setEnabled(common_.wiring.start_enabled);
  }
  timer_ = barrier_.timer(nh_, ros::Duration(1.0 / common_.wiring.rate), "control tick",
                          &ControllerBase::onTick, this);
  // The stop request is watched on wall time: on simulated time the clock may already
  // have stopped (its publisher shut down first) and a sim-time timer would never fire.
  stop_check_timer_ =
      barrier_.wallTimer(nh_, ros::WallDuration(0.05), "stop check",
                         [this](const ros::WallTimerEvent& event) { onStopCheck(event); });
}

bool ControllerBase::noteEstimate(const ros::Time& stamp, control::EstimateQuality quality) {
  first_estimate_("the target input (estimate or bearing)");
  const ros::Time now = ros::Time::now();
  const std::lock_guard<std::mutex> lock(safety_mutex_);
  if (follower_.onEstimate((stamp.isZero() ? now : stamp).toSec(), now.toSec(), quality)) {
    return true;
  }
  warnFutureEstimate(stamp, now);
  return false;
}

control::EstimateUse ControllerBase::noteEstimate(const ros::Time& stamp, TargetStatus status,
                                                  double range, double bearing,
                                                  const PolarSpread& spread, int hypotheses) {
  first_estimate_("the target input (estimate or bearing)");
  const ros::Time now = ros::Time::now();
  const std::lock_guard<std::mutex> lock(safety_mutex_);
  const control::EstimateUse use =
      follower_.onEstimate((stamp.isZero() ? now : stamp).toSec(), now.toSec(), status, range,
                           bearing, spread, hypotheses);
  if (use == control::EstimateUse::kRefused) {
    warnFutureEstimate(stamp, now);
  }
  return use;
}

void ControllerBase::warnFutureEstimate(const ros::Time& stamp, const ros::Time& now) const {
  // Seconds as double: a stamp 2^32 s ahead overflows ros::Duration (issue 34).
  ROS_WARN_THROTTLE(2.0, "%s: estimate stamped %.3f s ahead of this node's clock refused; stopping",
                    ros::this_node::getName().c_str(), stamp.toSec() - now.toSec());
}

bool ControllerBase::addTrackPoint(const ros::Time& stamp, const control::TrackPoint& point) {
  const double t = (stamp.isZero() ? ros::Time::now() : stamp).toSec();  // as noteEstimate()
  const std::lock_guard<std::mutex> lock(safety_mutex_);
  return follower_.addTrackPoint(t, point);
}

void ControllerBase::onRanges(const std::string& topic, const UwbRanges::ConstPtr& msg) {
  // Safety thread. Time is read before the lock: the receive time of this message.
  const ros::Time now = ros::Time::now();
  const double stamp = (msg->header.stamp.isZero() ? now : msg->header.stamp).toSec();
  first_range_.at(topic)(topic);
  const std::lock_guard<std::mutex> lock(safety_mutex_);
  const std::uint64_t future_before = follower_.pipeline().monitor().time().futureRefused();
  const std::uint64_t implausible_before = follower_.pipeline().monitor().implausibleRanges();
  bool violation = false;
  for (const auto& r : msg->ranges) {
    violation |= follower_.pipeline().onRange(stamp, now.toSec(), topic + "/" + msg->tag_id,
                                              msg->tag_id, r.anchor_id, r.range);
  }
  const bool future = follower_.pipeline().monitor().time().futureRefused() != future_before;
  if (future) {
    ROS_WARN_THROTTLE(2.0, "%s: range on %s stamped %.3f s ahead of this node's clock refused",
                      ros::this_node::getName().c_str(), topic.c_str(), stamp - now.toSec());
  }
  // Do not wait for the next tick: a person stepping in front of the robot must stop
  // it within one range update. The law's own reset (onStopped) follows on the main
  // thread at the next tick, which sees the same verdict.
  const bool implausible = follower_.pipeline().monitor().implausibleRanges() != implausible_before;
  if (implausible) {
    ROS_WARN_THROTTLE(2.0,
                      "%s: range on %s that no module can report (non-finite, negative or "
                      "beyond %.0f m) refused; stopping",
                      ros::this_node::getName().c_str(), topic.c_str(), kMaxUwbRange);
  }
  if (violation && follower_.pipeline().enabled()) {
    publishStopLocked(future        ? control::StopReason::kFutureStamp
                      : implausible ? control::StopReason::kImplausibleRange
                                    : control::StopReason::kTooClose);
  }
}

void ControllerBase::onScan(const sensor_msgs::LaserScan::ConstPtr& msg) {
  const ros::Time stamp = msg->header.stamp.isZero() ? ros::Time::now() : msg->header.stamp;
  double strip_half_width = 0.0;
  {
    const std::lock_guard<std::mutex> lock(safety_mutex_);
    strip_half_width = follower_.pipeline().params().avoidance.side_threshold;
  }
  // The sectors outside the lock: a stop from the range callback does not wait for a scan.
  const control::SectorRanges sectors =
      control::scanSectors(msg->ranges, msg->angle_min, msg->angle_increment, msg->range_min,
                           msg->range_max, strip_half_width);
  const std::lock_guard<std::mutex> lock(safety_mutex_);
  follower_.pipeline().onScan(sectors, stamp.toSec());
}

void ControllerBase::onEnableTopic(const std_msgs::Bool::ConstPtr& msg) {
  setEnabled(msg->data);
}

bool ControllerBase::onEnableService(std_srvs::SetBool::Request& req,
                                     std_srvs::SetBool::Response& res) {
  setEnabled(req.data);
  res.success = true;
  res.message = req.data ? "enabled" : "disabled";
  return true;
}

void ControllerBase::setEnabled(bool enabled) {
  {
    const std::lock_guard<std::mutex> lock(safety_mutex_);
    follower_.pipeline().setEnabled(enabled);
  }
  if (!enabled) {
    stopNow(control::StopReason::kDisabled);
  } else {
    ROS_INFO("%s: enabled", ros::this_node::getName().c_str());
  }
}

void ControllerBase::stopNow(control::StopReason reason) {
  const std::lock_guard<std::mutex> lock(safety_mutex_);
  publishLocked(follower_.stop(reason));
}

void ControllerBase::publishStopLocked(control::StopReason reason) {
  publishLocked(follower_.pipeline().stop(reason));
}

void ControllerBase::publishLocked(const control::PipelineResult& result) {
  publishCommand(result.command);
  publishStatus(result.state, result.text);
}

void ControllerBase::onStopCheck(const ros::WallTimerEvent& /*event*/) {
  if (!stop_requested || shutting_down_) {
    return;
  }
  shutting_down_ = true;
  timer_.stop();
  stop_check_timer_.stop();
  setEnabled(false);
  clearRunningMarker();  // a clean stop: the next start honours start_enabled
  // Give the zero command time to leave the process before the connections close.
  ros::WallDuration(0.2).sleep();
  ros::shutdown();
}

void ControllerBase::onTick(const ros::TimerEvent& event) {
  if (shutting_down_) {
    return;
  }
  const ros::Time now = ros::Time::now();
  double dt = (event.current_real - event.last_real).toSec();
  if (event.last_real.isZero() || !(dt > 0.0) || dt > 1.0) {
    dt = 1.0 / common_.wiring.rate;
  }

  // TF before the lock: a range must not wait for a lookup to stop the robot.
  const std::optional<Pose2> robot = robotPose();
  control::PipelineResult result;
  {
    const std::lock_guard<std::mutex> lock(safety_mutex_);
    result = follower_.tick(now.toSec(), dt, robot);
    publishLocked(result);
  }
  if (!result.moving) {
    ++stopped_ticks_;
  }
  if (result.scan_missing) {
    ROS_WARN_THROTTLE(5.0, "%s: no laser scan within %.2f s, forward motion blocked",
                      ros::this_node::getName().c_str(), common_.scan_timeout);
  }
  afterTick(now);
  diagnostics_.update();
}

void ControllerBase::publishCommand(const control::VelocityCommand& cmd) {
  if (dying_) {
    return;  // the last words sent zero; a tick on another thread must not undo it
  }
  geometry_msgs::Twist twist;
  twist.linear.x = cmd.linear;
  twist.angular.z = cmd.angular;
  cmd_pub_.publish(twist);
  cmd_diagnostic_->tick();
}

void ControllerBase::publishStatus(control::FollowerState state, const std::string& text) {
  state_ = state;
  status_text_ = text;
  if (!status_tracker_.update(state, text, ros::Time::now().toSec())) {
    return;
  }
  FollowerStatus msg;
  msg.header.stamp = ros::Time::now();
  msg.state = static_cast<std::uint8_t>(state);
  msg.text = text;
  status_pub_.publish(msg);
  ROS_INFO("%s: %s", ros::this_node::getName().c_str(), text.c_str());
}

void ControllerBase::diagnose(diagnostic_updater::DiagnosticStatusWrapper& status) {
  using diagnostic_msgs::DiagnosticStatus;
  const std::lock_guard<std::mutex> lock(safety_mutex_);
  const bool moving = state_ == control::FollowerState::kFollowing;
  status.summary(moving || state_ == control::FollowerState::kDisabled ||
                         state_ == control::FollowerState::kArrived
                     ? DiagnosticStatus::OK
                     : DiagnosticStatus::WARN,
                 status_text_);
  status.add("state", control::toString(state_));
  status.add("cmd_vel topic", cmd_pub_.getTopic());
  status.add("stopped ticks", stopped_ticks_);
  status.add("stamps from the future refused",
             follower_.pipeline().monitor().time().futureRefused());
  status.add("clock jumps back", follower_.pipeline().monitor().time().clockJumps());
  status.add("implausible ranges refused", follower_.pipeline().monitor().implausibleRanges());
  status.add("callback faults", barrier_.faults());
  if (barrier_.faults() > 0) {
    status.add("last callback fault", barrier_.lastFault());
  }
}

}  // namespace radio_follow
