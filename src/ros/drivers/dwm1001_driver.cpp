// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/ros/drivers/dwm1001_driver.hpp"

#include <cmath>
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
constexpr std::size_t kQueueDepth = 4096;

// The module's top update rate (lines/s): more on `ranges` is a backlog arriving.
constexpr double kMaxLineRate = 10.0;

}  // namespace

void Dwm1001DriverNode::Params::load(const ParamReader& private_nh) {
  private_nh.param("port", port, port);
  private_nh.param("baud", baud, baud);
  private_nh.param("configure", configure, configure);
  private_nh.param("output_mode", output_mode, output_mode);
  private_nh.param("tag_id", tag_id, tag_id);
  tag_id = normalizeId(tag_id);  // IDs enter normalised (upper case), as the layout's
  private_nh.param("frame_id", frame_id, frame_id);
  private_nh.param("network_frame_id", network_frame_id, network_frame_id);
  private_nh.param("reconnect_backoff", reconnect_backoff, reconnect_backoff);
  private_nh.param("silence_timeout", silence_timeout, silence_timeout);
  private_nh.param("shell_timeout", shell_timeout, shell_timeout);
  private_nh.param("max_line_length", max_line_length, max_line_length);
}

void Dwm1001DriverNode::Params::validate() const {
  require(!port.empty(), "port", port, "a device path such as /dev/dwm1001_5722");
  require(baud > 0, "baud", baud, "a positive baud rate (the module uses 115200)");
  require(output_mode == "lec" || output_mode == "les", "output_mode", output_mode,
          "'lec' or 'les'");
  require(configure || !frame_id.empty() || !tag_id.empty(), "frame_id", frame_id,
          "a frame (or a tag_id to derive it from) when configure is false");
  require(!network_frame_id.empty(), "network_frame_id", network_frame_id, "a frame name");
  require(reconnect_backoff > 0.0 && reconnect_backoff <= 10.0, "reconnect_backoff",
          reconnect_backoff, "seconds in (0, 10]");
  require(silence_timeout > 0.0, "silence_timeout", silence_timeout, "positive seconds");
  require(shell_timeout > 0.0, "shell_timeout", shell_timeout, "positive seconds");
  require(max_line_length >= 64, "max_line_length", max_line_length, "at least 64 bytes");
}

Dwm1001DriverNode::Dwm1001DriverNode(ros::NodeHandle& nh, ros::NodeHandle& private_nh)
    : framer_(1024), shell_("lec", 2.0) {
  params_ = loadStrict<Params>(private_nh);
  framer_ = drivers::LineFramer(static_cast<std::size_t>(params_.max_line_length));
  shell_ = drivers::Dwm1001Shell(params_.output_mode, params_.shell_timeout);

  ranges_pub_ = nh.advertise<UwbRanges>("ranges", kQueueDepth);
  location_pub_ = nh.advertise<UwbTagLocation>("tag_location", kQueueDepth);
  queue_ = std::make_unique<drivers::DeliveryQueue<Outgoing>>(
      kQueueDepth, [this](Outgoing& out) { publish(out); });
  diagnostics_ = std::make_unique<DriverDiagnostics>(
      nh, private_nh, "dwm1001 " + params_.port,
      params_.tag_id.empty() ? params_.port : params_.port + " (module " + params_.tag_id + ")",
      stats_, params_.silence_timeout, [this](diagnostic_updater::DiagnosticStatusWrapper& status) {
        std::lock_guard<std::mutex> lock(mutex_);
        status.add("tag id", params_.configure ? shell_.tagId() : params_.tag_id);
        status.add("shell restarts", shell_.restarts());
      });
  // A module may give no position (tag_location): no lower rate there.
  OutputDiagnostic::Bounds bounds =
      OutputDiagnostic::Bounds::forDriver(params_.silence_timeout, kMaxLineRate);
  ranges_diagnostic_.emplace(diagnostics_->updater(), "dwm1001 " + params_.port + " output",
                             ranges_pub_, bounds, true);
  bounds.min_hz = 0.0;
  location_diagnostic_.emplace(diagnostics_->updater(), "dwm1001 " + params_.port + " output",
                               location_pub_, bounds, true);
  if (params_.configure) {
    shell_timer_ = nh.createTimer(ros::Duration(0.25), &Dwm1001DriverNode::onShellTimer, this);
  }

  drivers::SerialTransport::Options options;
  options.port = params_.port;
  options.baud = static_cast<unsigned>(params_.baud);
  options.max_backoff =
      std::chrono::milliseconds(static_cast<long>(std::lround(params_.reconnect_backoff * 1000.0)));
  drivers::SerialTransport::Callbacks callbacks;
  callbacks.on_bytes = [this](const char* data, std::size_t size) { onBytes(data, size); };
  callbacks.on_connected = [this] { onConnected(); };
  callbacks.on_disconnected = [this](const std::string& reason) { onDisconnected(reason); };
  transport_ = std::make_unique<drivers::SerialTransport>(options, callbacks);
  transport_->start();
}

