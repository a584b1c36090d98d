// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/ros/controller_base.hpp"

#include <geometry_msgs/Twist.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <csignal>

#include "radio_follow/FollowerStatus.h"
#include "radio_follow/common/param_error.hpp"
#include "radio_follow/common/param_keys.hpp"
#include "radio_follow/config/layout.hpp"
#include "radio_follow/ros/controller_reconfigure.hpp"
#include "radio_follow/ros/params.hpp"
#include "radio_follow/ros/wiring_debug.hpp"

namespace radio_follow {
namespace {

// roscpp's own SIGINT handler shuts the node down before a last message can be sent, so
// controllers install this one. A signal handler can only reach static storage: this
// flag is the single piece of it, written by the handler and read by the timer.
std::atomic<bool> stop_requested{false};

void requestStop(int /*signal*/) {
  stop_requested = true;
}

}  // namespace

void ControllerCommonParams::load(const ParamReader& pnh) {
  pnh.param("cmd_vel_topic", cmd_vel_topic, cmd_vel_topic);
  pnh.param("rate", rate, rate);
  pnh.param("start_enabled", start_enabled, start_enabled);
  pnh.param("layout_file", layout_file, layout_file);
  pnh.param("calibrate_ranges", calibrate_ranges, calibrate_ranges);
  if (!layout_file.empty()) {
    // Explicit parameters below still win over what the layout implies.
    const Layout layout = loadLayoutFile(layout_file);
    range_topics = conventionalTopics(layout).uwb;
    target_anchor_id = layout.target_anchor_id;
    if (calibrate_ranges) {
      for (const TwrModule& module : layout.twr_modules) {
        calibrated_modules[module.id] = module;  // normalised by the parser
      }
    }
  }
  pnh.param("range_topics", range_topics, range_topics);
  pnh.param("target_anchor_id", target_anchor_id, target_anchor_id);
  target_anchor_id = normalizeId(target_anchor_id);
  pnh.param("use_scan", use_scan, use_scan);
  pnh.param("scan_timeout", scan_timeout, scan_timeout);
  pnh.param("safe_distance", safety.safe_distance, safety.safe_distance);
  pnh.param("estimate_timeout", safety.estimate_timeout, safety.estimate_timeout);
  pnh.param("range_timeout", safety.range_timeout, safety.range_timeout);
  pnh.param("hold_time", safety.hold_time, safety.hold_time);
  pnh.param("max_linear", limits.max_linear, limits.max_linear);
  pnh.param("max_angular", limits.max_angular, limits.max_angular);
  pnh.param("max_linear_accel", limits.max_linear_accel, limits.max_linear_accel);
  pnh.param("max_linear_decel", limits.max_linear_decel, limits.max_linear_decel);
  pnh.param("max_angular_accel", limits.max_angular_accel, limits.max_angular_accel);
  pnh.param("avoidance/obstacle_threshold", avoidance.obstacle_threshold,
            avoidance.obstacle_threshold);
  pnh.param("avoidance/stop_threshold", avoidance.stop_threshold, avoidance.stop_threshold);
  pnh.param("avoidance/side_threshold", avoidance.side_threshold, avoidance.side_threshold);
  pnh.param("avoidance/turn_rate", avoidance.turn_rate, avoidance.turn_rate);
}

void loadPidGains(const ParamReader& pnh, const std::string& ns, control::PidGains& gains) {
  pnh.param(ns + "/kp", gains.kp, gains.kp);
  pnh.param(ns + "/ki", gains.ki, gains.ki);
  pnh.param(ns + "/kd", gains.kd, gains.kd);
  pnh.param(ns + "/integral_limit", gains.integral_limit, gains.integral_limit);
  pnh.param(ns + "/derivative_time_constant", gains.derivative_time_constant,
            gains.derivative_time_constant);
}

void ControllerCommonParams::validate() const {
  requireGraphName("~cmd_vel_topic", cmd_vel_topic);
  require(rate >= 1.0 && rate <= 200.0, "~rate", rate, "a rate in [1, 200] Hz");
  for (const auto& topic : range_topics) {
    requireGraphName("~range_topics", topic);
  }
  require(scan_timeout > 0.0, "~scan_timeout", scan_timeout, "a timeout > 0 in seconds");
  // A calibration that moves the stop threshold far, or turns it around, is more likely a
  // typo in the layout than a module: the safety stop must not silently depend on it.
  const double d = safety.safe_distance;
  for (const auto& [id, module] : calibrated_modules) {
    const double shift = module.correctRange(d) - d;
    const double slope = (module.correctRange(d + 0.1) - module.correctRange(d)) / 0.1;
    require(std::abs(shift) <= kMaxSafetyCalibrationShift && slope > 0.5 && slope < 2.0,
            "~layout_file twr_modules[" + id + "].calibration", module.correctRange(d),
            "a corrected range at safe_distance (" + std::to_string(d) + " m) within " +
                std::to_string(kMaxSafetyCalibrationShift) +
                " m of it and a slope in (0.5, 2) there (or ~calibrate_ranges: false)");
  }
  safety.validate();
  limits.validate();
  avoidance.validate();
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
        p.load(params_in_);
        p.safety.watch_ranges = !p.range_topics.empty();
        p.validate();
        return p;
      }()),
      monitor_(common_.safety),
      limiter_(common_.limits) {}

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

