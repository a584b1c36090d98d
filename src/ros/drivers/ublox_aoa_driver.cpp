// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/ros/drivers/ublox_aoa_driver.hpp"

#include <algorithm>
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
constexpr std::size_t kBearingQueueDepth = 4096;

// Events/s of a busy board (several tags): more on `bearing` is a backlog arriving.
constexpr double kMaxEventRate = 100.0;

}  // namespace

UbloxAoaDriverNode::UbloxAoaDriverNode(ros::NodeHandle& nh, ros::NodeHandle& private_nh)
    : UbloxAoaDriverNode(nh, private_nh, loadStrict<Params>(private_nh)) {}

UbloxAoaDriverNode::UbloxAoaDriverNode(ros::NodeHandle& nh, ros::NodeHandle& private_nh,
                                       const Params& params)
    : QueuedSerialLineDriver(nh, private_nh, params, "ublox aoa " + params.port,
                             params.port + " (board " + params.frame_id + ")", kBearingQueueDepth),
      params_(params) {
  bearing_pub_ = nh.advertise<AoaBearing>("bearing", kBearingQueueDepth);
  bearing_output_ = &watchOutput(bearing_pub_, kMaxEventRate);
  start();
}

UbloxAoaDriverNode::~UbloxAoaDriverNode() {
  shutdown();
}

std::string UbloxAoaDriverNode::onOpened(double) {
  std::string text;
  for (const std::string& command : params_.init_commands) {
    text += command + "\r";
  }
  return text;
}

bool UbloxAoaDriverNode::accepted(const std::string& tag_id) const {
  return params_.tag_ids.empty() ||
         std::find(params_.tag_ids.begin(), params_.tag_ids.end(), tag_id) != params_.tag_ids.end();
}

std::string UbloxAoaDriverNode::onLine(std::string_view line, double stamp) {
  const drivers::UudfLineStatus status = drivers::decodeUudfLine(line, event_);
  drivers::LineVerdict verdict = drivers::verdictOf(status, drivers::UudfLineStatus::kEvent);
  if (verdict == drivers::LineVerdict::kMeasurement && !accepted(event_.tag_id)) {
    verdict = drivers::LineVerdict::kFiltered;
    ROS_DEBUG_THROTTLE_NAMED(5.0, "wiring", "%s: bearing dropped: tag %s not in ~tag_ids",
                             ros::this_node::getName().c_str(), event_.tag_id.c_str());
  }
  count(verdict, line, drivers::toString(status));
  if (verdict == drivers::LineVerdict::kMeasurement) {
    enqueue(message(stamp));
  }
  return {};
}

AoaBearing UbloxAoaDriverNode::message(double stamp) const {
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
  return msg;
}

void UbloxAoaDriverNode::publish(AoaBearing& msg) {
  bearing_pub_.publish(msg);
  bearing_output_->tick(msg.header.stamp);
}

}  // namespace radio_follow
