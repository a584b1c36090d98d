// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/ros/drivers/dwm1001_driver.hpp"

#include <utility>

#include "radio_follow/common/param_error.hpp"
#include "radio_follow/common/param_keys.hpp"

namespace radio_follow {
namespace {

// Depth of the publish queue and of the roscpp publisher queue behind it (one burst has
// to fit in each; a roscpp queue that overflows drops its oldest message without telling
// anyone). The module sends at most 10 lines/s, its top update rate, with up to 15
// anchors each; but a backlog arrives at once: whatever piled up in the host's tty buffers
// (up to 640 KiB) while the reader or a subscriber was held up, or what a replugged
// module had queued. 4096 lines are 400 s of the module's output; in the rostest
// driver_burst (doc/nodes/dwm1001_driver.md) they absorb 200,000 lines at 20,000 lines/s
// and bursts of 30 without a loss.
constexpr std::size_t kRangeQueueDepth = 4096;

// The module's top update rate (lines/s): more on `ranges` is a backlog arriving.
constexpr double kMaxLineRate = 10.0;

std::string hardwareId(const Dwm1001DriverNode::Params& params) {
  return params.tag_id.empty() ? params.port : params.port + " (module " + params.tag_id + ")";
}

// The locator and the layout spell module IDs in upper case: a driver in uwb/5a84 would
// publish where nobody listens, so it stops at start saying so (roslaunch cannot
// upper-case an argument: its $(eval) turns "0123" into 123).
const ros::NodeHandle& requireUpperCaseId(const ros::NodeHandle& private_nh) {
  const std::string ns = ros::this_node::getNamespace();
  const auto slash = ns.rfind('/');
  const std::string parent = slash == std::string::npos ? "" : ns.substr(0, slash);
  const std::string id = slash == std::string::npos ? ns : ns.substr(slash + 1);
  if (parent.size() >= 4 && parent.compare(parent.size() - 4, 4, "/uwb") == 0) {
    require(normalizeId(id) == id, "namespace", ns,
            "the module ID in upper case, " + parent + "/" + normalizeId(id) +
                ", where the locator listens (launch with id:=" + normalizeId(id) + ")");
  }
  return private_nh;
}

}  // namespace

Dwm1001DriverNode::Dwm1001DriverNode(ros::NodeHandle& nh, ros::NodeHandle& private_nh)
    : Dwm1001DriverNode(nh, private_nh, loadStrict<Params>(requireUpperCaseId(private_nh))) {}

Dwm1001DriverNode::Dwm1001DriverNode(ros::NodeHandle& nh, ros::NodeHandle& private_nh,
                                     const Params& params)
    : QueuedSerialLineDriver(nh, private_nh, params, "dwm1001 " + params.port, hardwareId(params),
                             kRangeQueueDepth),
      params_(params),
      shell_(params.output_mode, params.shell_timeout) {
  ranges_pub_ = nh.advertise<UwbRanges>("ranges", kRangeQueueDepth);
  location_pub_ = nh.advertise<UwbTagLocation>("tag_location", kRangeQueueDepth);
  ranges_output_ = &watchOutput(ranges_pub_, kMaxLineRate);
  // A module may give no position: no lower rate on tag_location.
  location_output_ = &watchOutput(location_pub_, kMaxLineRate, false);
  if (params_.configure) {
    shell_timer_ =
        barrier_.timer(nh, ros::Duration(0.25), "shell", &Dwm1001DriverNode::onShellTimer, this);
  }
  start();
}

Dwm1001DriverNode::~Dwm1001DriverNode() {
  shell_timer_.stop();
  std::string stop;
  if (params_.configure) {
    std::lock_guard<std::mutex> lock(mutex());
    stop = shell_.stopText();
  }
  shutdown(stop);
}

const std::string& Dwm1001DriverNode::tagId() const {
  return params_.configure ? shell_.tagId() : params_.tag_id;
}

std::string Dwm1001DriverNode::frameId() const {
  return params_.frame_id.empty() ? "uwb_" + tagId() : params_.frame_id;
}

std::string Dwm1001DriverNode::onOpened(double now) {
  return params_.configure ? shell_.onConnected(now) : std::string();
}

void Dwm1001DriverNode::onClosed() {
  shell_.onDisconnected();
}

std::string Dwm1001DriverNode::onLine(std::string_view line, double stamp) {
  std::string reply = params_.configure ? shell_.onLine(line, stamp) : std::string();
  decode(line, stamp);
  return reply;
}

std::string Dwm1001DriverNode::onPending(std::string_view pending, double now) {
  return params_.configure ? shell_.onPending(pending, now) : std::string();
}

void Dwm1001DriverNode::diagnose(diagnostic_updater::DiagnosticStatusWrapper& status) {
  std::lock_guard<std::mutex> lock(mutex());
  status.add("tag id", tagId());
  status.add("shell restarts", shell_.restarts());
}

void Dwm1001DriverNode::decode(std::string_view line, double stamp) {
  const drivers::DwmLineStatus status = drivers::decodeDwmLine(line, measurement_);
  drivers::LineVerdict verdict = drivers::verdictOf(status, drivers::DwmLineStatus::kMeasurement);
  if (verdict == drivers::LineVerdict::kMeasurement && params_.configure &&
      shell_.state() != drivers::Dwm1001Shell::State::kStreaming) {
    verdict = drivers::LineVerdict::kFiltered;  // a stream left running from before
    ROS_DEBUG_THROTTLE_NAMED(5.0, "wiring",
                             "%s: measurement dropped: shell dialogue not finished, module "
                             "ID unknown yet",
                             ros::this_node::getName().c_str());
  }
  count(verdict, line, drivers::toString(status));
  if (verdict == drivers::LineVerdict::kMeasurement) {
    enqueue(messages(stamp));
  }
}

Dwm1001Output Dwm1001DriverNode::messages(double stamp) const {
  const ros::Time time(stamp);
  Dwm1001Output out;
  out.has_ranges = !measurement_.ranges.empty();
  if (out.has_ranges) {
    UwbRanges& msg = out.ranges;
    msg.header.stamp = time;
    msg.header.frame_id = frameId();
    msg.tag_id = tagId();
    msg.ranges.reserve(measurement_.ranges.size());
    for (const drivers::DwmAnchorRange& a : measurement_.ranges) {
      UwbRange r;
      r.anchor_id = normalizeId(a.id);  // firmware prints upper case; a replayed log may not
      r.anchor_position.x = a.x;
      r.anchor_position.y = a.y;
      r.anchor_position.z = a.z;
      r.range = a.range;
      msg.ranges.push_back(r);
    }
  }
  out.has_location = measurement_.has_position;
  if (out.has_location) {
    UwbTagLocation& msg = out.location;
    msg.header.stamp = time;
    msg.header.frame_id = params_.network_frame_id;
    msg.position.x = measurement_.position.x;
    msg.position.y = measurement_.position.y;
    msg.position.z = measurement_.position.z;
    msg.quality = measurement_.position.quality;
    msg.computation_time_us = measurement_.computation_time_us;
  }
  return out;
}

void Dwm1001DriverNode::publish(Dwm1001Output& out) {
  if (out.has_ranges) {
    ranges_pub_.publish(out.ranges);
    ranges_output_->tick(out.ranges.header.stamp);
  }
  if (out.has_location) {
    location_pub_.publish(out.location);
    location_output_->tick(out.location.header.stamp);
  }
}

void Dwm1001DriverNode::onShellTimer(const ros::TimerEvent&) {
  std::string text;
  {
    std::lock_guard<std::mutex> lock(mutex());
    const double now = ros::Time::now().toSec();
    text = shell_.onTick(now);
    // A module that reset mid-stream is back in its binary API and says nothing:
    // run the dialogue again rather than only warning.
    if (text.empty() && silent(now)) {
      text = shell_.onSilence(now);
    }
  }
  send(std::move(text));
}

}  // namespace radio_follow
