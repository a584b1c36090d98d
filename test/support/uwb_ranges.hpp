// SPDX-License-Identifier: BSD-3-Clause
#pragma once

// For ROS tests that publish or record what a DWM1001 driver would: one module's ranges
// message with the target anchor's range.

#include <ros/time.h>

#include <string>

#include "radio_follow/UwbRanges.h"
#include "radio_follow/config/layout.hpp"

namespace radio_follow::test {

/// The ranges message of `module` at `stamp` holding one range to `anchor_id` (the driver's
/// raw reading, before the layout's calibration).
inline UwbRanges uwbRanges(const TwrModule& module, const std::string& anchor_id, double range,
                           const ros::Time& stamp) {
  UwbRanges msg;
  msg.header.stamp = stamp;
  msg.header.frame_id = module.frame_id;
  msg.tag_id = module.id;
  UwbRange r;
  r.anchor_id = anchor_id;
  r.range = range;
  msg.ranges.push_back(r);
  return msg;
}

}  // namespace radio_follow::test