Dwm1001DriverNode::~Dwm1001DriverNode() {
  shell_timer_.stop();
  if (params_.configure && transport_->state() == drivers::SerialTransport::State::kOpen) {
    std::string stop;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      stop = shell_.stopText();
    }
    transport_->write(stop);
  }
  transport_->stop();
  queue_->stop();  // publishes what the I/O thread queued last
}

std::string Dwm1001DriverNode::frameId() const {
  if (!params_.frame_id.empty()) {
    return params_.frame_id;
  }
  return "uwb_" + (params_.configure ? shell_.tagId() : params_.tag_id);
}

void Dwm1001DriverNode::onConnected() {
  const double now = ros::Time::now().toSec();
  stats_.connected = true;
  stats_.last_data_time = now;
  stats_.reconnects = transport_ ? transport_->reconnects() : 0;
  ROS_INFO("%s: opened %s", ros::this_node::getName().c_str(), params_.port.c_str());
  std::string text;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    framer_.reset();
    if (params_.configure) {
      text = shell_.onConnected(now);
    }
  }
  if (!text.empty()) {
    transport_->write(text);
  }
}

void Dwm1001DriverNode::onDisconnected(const std::string& reason) {
  stats_.connected = false;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    shell_.onDisconnected();
  }
  ROS_WARN("%s: device unavailable (%s); retrying", ros::this_node::getName().c_str(),
           reason.c_str());
}

void Dwm1001DriverNode::onBytes(const char* data, std::size_t size) {
  const double now = ros::Time::now().toSec();
  stats_.bytes += size;
  stats_.last_data_time = now;
  std::string reply;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    framer_.feed(data, size, now, [&](std::string_view line, double stamp) {
      if (params_.configure) {
        reply += shell_.onLine(line, stamp);
      }
      onLine(line, stamp);
    });
    if (params_.configure) {
      reply += shell_.onPending(framer_.pending(), now);
    }
    stats_.overflows = framer_.counters().overflows;
  }
  if (!reply.empty()) {
    transport_->write(reply);
  }
}

void Dwm1001DriverNode::onLine(std::string_view line, double stamp) {
  const drivers::DwmLineStatus status = drivers::decodeDwmLine(line, measurement_);
  switch (status) {
    case drivers::DwmLineStatus::kMeasurement:
      if (params_.configure && shell_.state() != drivers::Dwm1001Shell::State::kStreaming) {
        ++stats_.filtered;  // a stream left running from before; frame unknown yet
        ROS_DEBUG_THROTTLE_NAMED(5.0, "wiring",
                                 "%s: measurement dropped: shell dialogue not finished, module "
                                 "ID unknown yet",
                                 ros::this_node::getName().c_str());
      } else {
        enqueue(stamp);
      }
      break;
    case drivers::DwmLineStatus::kIgnored:
      ++stats_.ignored;
      break;
    default:
      ++stats_.rejected;
      if (status == drivers::DwmLineStatus::kImplausible) {
        ++stats_.implausible;
      }
      ROS_WARN_THROTTLE(5.0, "%s: rejected line (%s, %lu so far): '%.*s'",
                        ros::this_node::getName().c_str(), drivers::toString(status),
                        static_cast<unsigned long>(stats_.rejected.load()),
                        static_cast<int>(std::min<std::size_t>(line.size(), 120)), line.data());
  }
}

void Dwm1001DriverNode::enqueue(double stamp) {
  const ros::Time time(stamp);
  Outgoing out;
  out.has_ranges = !measurement_.ranges.empty();
  if (out.has_ranges) {
    UwbRanges& msg = out.ranges;
    msg.header.stamp = time;
    msg.header.frame_id = frameId();
    msg.tag_id = params_.configure ? shell_.tagId() : params_.tag_id;
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
  if (!queue_->push(std::move(out))) {
    ++stats_.dropped;
    ROS_DEBUG_THROTTLE_NAMED(1.0, "wiring", "%s: measurement dropped: publish queue full",
                             ros::this_node::getName().c_str());
  }
  stats_.queue_peak = queue_->peak();
}

void Dwm1001DriverNode::publish(Outgoing& out) {
  if (out.has_ranges) {
    ranges_pub_.publish(out.ranges);
    ranges_diagnostic_->tick(out.ranges.header.stamp);
  }
  if (out.has_location) {
    location_pub_.publish(out.location);
    location_diagnostic_->tick(out.location.header.stamp);
  }
  if (stats_.messages == 0) {
    ROS_DEBUG_NAMED("wiring", "%s: first measurement from %s published on %s",
                    ros::this_node::getName().c_str(), params_.port.c_str(),
                    ranges_pub_.getTopic().c_str());
  }
  ++stats_.messages;
}

void Dwm1001DriverNode::onShellTimer(const ros::TimerEvent&) {
  std::string text;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    const double now = ros::Time::now().toSec();
    text = shell_.onTick(now);
    // A module that reset mid-stream is back in its binary API and says nothing:
    // run the dialogue again rather than only warning.
    if (text.empty() && stats_.connected && now - stats_.last_data_time > params_.silence_timeout) {
      text = shell_.onSilence(now);
    }
  }
  if (!text.empty()) {
    transport_->write(text);
  }
}

}  // namespace radio_follow
