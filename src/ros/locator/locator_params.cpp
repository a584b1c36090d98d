// SPDX-License-Identifier: BSD-3-Clause
#include <cmath>

#include "radio_follow/common/param_error.hpp"
#include "radio_follow/ros/locator/locator_node.hpp"  // declares LocatorNode::Params

namespace radio_follow {

void LocatorNode::Params::load(const ParamSource& nh) {
  nh.param("layout_file", layout_file, layout_file);
  nh.param("uwb_topics", uwb_topics, uwb_topics);
  nh.param("aoa_topics", aoa_topics, aoa_topics);
  nh.param("tdoa_topics", tdoa_topics, tdoa_topics);
  nh.param("rate", rate, rate);
  nh.param("target_frame", target_frame, target_frame);
  nh.param("publish_tf", publish_tf, publish_tf);
  nh.param("input_timeout", input_timeout, input_timeout);
  nh.param("path_length", path_length, path_length);
  nh.param("odom_frame", odom_frame, odom_frame);
  nh.param("tf_tolerance", tf_tolerance, tf_tolerance);

  locator.load(nh);
}

void LocatorNode::Params::validate() const {
  require(!layout_file.empty(), "~layout_file", layout_file, "the path of a layout YAML file");
  // All topic lists empty is fine: the node then uses the layout's conventional topics.
  require(std::isfinite(rate) && rate > 0.0 && rate <= 200.0, "~rate", rate,
          "a solve rate in (0, 200] Hz");
  require(!target_frame.empty(), "~target_frame", target_frame, "a frame name");
  require(std::isfinite(input_timeout) && input_timeout > 0.0 && input_timeout <= 600.0,
          "~input_timeout", input_timeout, "seconds in (0, 600]");
  require(path_length >= 0 && path_length <= 100000, "~path_length", path_length,
          "a number of estimates in [0, 100000] (0 = no path)");
  require(std::isfinite(tf_tolerance) && tf_tolerance >= 0.0 && tf_tolerance <= 1.0,
          "~tf_tolerance", tf_tolerance, "seconds in [0, 1]");
  locator.validate();  // the core names its fields exactly like these private parameters
}

}  // namespace radio_follow
