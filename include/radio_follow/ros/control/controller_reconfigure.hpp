// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <ros/ros.h>

#include <functional>
#include <memory>

#include "radio_follow/ControllerTuningConfig.h"
#include "radio_follow/FollowLawTuningConfig.h"
#include "radio_follow/control/velocity_law.hpp"
#include "radio_follow/ros/control/controller_base.hpp"
#include "radio_follow/ros/common/reconfigure_server.hpp"

namespace radio_follow {

/// Live tuning of a controller's shared safety thresholds and motion limits, on the
/// controller's private namespace (doc/live_tuning.md).
using ControllerReconfigure = ReconfigureServer<ControllerTuningConfig, ControllerCommonParams>;
std::unique_ptr<ControllerReconfigure> makeControllerReconfigure(
    const ros::NodeHandle& private_nh, const ControllerCommonParams& initial,
    std::function<void(const ControllerCommonParams&)> apply);

/// Live tuning of the follow law (follow distance, slow-down, feed-forward, PID gains) of
/// velocity_controller and path_follower, on `<node>/law` (doc/live_tuning.md).
using FollowLawReconfigure = ReconfigureServer<FollowLawTuningConfig, control::VelocityLawParams>;
std::unique_ptr<FollowLawReconfigure> makeFollowLawReconfigure(
    const ros::NodeHandle& private_nh, const control::VelocityLawParams& initial,
    std::function<void(const control::VelocityLawParams&)> apply);

}  // namespace radio_follow
