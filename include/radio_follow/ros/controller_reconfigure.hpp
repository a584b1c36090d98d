// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <dynamic_reconfigure/server.h>
#include <ros/ros.h>

#include <boost/thread/recursive_mutex.hpp>
#include <functional>

#include "radio_follow/ControllerTuningConfig.h"
#include "radio_follow/ros/controller_base.hpp"

namespace radio_follow {

/// dynamic_reconfigure server of a controller's shared safety thresholds and motion limits
/// (doc/live_tuning.md). Starts with the loaded values; each request runs the same
/// ControllerCommonParams::validate() as at startup before `apply` installs it; a refused
/// request is logged (parameter, value, expectation) and the old values are pushed back.
class ControllerReconfigure {
 public:
  ControllerReconfigure(const ros::NodeHandle& private_nh, const ControllerCommonParams& initial,
                        std::function<void(const ControllerCommonParams&)> apply);

 private:
  void onRequest(ControllerTuningConfig& request, uint32_t level);

  boost::recursive_mutex mutex_;  // the server's API takes this type; guards its updates
  dynamic_reconfigure::Server<ControllerTuningConfig> server_;
  ControllerCommonParams current_;
  std::function<void(const ControllerCommonParams&)> apply_;
};

}  // namespace radio_follow
