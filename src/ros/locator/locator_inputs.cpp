// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/ros/locator/locator_inputs.hpp"

#include <cmath>

#include "radio_follow/common/param_keys.hpp"

namespace radio_follow {

bool LocatorInputs::poseFor(const ros::Time& stamp, std::optional<Pose2>* pose) {
  pose->reset();
  if (!lookup_) {
    return true;
  }
  // A stamp further than kTfHorizon from the receiver's clock has no transform in any TF
  // buffer (tf2 keeps 10 s): the lookup's answer is known, nothing, and asking tf2 about a
  // stamp 2^32 s away overflows ros::Duration in its error text (issue 34).
  const double age = clock_() - stamp.toSec();
  if (std::abs(age) <= kTfHorizon) {
    *pose = lookup_(stamp);
  }
  const auto decision = placement_.decide(*pose, clock_());
  if (decision == estimation::OdometryPlacement::Decision::kRobotFrame) {
    pose->reset();
  }
  return decision != estimation::OdometryPlacement::Decision::kDrop;
}

std::size_t LocatorInputs::add(const UwbRanges& msg) {
  // The module is named by its ID; drivers started without one still set their frame.
  // IDs compare normalised (upper case), as the layout parser stores them: a layout
  // saying "da12" and a driver printing "DA12" mean the same anchor. (The module lookup,
  // Layout::findTwrModule, normalises the module ID itself.)
  const Layout& layout = locator_.layout();
  const std::size_t module =
      modules_(msg.tag_id.empty() ? msg.header.frame_id : msg.tag_id,
               [&](const std::string& id) { return layout.twrModuleIndex(id); });
  std::size_t refused = 0;
  std::optional<Pose2> pose;
  if (!poseFor(msg.header.stamp, &pose)) {
    return 0;  // counted by the placement
  }
  for (const auto& range : msg.ranges) {
    const bool target = target_anchors_(range.anchor_id, [&](const std::string& id) {
                          return normalizeId(id) == layout.target_anchor_id ? 0 : kNoSensor;
                        }) == 0;
    if (!target) {
      ++other_anchors_[normalizeId(range.anchor_id)];  // another anchor, or a wrong layout
      continue;
    }
    ++target_ranges_;
    refused += !locator_.addRange(module, range.range, msg.header.stamp.toSec(), pose);
  }
  return refused;
}

std::size_t LocatorInputs::add(const AoaBearing& msg) {
  const std::string& tag = locator_.layout().target_tag_id;
  if (!tag.empty() && normalizeId(msg.tag_id) != tag) {
    return 0;
  }
  std::optional<Pose2> pose;
  if (!poseFor(msg.header.stamp, &pose)) {
    return 0;
  }
  const std::size_t board = boards_(msg.header.frame_id, [&](const std::string& id) {
    return locator_.layout().aoaBoardIndex(id);
  });
  return !locator_.addBearing(board, msg.azimuth, msg.elevation, msg.rssi, msg.header.stamp.toSec(),
                              pose);
}

std::size_t LocatorInputs::add(const TdoaMeasurements& msg) {
  const Layout& layout = locator_.layout();
  const auto anchor = [&](const std::string& id) {
    return tdoa_anchors_(id, [&](const std::string& a) { return layout.tdoaAnchorIndex(a); });
  };
  if (!layout.isTargetTdoaTag(msg.tag_id)) {
    const std::size_t module = tdoa_tags_(msg.tag_id, [&](const std::string& id) {
      return locator_.tdoaCalibration().moduleOf(id).value_or(kNoSensor);
    });
    if (module != kNoSensor) {
      // One of the robot's own modules, at a known position: the anchors' offsets.
      std::size_t refused = 0;
      for (const auto& d : msg.differences) {
        refused += !locator_.addTdoaCalibration(module, anchor(d.anchor_a), anchor(d.anchor_b),
                                                d.distance_difference, msg.header.stamp.toSec());
      }
      ++calibration_blinks_;
      return refused;
    }
    ++other_tdoa_tags_[normalizeId(msg.tag_id)];  // not the person: never fused
    return 0;
  }
  std::size_t refused = 0;
  std::optional<Pose2> pose;
  if (!poseFor(msg.header.stamp, &pose)) {
    return 0;
  }
  for (const auto& d : msg.differences) {
    refused += !locator_.addTdoa(anchor(d.anchor_a), anchor(d.anchor_b), d.distance_difference,
                                 d.variance, msg.header.stamp.toSec(), pose);
  }
  return refused;
}

}  // namespace radio_follow
