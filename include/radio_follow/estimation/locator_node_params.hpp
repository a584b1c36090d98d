// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <map>
#include <string>
#include <vector>

#include "radio_follow/common/param_source.hpp"
#include "radio_follow/common/param_table.hpp"
#include "radio_follow/estimation/locator.hpp"

namespace radio_follow {
namespace estimation {

/// The locator node's parameters (doc/nodes/locator.md, config/locator.yaml): its wiring
/// and the core's tuning. The offline tools and the lockstep closed loop read the same
/// keys from the same file.
struct LocatorNodeParams {
  std::string layout_file;  ///< required
  /// Inputs, by each kind's topics parameter (topicsParams(): uwb_topics, aoa_topics,
  /// tdoa_topics); all empty (the default) = the layout's conventional topics.
  std::map<std::string, std::vector<std::string>> topics;
  double rate = 20.0;                   ///< solves per second, Hz
  std::string target_frame = "target";  ///< child frame of the published TF
  bool publish_tf = true;
  /// An input topic without a message for this long (or never since the start) is
  /// silent: warned about once per 10 s and listed in the diagnostics, s.
  double input_timeout = 3.0;
  /// Estimates kept in `target_path` (nav_msgs/Path); 0 = no path topic.
  int path_length = 200;
  /// Odometry frame the particle estimator tracks in (TF odom_frame -> fixed frame at
  /// each measurement's stamp); "" = the robot's own frame.
  std::string odom_frame = "odom";
  /// A stamp up to this much newer than the newest odometry TF uses that TF, s.
  double tf_tolerance = 0.25;
  LocatorConfig locator;  ///< the core's tuning

  /// The node's own parameters but the topic lists; the core's tuning has its own
  /// table (estimation::LocatorConfig::table()).
  static const ParamTable<LocatorNodeParams>& table();
  /// Reads the private parameters from `source`: the node's namespace (ParamReader) or
  /// a YamlParams (a parameter file, for tools without a master), the same keys either
  /// way (doc/nodes/locator.md).
  void load(const ParamSource& source);
  /// Throws ParamError naming the first invalid parameter.
  void validate() const;
};

}  // namespace estimation
}  // namespace radio_follow
