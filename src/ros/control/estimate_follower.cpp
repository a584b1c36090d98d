// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/ros/control/estimate_follower.hpp"

#include <optional>

#include "radio_follow/common/geometry.hpp"
#include "radio_follow/control/target_track.hpp"
#include "radio_follow/ros/common/target_estimate.hpp"
#include "radio_follow/ros/common/wiring_debug.hpp"

namespace radio_follow {

void EstimateFollowerNode::startFollowing(control::FollowLaw& law) {
  estimate_sub_ = barrier_.subscribe(nh_, "target", 5, &EstimateFollowerNode::onEstimate, this);
  debugSubscribed(estimate_sub_);
  start(law);
}

void EstimateFollowerNode::onEstimate(const TargetEstimate::ConstPtr& msg) {
  const auto& c = msg->position_covariance;  // row-major 3x3
  Eigen::Matrix2d covariance;
  covariance << c[0], c[1], c[3], c[4];
  // A position or an odometry part no robot can have (non-finite, far beyond any network)
  // is no target: the robot stops as for LOST.
  const TargetStatus status = estimateQuality(*msg) == control::EstimateQuality::kLost
                                  ? TargetStatus::kLost
                                  : static_cast<TargetStatus>(msg->status);
  const control::EstimateUse use = noteEstimate(
      msg->header.stamp, status, msg->range, msg->bearing,
      polarSpread(Eigen::Vector2d(msg->position.x, msg->position.y), covariance), msg->hypotheses);
  // A refused estimate (from the future) stops the robot; nothing of it reaches the track.
  if (use != control::EstimateUse::kTrackPoint) {
    return;
  }
  const std::optional<control::TrackPoint> point =
      msg->odom_frame.empty() || !acceptsOdomFrame(msg->odom_frame)
          ? std::nullopt
          : control::trackPoint(Eigen::Vector2d(msg->odom_robot.x, msg->odom_robot.y),
                                Eigen::Vector2d(msg->odom_position.x, msg->odom_position.y),
                                Eigen::Vector2d(msg->odom_velocity.x, msg->odom_velocity.y));
  const bool kept = point && addTrackPoint(msg->header.stamp, *point);
  onTrackPoint(point.has_value(), kept, msg->header.stamp);
}

}  // namespace radio_follow
