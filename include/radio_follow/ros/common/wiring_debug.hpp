// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <ros/ros.h>

#include <atomic>
#include <string>

namespace radio_follow {

/// Debug lines for a user tracing a wiring problem (logger `ros.radio_follow.wiring`,
/// doc/diagnostics.md): which fully resolved topic a node reads or writes, and when the
/// first message of an input arrived. Silent unless the logger is at DEBUG.
void debugSubscribed(const ros::Subscriber& subscriber);
void debugAdvertised(const ros::Publisher& publisher);

/// Logs (DEBUG) the first message received on one input, once; thread-safe.
class FirstMessageLog {
 public:
  void operator()(const std::string& topic);

 private:
  std::atomic<bool> seen_{false};
};

}  // namespace radio_follow