void ControllerBase::start() {
  if (!params_checked_) {
    throw std::logic_error("ControllerBase::start() before requireKnownParams()");
  }
  cmd_pub_ = nh_.advertise<geometry_msgs::Twist>(common_.cmd_vel_topic, 1);
  status_pub_ = private_nh_.advertise<FollowerStatus>("status", 10, true);
  debugAdvertised(status_pub_);
  // The safety path has its own queue and thread: a range below safe_distance stops the
  // robot however long an estimate callback or a TF lookup takes on the main queue.
  for (const auto& topic : common_.range_topics) {
    first_range_[topic];  // before the safety thread reads the map
    ros::SubscribeOptions options = ros::SubscribeOptions::create<UwbRanges>(
        topic, kRangeQueueSize,
        [this, topic](const UwbRanges::ConstPtr& msg) { onRanges(topic, msg); }, ros::VoidPtr(),
        &safety_queue_);
    options.transport_hints = ros::TransportHints().tcpNoDelay();
    range_subs_.push_back(nh_.subscribe(options));
    debugSubscribed(range_subs_.back());
  }
  if (!range_subs_.empty()) {
    safety_spinner_ = std::make_unique<ros::AsyncSpinner>(1, &safety_queue_);
    safety_spinner_->start();
  }
  if (common_.use_scan) {
    scan_sub_ = nh_.subscribe("scan", 1, &ControllerBase::onScan, this);
    debugSubscribed(scan_sub_);
  }
  enable_sub_ = private_nh_.subscribe("enable", 10, &ControllerBase::onEnableTopic, this);
  debugSubscribed(enable_sub_);
  enable_srv_ = private_nh_.advertiseService("set_enabled", &ControllerBase::onEnableService, this);

  // The node and what it drives: two controllers on one robot differ in both.
  diagnostics_.setHardwareID(ros::this_node::getName() + " -> " + cmd_pub_.getTopic());
  diagnostics_.add("controller", this, &ControllerBase::diagnose);
  // cmd_vel goes out every tick; a stop from the range callback comes on top of that.
  OutputDiagnostic::Bounds bounds;
  bounds.min_hz = common_.rate;
  bounds.max_hz = 2.0 * common_.rate;
  cmd_diagnostic_.emplace(diagnostics_, "controller output", cmd_pub_, bounds, false);

  std::signal(SIGINT, requestStop);
  std::signal(SIGTERM, requestStop);

  reconfigure_ =
      makeControllerReconfigure(private_nh_, common_, [this](const ControllerCommonParams& params) {
        onCommonChange(params);  // the law checks the new limits first; throws to refuse
        const std::lock_guard<std::mutex> lock(safety_mutex_);
        monitor_.setParams(params.safety);  // both validated by the caller: no partial update
        limiter_.setLimits(params.limits);
        common_ = params;
      });

  setEnabled(common_.start_enabled);
  timer_ = nh_.createTimer(ros::Duration(1.0 / common_.rate), &ControllerBase::onTick, this);
  // The stop request is watched on wall time: on simulated time the clock may already
  // have stopped (its publisher shut down first) and a sim-time timer would never fire.
  stop_check_timer_ =
      nh_.createWallTimer(ros::WallDuration(0.05), &ControllerBase::onStopCheck, this);
}

bool ControllerBase::noteEstimate(const ros::Time& stamp, control::EstimateQuality quality) {
  first_estimate_("the target input (estimate or bearing)");
  const ros::Time now = ros::Time::now();
  const std::lock_guard<std::mutex> lock(safety_mutex_);
  if (monitor_.onEstimate((stamp.isZero() ? now : stamp).toSec(), now.toSec(), quality)) {
    return true;
  }
  ROS_WARN_THROTTLE(2.0, "%s: estimate stamped %.3f s ahead of this node's clock refused; stopping",
                    ros::this_node::getName().c_str(), (stamp - now).toSec());
  return false;
}

double ControllerBase::moduleGap(const ros::Time& now) const {
  const std::lock_guard<std::mutex> lock(safety_mutex_);
  return monitor_.nearestRange(now.toSec()) - monitor_.params().safe_distance;
}

