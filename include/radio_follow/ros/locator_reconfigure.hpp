// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <dynamic_reconfigure/server.h>
#include <ros/ros.h>

#include <boost/thread/recursive_mutex.hpp>
#include <functional>

#include "radio_follow/LocatorTuningConfig.h"
#include "radio_follow/estimation/locator.hpp"

namespace radio_follow {

/// The core tuning as the reconfigure server shows it (the node's parameter names).
LocatorTuningConfig toTuning(const LocatorConfig& config);
/// `base` with the reconfigurable fields taken from `tuning` (mode and the rest kept).
/// Throws ParamError for an unknown enum text; values are validated by the caller.
LocatorConfig fromTuning(const LocatorTuningConfig& tuning, LocatorConfig base);

/// dynamic_reconfigure server of the locator node (doc/live_tuning.md). It starts with the
/// node's loaded tuning, not the .cfg defaults. Each request is converted, validated with
/// the same LocatorConfig::validate() as at startup and handed to `apply`; a refused change
/// (ParamError from either) is logged with the parameter, value and expectation, and the
/// old values are pushed back to the server and the parameter server.
class LocatorReconfigure {
 public:
  /// `apply` installs a valid tuning (e.g. Locator::setConfig); it may throw ParamError.
  LocatorReconfigure(const ros::NodeHandle& private_nh, const LocatorConfig& initial,
                     std::function<void(const LocatorConfig&)> apply);

 private:
  void onRequest(LocatorTuningConfig& request, uint32_t level);

  boost::recursive_mutex mutex_;  // the server's API takes this type; guards its updates
  dynamic_reconfigure::Server<LocatorTuningConfig> server_;
  LocatorConfig current_;
  std::function<void(const LocatorConfig&)> apply_;
};

}  // namespace radio_follow
