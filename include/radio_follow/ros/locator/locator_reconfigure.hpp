// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <ros/ros.h>

#include <functional>
#include <memory>

#include "radio_follow/LocatorTuningConfig.h"
#include "radio_follow/estimation/locator.hpp"
#include "radio_follow/ros/common/reconfigure_server.hpp"

namespace radio_follow {

/// The core tuning as the reconfigure server shows it (the node's parameter names).
LocatorTuningConfig toTuning(const estimation::LocatorConfig& config);
/// `base` with the reconfigurable fields taken from `tuning` (mode and the rest kept).
/// Throws ParamError for an unknown enum text; values are validated by the caller.
estimation::LocatorConfig fromTuning(const LocatorTuningConfig& tuning,
                                     estimation::LocatorConfig base);

/// dynamic_reconfigure server of the locator node (doc/live_tuning.md): the generic
/// server (ros/reconfigure_server.hpp) over LocatorConfig. `apply` installs a valid tuning
/// (Locator::setConfig); it may throw ParamError, which refuses the change like a failed
/// validate().
using LocatorReconfigure = ReconfigureServer<LocatorTuningConfig, estimation::LocatorConfig>;
std::unique_ptr<LocatorReconfigure> makeLocatorReconfigure(
    const ros::NodeHandle& private_nh, const estimation::LocatorConfig& initial,
    std::function<void(const estimation::LocatorConfig&)> apply);

}  // namespace radio_follow