void ControllerBase::onRanges(const std::string& topic, const UwbRanges::ConstPtr& msg) {
  // Safety thread. Time is read before the lock: the receive time of this message.
  const ros::Time now = ros::Time::now();
  const double stamp = (msg->header.stamp.isZero() ? now : msg->header.stamp).toSec();
  first_range_.at(topic)(topic);
  const std::lock_guard<std::mutex> lock(safety_mutex_);
  const std::uint64_t future_before = monitor_.time().futureRefused();
  bool violation = false;
  for (const auto& r : msg->ranges) {
    if (!common_.target_anchor_id.empty() && normalizeId(r.anchor_id) != common_.target_anchor_id) {
      continue;
    }
    const auto module = common_.calibrated_modules.find(normalizeId(msg->tag_id));
    const double range =
        module == common_.calibrated_modules.end() ? r.range : module->second.correctRange(r.range);
    violation |= monitor_.onRange(stamp, now.toSec(), topic + "/" + msg->tag_id, range);
  }
  const bool future = monitor_.time().futureRefused() != future_before;
  if (future) {
    ROS_WARN_THROTTLE(2.0, "%s: range on %s stamped %.3f s ahead of this node's clock refused",
                      ros::this_node::getName().c_str(), topic.c_str(), stamp - now.toSec());
  }
  // Do not wait for the next tick: a person stepping in front of the robot must stop
  // it within one range update. The law's own reset (onStopped) follows on the main
  // thread at the next tick, which sees the same verdict.
  if (violation && monitor_.enabled()) {
    publishStopLocked(future ? control::StopReason::kFutureStamp : control::StopReason::kTooClose);
  }
}

void ControllerBase::onScan(const sensor_msgs::LaserScan::ConstPtr& msg) {
  sectors_ = control::scanSectors(msg->ranges, msg->angle_min, msg->angle_increment, msg->range_min,
                                  msg->range_max);
  scan_stamp_ = msg->header.stamp.isZero() ? ros::Time::now() : msg->header.stamp;
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
    monitor_.setEnabled(enabled);
  }
  if (!enabled) {
    stopNow(control::StopReason::kDisabled);
  } else {
    ROS_INFO("%s: enabled", ros::this_node::getName().c_str());
  }
}

void ControllerBase::stopNow(control::StopReason reason) {
  onStopped();
  const std::lock_guard<std::mutex> lock(safety_mutex_);
  publishStopLocked(reason);
}

void ControllerBase::publishStopLocked(control::StopReason reason) {
  limiter_.reset();
  publishCommand(control::VelocityCommand{});
  publishStatus(control::stateFor(reason), control::stopText(reason));
}

void ControllerBase::onStopCheck(const ros::WallTimerEvent& /*event*/) {
  if (!stop_requested || shutting_down_) {
    return;
  }
  shutting_down_ = true;
  timer_.stop();
  stop_check_timer_.stop();
  setEnabled(false);
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
    dt = 1.0 / common_.rate;
  }

  control::SafetyDecision decision;
  {
    const std::lock_guard<std::mutex> lock(safety_mutex_);
    decision = monitor_.evaluate(now.toSec());
  }
  if (!decision.may_move) {
    stopNow(decision.reason);
    ++stopped_ticks_;
    diagnostics_.update();
    return;
  }

  Output out = compute(now, dt);
  control::VelocityCommand request = out.command;
  if (common_.use_scan) {
    const bool scan_fresh = sectors_ && (now - scan_stamp_).toSec() <= common_.scan_timeout;
    if (scan_fresh) {
      request = control::avoidObstacles(request, *sectors_, common_.avoidance);
    } else {
      // Avoidance was asked for but cannot see: turning in place is the only safe motion.
      request.linear = 0.0;
      out.text = "No laser scan, not driving.";
      ROS_WARN_THROTTLE(5.0, "%s: no laser scan within %.2f s, forward motion blocked",
                        ros::this_node::getName().c_str(), common_.scan_timeout);
    }
  }
  {
    // The law ran without the lock; a range that arrived meanwhile may have stopped the
    // robot, so the verdict is taken again, at the time of publishing.
    const std::lock_guard<std::mutex> lock(safety_mutex_);
    decision = monitor_.evaluate(ros::Time::now().toSec());
    if (decision.may_move) {
      publishCommand(control::gateCommand(decision, limiter_.update(request, dt)));
      publishStatus(out.state, out.text.empty() ? control::defaultText(out.state) : out.text);
    } else {
      publishStopLocked(decision.reason);
    }
  }
  diagnostics_.update();
}

void ControllerBase::publishCommand(const control::VelocityCommand& cmd) {
  geometry_msgs::Twist twist;
  twist.linear.x = cmd.linear;
  twist.angular.z = cmd.angular;
  cmd_pub_.publish(twist);
  cmd_diagnostic_->tick();
}

void ControllerBase::publishStatus(control::FollowerState state, const std::string& text) {
  state_ = state;
  status_text_ = text;
  if (!status_tracker_.update(state, text)) {
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
  status.add("stamps from the future refused", monitor_.time().futureRefused());
  status.add("clock jumps back", monitor_.time().clockJumps());
}

}  // namespace radio_follow
