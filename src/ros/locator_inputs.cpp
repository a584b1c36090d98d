// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/ros/locator_inputs.hpp"

namespace radio_follow {

std::size_t LocatorInputs::add(const UwbRanges& msg) {
  // The module is named by its ID; drivers started without one still set their frame.
  const std::string& module = msg.tag_id.empty() ? msg.header.frame_id : msg.tag_id;
  std::size_t refused = 0;
  for (const auto& range : msg.ranges) {
    if (range.anchor_id != locator_.layout().target_anchor_id) {
      continue;  // another anchor of the UWB network, not the target
    }
    refused += !locator_.addRange(module, range.range, msg.header.stamp.toSec());
  }
  return refused;
}

std::size_t LocatorInputs::add(const AoaBearing& msg) {
  const std::string& tag = locator_.layout().target_tag_id;
  if (!tag.empty() && msg.tag_id != tag) {
    return 0;
  }
  return !locator_.addBearing(msg.header.frame_id, msg.azimuth, msg.elevation, msg.rssi,
                              msg.header.stamp.toSec());
}

std::size_t LocatorInputs::add(const TdoaMeasurements& msg) {
  std::size_t refused = 0;
  for (const auto& d : msg.differences) {
    refused += !locator_.addTdoa(d.anchor_a, d.anchor_b, d.distance_difference, d.variance,
                                 msg.header.stamp.toSec());
  }
  return refused;
}

}  // namespace radio_follow
