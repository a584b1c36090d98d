// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/ros/control/announcer.hpp"

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <sstream>

#include "radio_follow/common/param_error.hpp"
#include "radio_follow/ros/common/params.hpp"

extern char** environ;

namespace radio_follow {

std::string findExecutable(const std::string& command) {
  if (command.find('/') != std::string::npos) {
    return access(command.c_str(), X_OK) == 0 ? command : std::string();
  }
  const char* path = std::getenv("PATH");
  std::istringstream dirs(path ? path : "/usr/bin:/bin");
  std::string dir;
  while (std::getline(dirs, dir, ':')) {
    const std::string candidate = (dir.empty() ? "." : dir) + "/" + command;
    if (access(candidate.c_str(), X_OK) == 0) {
      return candidate;
    }
  }
  return std::string();
}

const ParamTable<AnnouncerNode::Params>& AnnouncerNode::Params::table() {
  using P = AnnouncerNode::Params;
  using F = control::FaultSpeechParams;
  static const ParamTable<P> t =
      ParamTable<P>()
          .add("command", &P::command, "", "Speech program (name on PATH or a path).")
          .add("voice", &P::voice, "", "espeak-ng voice.")
          .add("words_per_minute", &P::words_per_minute, "words/min", "Speech rate.",
               Range::closed(80, 450))
          .add("repeat_interval", &P::repeat_interval, "s",
               "Minimum interval between identical texts.", Range::atLeast(0.0))
          .add("max_queued", &P::max_queued, "messages", "Texts waiting beyond this are dropped.",
               Range::atLeast(1))
          .add("diagnostics_topic", &P::diagnostics_topic, "",
               "Where faults are read; empty = faults not spoken.")
          .add("fault_hold_time", &P::faults, &F::hold_time, "s",
               "A fault or its end is spoken once it has held this long.", Range::atLeast(0.0))
          .add("fault_silence_timeout", &P::faults, &F::silence_timeout, "s",
               "A source silent this long stopped reporting.", Range::above(0.0));
  return t;
}

void AnnouncerNode::Params::load(const ParamReader& pnh) {
  pnh.param("status_topics", status_topics, status_topics);
  table().load(pnh, *this);
}

void AnnouncerNode::Params::validate() const {
  require(!status_topics.empty(), "~status_topics", status_topics.size(),
          "at least one FollowerStatus topic");
  require(!command.empty(), "~command", command, "an executable name");
  table().check(*this);
  if (!diagnostics_topic.empty()) {
    requireGraphName("~diagnostics_topic", diagnostics_topic);
  }
  faults.validate("~fault_");
}

AnnouncerNode::AnnouncerNode(ros::NodeHandle& nh, ros::NodeHandle& private_nh)
    : params_(loadStrict<Params>(private_nh)),
      queue_(params_.repeat_interval, static_cast<std::size_t>(params_.max_queued)),
      faults_(params_.faults),
      executable_(findExecutable(params_.command)) {
  if (executable_.empty()) {
    ROS_WARN("%s: '%s' not found; status texts are only printed", ros::this_node::getName().c_str(),
             params_.command.c_str());
  }
  for (const auto& topic : params_.status_topics) {
    subs_.push_back(barrier_.subscribe(nh, topic, 10, &AnnouncerNode::onStatus, this));
  }
  if (!params_.diagnostics_topic.empty()) {
    subs_.push_back(
        barrier_.subscribe(nh, params_.diagnostics_topic, 10, &AnnouncerNode::onDiagnostics, this));
  }
  timer_ = barrier_.timer(nh, ros::Duration(0.1), "speech", &AnnouncerNode::onTimer, this);
}

AnnouncerNode::~AnnouncerNode() {
  if (child_ > 0) {
    kill(child_, SIGTERM);
    waitpid(child_, nullptr, 0);
  }
}

void AnnouncerNode::onStatus(const FollowerStatus::ConstPtr& msg) {
  queue_.push(msg->text, ros::WallTime::now().toSec());
}

void AnnouncerNode::onDiagnostics(const diagnostic_msgs::DiagnosticArray::ConstPtr& msg) {
  const double now = ros::WallTime::now().toSec();
  for (const auto& status : msg->status) {
    // Levels beyond STALE are not defined: read them as an error, never as OK.
    const bool defined = status.level >= diagnostic_msgs::DiagnosticStatus::OK &&
                         status.level <= diagnostic_msgs::DiagnosticStatus::STALE;
    const auto level =
        defined ? static_cast<control::StatusLevel>(status.level) : control::StatusLevel::kError;
    faults_.observe({status.name, level, status.message, status.hardware_id}, now);
  }
}

void AnnouncerNode::onTimer(const ros::TimerEvent& /*event*/) {
  const double wall = ros::WallTime::now().toSec();
  for (const std::string& text : faults_.due(wall)) {
    queue_.push(text, wall);
  }
  if (child_ > 0) {
    int status = 0;
    const pid_t done = waitpid(child_, &status, WNOHANG);
    if (done == 0) {
      return;  // still speaking: one message at a time
    }
    child_ = -1;
  }
  const auto text = queue_.pop(ros::WallTime::now().toSec());
  if (!text) {
    return;
  }
  ROS_INFO("%s: \"%s\"", ros::this_node::getName().c_str(), text->c_str());
  if (!executable_.empty()) {
    speak(*text);
  }
}

bool AnnouncerNode::speak(const std::string& text) {
  const std::string speed = std::to_string(params_.words_per_minute);
  // The text is one argv element: no shell, so nothing in it is interpreted.
  std::vector<std::string> args{executable_, "-v", params_.voice, "-s", speed, "--", text};
  std::vector<char*> argv;
  for (auto& a : args) {
    argv.push_back(a.data());
  }
  argv.push_back(nullptr);
  const int err = posix_spawn(&child_, executable_.c_str(), nullptr, nullptr, argv.data(), environ);
  if (err != 0) {
    child_ = -1;
    ROS_WARN_THROTTLE(30.0, "%s: cannot start %s: %s", ros::this_node::getName().c_str(),
                      executable_.c_str(), std::strerror(err));
    return false;
  }
  return true;
}

}  // namespace radio_follow
