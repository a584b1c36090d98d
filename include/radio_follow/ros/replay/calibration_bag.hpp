// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstddef>
#include <map>
#include <string>
#include <vector>

#include "radio_follow/config/layout.hpp"
#include "radio_follow/estimation/calibration_pairing.hpp"

namespace radio_follow {

/// The topics a calibration reads from a bag (names as recorded, with or without the
/// leading '/').
struct CalibrationTopics {
  std::vector<std::string> uwb;  ///< radio_follow/UwbRanges
  std::vector<std::string> aoa;  ///< radio_follow/AoaBearing
  /// The ground truth: geometry_msgs/PointStamped (the simulator's
  /// ground_truth/target_relative), PoseStamped or nav_msgs/Odometry (a motion-capture
  /// system), of the tag in the layout's fixed frame. Empty: no ground-truth topic (tape
  /// points instead).
  std::string truth;
};

/// What a calibration needs of a bag, as the core's types.
struct CalibrationBag {
  /// Ranges to the layout's target anchor and bearings of its tag, in recording order.
  std::vector<estimation::CalibrationMeasurement> measurements;
  std::vector<estimation::TimedPosition> truth;
  /// Messages read per requested sensor topic (as given); 0 when the bag lacks it.
  std::map<std::string, std::size_t> messages;
  /// Every topic of the bag with its type, for messages naming what it does hold.
  std::map<std::string, std::string> bag_topics;
  std::size_t other_anchors = 0;  ///< ranges to anchors other than the target's
  std::size_t other_tags = 0;     ///< bearings of tags other than the target's
  double duration = 0.0;          ///< s, of the recording
};

/// Reads `topics` of the bag at `path`. Throws std::runtime_error naming the bag and the
/// topic when the bag cannot be read, a topic has another type than expected, the truth
/// topic is not in the bag (listing the bag's topics of a usable type) or its frame is
/// not the layout's fixed frame.
CalibrationBag loadCalibrationBag(const std::string& path, const Layout& layout,
                                  const CalibrationTopics& topics);

/// The bag's topics of `type`, comma separated, or "none": for error messages.
std::string topicsOfType(const CalibrationBag& bag, const std::string& type);

}  // namespace radio_follow
