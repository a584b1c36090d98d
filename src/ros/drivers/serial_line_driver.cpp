// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/ros/drivers/serial_line_driver.hpp"

#include <algorithm>

namespace radio_follow {

SerialLineDriver::SerialLineDriver(ros::NodeHandle& nh, ros::NodeHandle& private_nh,
                                   const drivers::SerialLineParams& params, const std::string& name,
                                   const std::string& hardware_id)
    : options_(params.transportOptions()),
      silence_timeout_(params.silence_timeout),
      name_(name),
      line_(static_cast<std::size_t>(params.max_line_length)),
      diagnostics_(
          nh, private_nh, name, hardware_id, line_.stats(), params.silence_timeout,
          [this](diagnostic_updater::DiagnosticStatusWrapper& status) { diagnose(status); }) {}

SerialLineDriver::~SerialLineDriver() = default;

OutputDiagnostic& SerialLineDriver::watchOutput(const ros::Publisher& publisher, double max_hz,
                                                bool rate_floor) {
  OutputDiagnostic::Bounds bounds = OutputDiagnostic::Bounds::forDriver(silence_timeout_, max_hz);
  if (!rate_floor) {
    bounds.min_hz = 0.0;
  }
  if (outputs_.empty()) {
    first_topic_ = publisher.getTopic();
  }
  outputs_.push_back(std::make_unique<OutputDiagnostic>(diagnostics_.updater(), name_ + " output",
                                                        publisher, bounds, true));
  return *outputs_.back();
}

void SerialLineDriver::start() {
  drivers::SerialTransport::Callbacks callbacks;
  // The I/O thread's callbacks run inside the barrier: an exception would end io_.run()
  // and with it the process.
  callbacks.on_bytes = [this](const char* data, std::size_t size) {
    barrier_.run("serial input", [&] { onBytes(data, size); });
  };
  callbacks.on_connected = [this] { barrier_.run("serial connect", [&] { onConnected(); }); };
  callbacks.on_disconnected = [this](const std::string& reason) {
    barrier_.run("serial disconnect", [&] { onDisconnected(reason); });
  };
  transport_ = std::make_unique<drivers::SerialTransport>(options_, callbacks);
  transport_->start();
}

void SerialLineDriver::closePort(const std::string& farewell) {
  if (!transport_) {
    return;
  }
  if (!farewell.empty() && transport_->state() == drivers::SerialTransport::State::kOpen) {
    transport_->write(farewell);
  }
  transport_->stop();
}

void SerialLineDriver::send(std::string text) {
  if (!text.empty()) {
    transport_->write(std::move(text));
  }
}

std::string SerialLineDriver::onOpened(double) {
  return {};
}

void SerialLineDriver::onClosed() {}

std::string SerialLineDriver::onPending(std::string_view, double) {
  return {};
}

void SerialLineDriver::diagnose(diagnostic_updater::DiagnosticStatusWrapper&) {}

void SerialLineDriver::onConnected() {
  const double now = ros::Time::now().toSec();
  ROS_INFO("%s: %s: opened", ros::this_node::getName().c_str(), name_.c_str());
  std::string text;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    line_.onConnected(now, transport_->reconnects());
    text = onOpened(now);
  }
  send(std::move(text));
}

void SerialLineDriver::onDisconnected(const std::string& reason) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    line_.onDisconnected();
    onClosed();
  }
  ROS_WARN("%s: %s: device unavailable (%s); retrying", ros::this_node::getName().c_str(),
           name_.c_str(), reason.c_str());
}

void SerialLineDriver::onBytes(const char* data, std::size_t size) {
  const double now = ros::Time::now().toSec();
  std::string reply;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    line_.onBytes(data, size, now,
                  [&](std::string_view line, double stamp) { reply += onLine(line, stamp); });
    reply += onPending(line_.pending(), now);
  }
  send(std::move(reply));
}

void SerialLineDriver::count(drivers::LineVerdict verdict, std::string_view line,
                             const char* reason) {
  const std::uint64_t rejected = line_.count(verdict);
  if ((verdict == drivers::LineVerdict::kRejected ||
       verdict == drivers::LineVerdict::kImplausible) &&
      rejected_log_.ready(ros::WallTime::now().toSec())) {
    ROS_WARN("%s: %s: rejected line (%s, %lu so far): '%.*s'", ros::this_node::getName().c_str(),
             name_.c_str(), reason, static_cast<unsigned long>(rejected),
             static_cast<int>(std::min<std::size_t>(line.size(), 120)), line.data());
  }
}

void SerialLineDriver::queued(bool kept, std::size_t peak) {
  line_.onQueued(kept, peak);
  if (!kept) {
    ROS_DEBUG_THROTTLE_NAMED(1.0, "wiring", "%s: measurement dropped: publish queue full",
                             ros::this_node::getName().c_str());
  }
}

void SerialLineDriver::published() {
  if (line_.onPublished()) {
    ROS_DEBUG_NAMED("wiring", "%s: first measurement from %s published on %s",
                    ros::this_node::getName().c_str(), options_.port.c_str(), first_topic_.c_str());
  }
}

bool SerialLineDriver::silent(double now) const {
  return line_.silent(now, silence_timeout_);
}

}  // namespace radio_follow
