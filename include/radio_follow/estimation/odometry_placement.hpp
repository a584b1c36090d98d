// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstddef>
#include <optional>

#include "radio_follow/common/pose2.hpp"

namespace radio_follow {
namespace estimation {

/// Where a measurement goes when the robot's odometry pose at its stamp is looked up
/// (the locator's odometry-frame tracking, doc/nodes/locator.md):
/// - a pose: placed in the odometry frame;
/// - no pose while odometry was there within `fallback_after` seconds: dropped (counted),
///   a gap in TF must not switch frames, which restarts the track;
/// - no pose for longer (no odometry on this robot, or it died): the robot's own frame,
///   the tracking the locator did before odometry existed.
class OdometryPlacement {
 public:
  enum class Decision { kPlace, kDrop, kRobotFrame };

  explicit OdometryPlacement(double fallback_after = 1.0) : fallback_after_(fallback_after) {}

  /// `pose`: the lookup for a measurement received at `now` (receiver clock, s).
  Decision decide(const std::optional<Pose2>& pose, double now) {
    if (pose) {
      last_pose_ = now;
      ++placed_;
      return Decision::kPlace;
    }
    if (last_pose_ && now - *last_pose_ <= fallback_after_ && now >= *last_pose_) {
      ++dropped_;
      return Decision::kDrop;
    }
    last_pose_.reset();
    ++robot_frame_;
    return Decision::kRobotFrame;
  }

  bool usingOdometry() const { return last_pose_.has_value(); }
  std::size_t placed() const { return placed_; }
  std::size_t dropped() const { return dropped_; }
  std::size_t robotFrame() const { return robot_frame_; }

 private:
  double fallback_after_;
  std::optional<double> last_pose_;
  std::size_t placed_ = 0;
  std::size_t dropped_ = 0;
  std::size_t robot_frame_ = 0;
};

}  // namespace estimation
}  // namespace radio_follow
