// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <dynamic_reconfigure/server.h>
#include <ros/ros.h>

#include <boost/thread/recursive_mutex.hpp>
#include <functional>
#include <string>
#include <utility>

#include "radio_follow/common/param_error.hpp"

namespace radio_follow {

/// A dynamic_reconfigure server over a node's parameter struct `Params` (which has
/// validate()). It starts with the values the node loaded, not the .cfg defaults; each
/// request is converted to a `Params`, checked by the same validate() as at startup and
/// handed to `apply`; a refused request is logged (parameter, value, expectation) and the
/// old values are pushed back, so a live change can never install what startup refuses.
/// The answer says so too: its `refused` field (every .cfg has it, kRefusedField) holds
/// the same reason after a refusal and is empty after an accepted change, so a client
/// (`dynparam get`, a script reading the service's response) sees the refusal.
template <typename Tuning, typename Params>
class ReconfigureServer {
 public:
  using ToTuning = std::function<Tuning(const Params&)>;
  /// Builds the requested parameters from the request and the current ones (fields the
  /// .cfg does not hold stay as they are).
  using FromTuning = std::function<Params(const Tuning&, const Params&)>;

  ReconfigureServer(const ros::NodeHandle& nh, const Params& initial, ToTuning to_tuning,
                    FromTuning from_tuning, std::function<void(const Params&)> apply)
      : server_(mutex_, nh),
        current_(initial),
        to_tuning_(std::move(to_tuning)),
        from_tuning_(std::move(from_tuning)),
        apply_(std::move(apply)),
        name_(nh.getNamespace()) {
    server_.updateConfig(to_tuning_(current_));
    server_.setCallback([this](Tuning& request, uint32_t /*level*/) { onRequest(request); });
  }

 private:
  void onRequest(Tuning& request) {
    try {
      const Params next = from_tuning_(request, current_);
      next.validate();
      apply_(next);
      current_ = next;
      request.refused.clear();
    } catch (const ParamError& e) {
      ROS_ERROR("%s: reconfigure refused, old values kept: %s", name_.c_str(), e.what());
      request = to_tuning_(current_);  // the server stores and publishes what is left here
      request.refused = e.what();
    }
  }

  boost::recursive_mutex mutex_;  // the server's API takes this type; guards its updates
  dynamic_reconfigure::Server<Tuning> server_;
  Params current_;
  ToTuning to_tuning_;
  FromTuning from_tuning_;
  std::function<void(const Params&)> apply_;
  std::string name_;
};

}  // namespace radio_follow
