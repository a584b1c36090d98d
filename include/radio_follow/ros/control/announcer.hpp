// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <diagnostic_msgs/DiagnosticArray.h>
#include <ros/ros.h>
#include <sys/types.h>

#include <string>
#include <vector>

#include "radio_follow/FollowerStatus.h"
#include "radio_follow/common/param_table.hpp"
#include "radio_follow/control/announcement_queue.hpp"
#include "radio_follow/control/fault_speech.hpp"
#include "radio_follow/ros/common/callback_barrier.hpp"
#include "radio_follow/ros/common/params.hpp"

namespace radio_follow {

/// announcer (thesis Section 4.8): speaks the controllers' status texts with espeak-ng,
/// one at a time, identical texts rate-limited, and the drivers' and the locator's faults
/// read from /diagnostics (control::FaultSpeech: device lost or silent, target lost or
/// uncertain, a node that stopped reporting), through the same queue. The speech runs in
/// a child process (posix_spawn); a timer reaps it, so the ROS thread never blocks.
/// Without espeak-ng it logs that once and only prints the texts.
class AnnouncerNode {
 public:
  struct Params {
    std::vector<std::string> status_topics{"status"};
    std::string command = "espeak-ng";
    std::string voice = "en";
    int words_per_minute = 160;
    double repeat_interval = 10.0;  ///< s
    int max_queued = 5;
    /// DiagnosticArray topic the faults are read from; empty: faults are not spoken.
    std::string diagnostics_topic = "/diagnostics";
    control::FaultSpeechParams faults;  ///< fault_hold_time, fault_silence_timeout

    /// Every parameter but the list ~status_topics (config/announcer.yaml).
    static const ParamTable<Params>& table();
    void load(const ParamReader& private_nh);
    void validate() const;
  };

  AnnouncerNode(ros::NodeHandle& nh, ros::NodeHandle& private_nh);
  ~AnnouncerNode();
  AnnouncerNode(const AnnouncerNode&) = delete;
  AnnouncerNode& operator=(const AnnouncerNode&) = delete;

 private:
  void onStatus(const FollowerStatus::ConstPtr& msg);
  void onDiagnostics(const diagnostic_msgs::DiagnosticArray::ConstPtr& msg);
  void onTimer(const ros::TimerEvent& event);
  bool speak(const std::string& text);

  Params params_;
  control::AnnouncementQueue queue_;
  control::FaultSpeech faults_;
  std::string executable_;  // resolved path, empty when not installed
  pid_t child_ = -1;
  CallbackBarrier barrier_;  // every subscriber and the timer run inside it
  std::vector<ros::Subscriber> subs_;
  ros::Timer timer_;
};

/// Resolves `command` on $PATH (or as given when it contains '/'); empty when not
/// found or not executable.
std::string findExecutable(const std::string& command);

}  // namespace radio_follow
