// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/ros/controller_base.hpp"

#include <geometry_msgs/Twist.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <csignal>

#include "radio_follow/FollowerStatus.h"
#include "radio_follow/common/param_error.hpp"
#include "radio_follow/config/layout.hpp"
#include "radio_follow/ros/controller_reconfigure.hpp"
#include "radio_follow/ros/params.hpp"

namespace radio_follow {
namespace {

// roscpp's own SIGINT handler shuts the node down before a last message can be sent, so
// controllers install this one. A signal handler can only reach static storage: this
// flag is the single piece of it, written by the handler and read by the timer.
std::atomic<bool> stop_requested{false};

void requestStop(int /*signal*/) {
  stop_requested = true;
}

std::string upper(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(),
                 [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
  return s;
}

}  // namespace

void ControllerCommonParams::load(const ros::NodeHandle& pnh) {
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
        calibrated_modules[upper(module.id)] = module;
      }
    }
  }
  loadStringList(pnh, "range_topics", range_topics);
  pnh.param("target_anchor_id", target_anchor_id, target_anchor_id);
  target_anchor_id = upper(target_anchor_id);
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

void loadPidGains(const ros::NodeHandle& pnh, const std::string& ns, control::PidGains& gains) {
  pnh.param(ns + "/kp", gains.kp, gains.kp);
  pnh.param(ns + "/ki", gains.ki, gains.ki);
  pnh.param(ns + "/kd", gains.kd, gains.kd);
  pnh.param(ns + "/integral_limit", gains.integral_limit, gains.integral_limit);
  pnh.param(ns + "/derivative_time_constant", gains.derivative_time_constant,
            gains.derivative_time_constant);
}

void ControllerCommonParams::validate() const {
  require(!cmd_vel_topic.empty(), "~cmd_vel_topic", cmd_vel_topic, "a topic name");
  require(rate >= 1.0 && rate <= 200.0, "~rate", rate, "a rate in [1, 200] Hz");
  for (const auto& topic : range_topics) {
    require(!topic.empty(), "~range_topics", topic, "non-empty topic names");
  }
  require(scan_timeout > 0.0, "~scan_timeout", scan_timeout, "a timeout > 0 in seconds");
  // A calibration that moves the stop threshold far, or turns it around, is more likely a
  // typo in the layout than a module: the safety stop must not silently depend on it.
  const double d = safety.safe_distance;
  for (const auto& [id, module] : calibrated_modules) {
    const double shift = module.correctRange(d) - d;
    const double slope = (module.correctRange(d + 0.1) - module.correctRange(d)) / 0.1;
    require(std::abs(shift) <= kMaxSafetyCalibrationShift && slope > 0.5 && slope < 2.0,
            "~layout_file twr_modules[" + id + "].calibration",
            module.correctRange(d),
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
      common_([&] {
        ControllerCommonParams p;
        if (!watch_ranges_default) {
          p.range_topics.clear();
        }
        p.load(private_nh);
        p.safety.watch_ranges = !p.range_topics.empty();
        p.validate();
        return p;
      }()),
      monitor_(common_.safety),
      limiter_(common_.limits) {}

ControllerBase::~ControllerBase() = default;

void ControllerBase::start() {
  cmd_pub_ = nh_.advertise<geometry_msgs::Twist>(common_.cmd_vel_topic, 1);
  status_pub_ = private_nh_.advertise<FollowerStatus>("status", 10, true);
  for (const auto& topic : common_.range_topics) {
    range_subs_.push_back(nh_.subscribe<UwbRanges>(
        topic, 10, [this, topic](const UwbRanges::ConstPtr& msg) { onRanges(topic, msg); }));
  }
  if (common_.use_scan) {
    scan_sub_ = nh_.subscribe("scan", 1, &ControllerBase::onScan, this);
  }
  enable_sub_ = private_nh_.subscribe("enable", 10, &ControllerBase::onEnableTopic, this);
  enable_srv_ = private_nh_.advertiseService("set_enabled", &ControllerBase::onEnableService, this);

  diagnostics_.setHardwareID("none");
  diagnostics_.add("controller", this, &ControllerBase::diagnose);

  std::signal(SIGINT, requestStop);
  std::signal(SIGTERM, requestStop);

  reconfigure_ =
      makeControllerReconfigure(private_nh_, common_, [this](const ControllerCommonParams& params) {
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

void ControllerBase::noteEstimate(const ros::Time& stamp, bool usable) {
  monitor_.onEstimate((stamp.isZero() ? ros::Time::now() : stamp).toSec(), usable);
}

double ControllerBase::moduleGap(const ros::Time& now) const {
  return monitor_.nearestRange(now.toSec()) - common_.safety.safe_distance;
}

void ControllerBase::onRanges(const std::string& topic, const UwbRanges::ConstPtr& msg) {
  const double stamp = (msg->header.stamp.isZero() ? ros::Time::now() : msg->header.stamp).toSec();
  bool violation = false;
  for (const auto& r : msg->ranges) {
    if (!common_.target_anchor_id.empty() && upper(r.anchor_id) != common_.target_anchor_id) {
      continue;
    }
    const auto module = common_.calibrated_modules.find(upper(msg->tag_id));
    const double range = module == common_.calibrated_modules.end()
                             ? r.range
                             : module->second.correctRange(r.range);
    violation |= monitor_.onRange(stamp, topic + "/" + msg->tag_id, range);
  }
  // Do not wait for the next tick: a person stepping in front of the robot must stop
  // it within one range update.
  if (violation && state_ != control::FollowerState::kDisabled) {
    stopNow(control::StopReason::kTooClose);
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
  monitor_.setEnabled(enabled);
  if (!enabled) {
    stopNow(control::StopReason::kDisabled);
  } else {
    ROS_INFO("%s: enabled", ros::this_node::getName().c_str());
  }
}

void ControllerBase::stopNow(control::StopReason reason) {
  limiter_.reset();
  onStopped();
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
  monitor_.setEnabled(false);
  stopNow(control::StopReason::kDisabled);
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

  const control::SafetyDecision decision = monitor_.evaluate(now.toSec());
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
  const control::VelocityCommand cmd = control::gateCommand(decision, limiter_.update(request, dt));
  publishCommand(cmd);
  publishStatus(out.state, out.text.empty() ? control::defaultText(out.state) : out.text);
  diagnostics_.update();
}

void ControllerBase::publishCommand(const control::VelocityCommand& cmd) {
  geometry_msgs::Twist twist;
  twist.linear.x = cmd.linear;
  twist.angular.z = cmd.angular;
  cmd_pub_.publish(twist);
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
  const bool moving = state_ == control::FollowerState::kFollowing;
  status.summary(moving || state_ == control::FollowerState::kDisabled ||
                         state_ == control::FollowerState::kArrived
                     ? DiagnosticStatus::OK
                     : DiagnosticStatus::WARN,
                 status_text_);
  status.add("state", static_cast<int>(state_));
  status.add("stopped ticks", stopped_ticks_);
}

}  // namespace radio_follow
