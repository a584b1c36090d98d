// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <diagnostic_updater/diagnostic_updater.h>
#include <ros/ros.h>

#include <functional>
#include <string>

#include "radio_follow/common/throttle.hpp"
#include "radio_follow/drivers/driver_stats.hpp"
#include "radio_follow/ros/common/callback_barrier.hpp"

namespace radio_follow {

/// Diagnostics and silence watchdog shared by the device drivers. Once a second it
/// publishes one status (message rate, messages published and dropped, lines
/// rejected/implausible/ignored, overflows, reconnects, seconds since data), WARN while
/// measurements are being dropped, and warns, throttled, when a connected device has been
/// silent for longer than `silence_timeout`. `stats.last_data_time` must be in ROS time
/// seconds (the drivers set it on every chunk and on connect).
class DriverDiagnostics {
 public:
  /// Adds node-specific key/values (e.g. the module's ID) to the status.
  using Extra = std::function<void(diagnostic_updater::DiagnosticStatusWrapper&)>;

  DriverDiagnostics(ros::NodeHandle& nh, ros::NodeHandle& private_nh, const std::string& name,
                    const std::string& hardware_id, const drivers::DriverStats& stats,
                    double silence_timeout, Extra extra = {});

  /// The node's updater, for the output topics' rate/stamp diagnostics (OutputDiagnostic).
  diagnostic_updater::Updater& updater() { return updater_; }

 private:
  void tick(const ros::TimerEvent& event);
  void produce(diagnostic_updater::DiagnosticStatusWrapper& status);

  const drivers::DriverStats& stats_;
  std::string name_;  // the status name, which names the device in the log lines
  double silence_timeout_;
  Extra extra_;
  diagnostic_updater::Updater updater_;
  CallbackBarrier barrier_;
  ros::Timer timer_;
  drivers::DriverStatsSnapshot previous_;
  double previous_time_ = 0.0;
  double rate_ = 0.0;
  bool dropping_ = false;  // measurements were dropped since the previous tick
  Throttle dropping_log_{5.0};
  Throttle silence_log_;
};

}  // namespace radio_follow
