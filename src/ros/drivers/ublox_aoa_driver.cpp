// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/ros/drivers/ublox_aoa_driver.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "radio_follow/common/param_error.hpp"
#include "radio_follow/drivers/text_fields.hpp"

namespace radio_follow {
namespace {

// Depth of the publish queue and of the roscpp publisher queue behind it (one burst has
// to fit in each; a roscpp queue that overflows drops its oldest message without telling
// anyone). A board reports up to about 50 +UUDF events/s (one per received CTE
// advertisement, several tags); a backlog arrives at once: whatever piled up in the host's
// tty buffers (up to 640 KiB) while the reader or a subscriber was held up. 4096 events
// are 80 s of a busy board; in the rostest driver_burst (doc/nodes/ublox_aoa_driver.md)
// they absorb 200,000 lines at 20,000 lines/s and bursts of 30 without a loss.
constexpr std::size_t kQueueDepth = 4096;

// Events/s of a busy board (several tags): more on `bearing` is a backlog arriving.
constexpr double kMaxEventRate = 100.0;

}  // namespace

void UbloxAoaDriverNode::Params::load(const ParamReader& private_nh) {
  private_nh.param("port", port, port);
  private_nh.param("baud", baud, baud);
  private_nh.param("frame_id", frame_id, frame_id);
  private_nh.param("tag_ids", tag_ids, tag_ids);
  private_nh.param("invert_azimuth", invert_azimuth, invert_azimuth);
  private_nh.param("init_commands", init_commands, init_commands);
  private_nh.param("reconnect_backoff", reconnect_backoff, reconnect_backoff);
  private_nh.param("silence_timeout", silence_timeout, silence_timeout);
  private_nh.param("max_line_length", max_line_length, max_line_length);
  // The device reports IDs in upper case; accept either spelling in the config.
  for (std::string& id : tag_ids) {
    drivers::assignUpperHex(std::string(id), id);
  }
}

void UbloxAoaDriverNode::Params::validate() const {
  require(!port.empty(), "port", port, "a device path such as /dev/aoa_front");
  require(baud > 0, "baud", baud, "a positive baud rate (the board uses 115200)");
  require(!frame_id.empty(), "frame_id", frame_id, "the antenna board's frame name");
  for (const std::string& id : tag_ids) {
    require(drivers::isHexId(id, 12), "tag_ids", id, "12 hexadecimal digits per tag");
  }
  for (const std::string& command : init_commands) {
    require(!command.empty() && command.find_first_of("\r\n") == std::string::npos, "init_commands",
            command, "one AT command per entry, without line ends");
  }
  require(reconnect_backoff > 0.0 && reconnect_backoff <= 10.0, "reconnect_backoff",
          reconnect_backoff, "seconds in (0, 10]");
  require(silence_timeout > 0.0, "silence_timeout", silence_timeout, "positive seconds");
  require(max_line_length >= 64, "max_line_length", max_line_length, "at least 64 bytes");
}

UbloxAoaDriverNode::UbloxAoaDriverNode(ros::NodeHandle& nh, ros::NodeHandle& private_nh) {
  params_ = loadStrict<Params>(private_nh);
  framer_ = drivers::LineFramer(static_cast<std::size_t>(params_.max_line_length));
  bearing_pub_ = nh.advertise<AoaBearing>("bearing", kQueueDepth);
  queue_ =
      std::make_unique<drivers::DeliveryQueue<AoaBearing>>(kQueueDepth, [this](AoaBearing& msg) {
        bearing_pub_.publish(msg);
        bearing_diagnostic_->tick(msg.header.stamp);
        if (stats_.messages++ == 0) {
          ROS_DEBUG_NAMED("wiring", "%s: first bearing from %s published on %s",
                          ros::this_node::getName().c_str(), params_.port.c_str(),
                          bearing_pub_.getTopic().c_str());
        }
      });
  diagnostics_ = std::make_unique<DriverDiagnostics>(
      nh, private_nh, "ublox aoa " + params_.port,
      params_.port + " (board " + params_.frame_id + ")", stats_, params_.silence_timeout);
  bearing_diagnostic_.emplace(
      diagnostics_->updater(), "ublox aoa " + params_.port + " output", bearing_pub_,
      OutputDiagnostic::Bounds::forDriver(params_.silence_timeout, kMaxEventRate), true);

  drivers::SerialTransport::Options options;
  options.port = params_.port;
  options.baud = static_cast<unsigned>(params_.baud);
  options.max_backoff =
      std::chrono::milliseconds(static_cast<long>(std::lround(params_.reconnect_backoff * 1000.0)));
  drivers::SerialTransport::Callbacks callbacks;
  callbacks.on_bytes = [this](const char* data, std::size_t size) { onBytes(data, size); };
  callbacks.on_connected = [this] { onConnected(); };
  callbacks.on_disconnected = [this](const std::string& reason) {
    stats_.connected = false;
    ROS_WARN("%s: device unavailable (%s); retrying", ros::this_node::getName().c_str(),
             reason.c_str());
  };
  transport_ = std::make_unique<drivers::SerialTransport>(options, callbacks);
  transport_->start();
}

UbloxAoaDriverNode::~UbloxAoaDriverNode() {
  transport_->stop();
  queue_->stop();  // publishes what the I/O thread queued last
}

void UbloxAoaDriverNode::onConnected() {
  stats_.connected = true;
  stats_.last_data_time = ros::Time::now().toSec();
  stats_.reconnects = transport_ ? transport_->reconnects() : 0;
  ROS_INFO("%s: opened %s", ros::this_node::getName().c_str(), params_.port.c_str());
  {
    std::lock_guard<std::mutex> lock(mutex_);
    framer_.reset();
  }
  for (const std::string& command : params_.init_commands) {
    transport_->write(command + "\r");
  }
}

void UbloxAoaDriverNode::onBytes(const char* data, std::size_t size) {
  const double now = ros::Time::now().toSec();
  stats_.bytes += size;
  stats_.last_data_time = now;
  std::lock_guard<std::mutex> lock(mutex_);
  framer_.feed(data, size, now,
               [this](std::string_view line, double stamp) { onLine(line, stamp); });
  stats_.overflows = framer_.counters().overflows;
}

bool UbloxAoaDriverNode::accepted(const std::string& tag_id) const {
  return params_.tag_ids.empty() ||
         std::find(params_.tag_ids.begin(), params_.tag_ids.end(), tag_id) != params_.tag_ids.end();
}

void UbloxAoaDriverNode::onLine(std::string_view line, double stamp) {
  const drivers::UudfLineStatus status = drivers::decodeUudfLine(line, event_);
  if (status == drivers::UudfLineStatus::kIgnored) {
    ++stats_.ignored;
    return;
  }
  if (status != drivers::UudfLineStatus::kEvent) {
    ++stats_.rejected;
    if (status == drivers::UudfLineStatus::kImplausible) {
      ++stats_.implausible;
    }
    ROS_WARN_THROTTLE(5.0, "%s: rejected line (%s, %lu so far): '%.*s'",
                      ros::this_node::getName().c_str(), drivers::toString(status),
                      static_cast<unsigned long>(stats_.rejected.load()),
                      static_cast<int>(std::min<std::size_t>(line.size(), 120)), line.data());
    return;
  }
  if (!accepted(event_.tag_id)) {
    ++stats_.filtered;
    ROS_DEBUG_THROTTLE_NAMED(5.0, "wiring", "%s: bearing dropped: tag %s not in ~tag_ids",
                             ros::this_node::getName().c_str(), event_.tag_id.c_str());
    return;
  }
  AoaBearing msg;
  msg.header.stamp = ros::Time(stamp);
  msg.header.frame_id = params_.frame_id;
  msg.tag_id = event_.tag_id;
  msg.anchor_id = event_.anchor_id;
  // The device measures clockwise seen from above; REP-103 frames turn counter-clockwise.
  msg.azimuth = params_.invert_azimuth ? -event_.azimuth : event_.azimuth;
  msg.elevation = event_.elevation;
  msg.rssi = event_.rssi;
  msg.rssi_second = event_.rssi_second;
  msg.channel = event_.channel;
  msg.device_timestamp_ms = event_.timestamp_ms;
  msg.event_counter = event_.event_counter;
  if (!queue_->push(std::move(msg))) {
    ++stats_.dropped;
    ROS_DEBUG_THROTTLE_NAMED(1.0, "wiring", "%s: bearing dropped: publish queue full",
                             ros::this_node::getName().c_str());
  }
  stats_.queue_peak = queue_->peak();
}

}  // namespace radio_follow
