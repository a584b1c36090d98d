// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>

#include "radio_follow/common/param_source.hpp"
#include "radio_follow/common/param_table.hpp"

namespace radio_follow {
namespace control {

/// What every controller node reads besides its command pipeline and its law
/// (doc/nodes/velocity_controller.md); the lockstep closed loop runs at the same rate.
struct ControllerWiring {
  std::string cmd_vel_topic = "cmd_vel";
  double rate = 20.0;  ///< Hz
  bool start_enabled = false;
  /// Optional sensor layout: when set, `range_topics` and `target_anchor_id` default to
  /// the layout's conventional topics (`uwb/<module id>/ranges`) and target anchor.
  std::string layout_file;

  static const ParamTable<ControllerWiring>& table();
};

/// Where the velocity and path controllers place the locator's estimates to track the
/// target's motion (the speed feed-forward, the path follower's path).
struct TrackParams {
  std::string odom_frame = "odom";  ///< empty: no track (no feed-forward), no TF needed
  /// An estimate newer than the newest odometry pose uses that pose when it is at most
  /// this much newer, s.
  double tf_timeout = 0.05;

  static const ParamTable<TrackParams>& table();
  void load(const ParamSource& source);
  void validate() const;
};

}  // namespace control
}  // namespace radio_follow
