// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <ros/time.h>
#include <tf2/buffer_core.h>

#include <optional>
#include <string>

#include "radio_follow/common/pose2.hpp"

namespace radio_follow {

/// The robot's planar pose in `odom_frame` at `stamp` from TF (`odom_frame -> robot_frame`,
/// interpolated): where the locator places a measurement of that stamp (doc/nodes/locator.md).
/// A stamp newer than the newest transform uses the newest one when it is at most
/// `tolerance` s older (TF lags the drivers by a few ms); otherwise nothing. The node passes
/// its tf2_ros::Buffer, locator_offline a tf2::BufferCore filled from the bag's /tf.
std::optional<Pose2> odometryPoseAt(const tf2::BufferCore& tf, const std::string& odom_frame,
                                    const std::string& robot_frame, const ros::Time& stamp,
                                    double tolerance);

}  // namespace radio_follow
