// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/ros/drivers/driver_diagnostics.hpp"

#include <diagnostic_msgs/DiagnosticStatus.h>

#include <utility>

namespace radio_follow {

DriverDiagnostics::DriverDiagnostics(ros::NodeHandle& nh, ros::NodeHandle& private_nh,
                                     const std::string& name, const std::string& hardware_id,
                                     const drivers::DriverStats& stats, double silence_timeout,
                                     Extra extra)
    : stats_(stats),
      name_(name),
      silence_timeout_(silence_timeout),
      extra_(std::move(extra)),
      updater_(nh, private_nh),
      silence_log_(silence_timeout) {
  updater_.setHardwareID(hardware_id);
  updater_.add(name, this, &DriverDiagnostics::produce);
  timer_ = barrier_.timer(nh, ros::Duration(1.0), "diagnostics", &DriverDiagnostics::tick, this);
}

void DriverDiagnostics::tick(const ros::TimerEvent&) {
  const drivers::DriverStatsSnapshot now_stats = stats_.snapshot();
  const double now = ros::Time::now().toSec();
  if (previous_time_ > 0.0 && now > previous_time_) {
    rate_ = static_cast<double>(now_stats.messages - previous_.messages) / (now - previous_time_);
  }
  dropping_ = now_stats.dropped > previous_.dropped;
  if (dropping_ && dropping_log_.ready(now)) {
    ROS_WARN("%s: %s: publish queue full, %llu measurements dropped so far",
             ros::this_node::getName().c_str(), name_.c_str(),
             static_cast<unsigned long long>(now_stats.dropped));
  }
  previous_ = now_stats;
  previous_time_ = now;
  if (now_stats.connected && now_stats.last_data_time > 0.0 &&
      now - now_stats.last_data_time > silence_timeout_ && silence_log_.ready(now)) {
    ROS_WARN("%s: %s: no data from the device for %.1f s", ros::this_node::getName().c_str(),
             name_.c_str(), now - now_stats.last_data_time);
  }
  updater_.update();
}

void DriverDiagnostics::produce(diagnostic_updater::DiagnosticStatusWrapper& status) {
  const drivers::DriverStatsSnapshot s = stats_.snapshot();
  const double silence =
      s.last_data_time > 0.0 ? ros::Time::now().toSec() - s.last_data_time : -1.0;
  if (!s.connected) {
    status.summary(diagnostic_msgs::DiagnosticStatus::ERROR, "device not connected");
  } else if (silence > silence_timeout_) {
    status.summary(diagnostic_msgs::DiagnosticStatus::WARN, "no data from the device");
  } else if (rate_ <= 0.0) {
    status.summary(diagnostic_msgs::DiagnosticStatus::WARN, "connected, no measurements");
  } else if (dropping_) {
    status.summary(diagnostic_msgs::DiagnosticStatus::WARN, "dropping measurements");
  } else {
    status.summary(diagnostic_msgs::DiagnosticStatus::OK, "streaming");
  }
  status.add("message rate (Hz)", rate_);
  status.add("messages published", s.messages);
  status.add("messages dropped", s.dropped);
  status.add("publish queue peak", s.queue_peak);
  status.add("lines rejected", s.rejected);
  status.add("lines implausible", s.implausible);
  status.add("lines ignored", s.ignored);
  status.add("lines too long", s.overflows);
  status.add("measurements filtered", s.filtered);
  status.add("reconnects", s.reconnects);
  status.add("bytes received", s.bytes);
  status.add("seconds since data", silence);
  if (extra_) {
    extra_(status);
  }
}

}  // namespace radio_follow
