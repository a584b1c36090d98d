// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <ros/ros.h>

#include <exception>
#include <string>

#include "radio_follow/common/param_error.hpp"

namespace radio_follow {

/// The whole `main` of a node: init ROS, construct `Node(nh, private_nh)` (which loads
/// and validates its parameters before it subscribes to anything), spin, and turn a
/// configuration error into a fatal log line and exit code 1.
template <typename Node>
int runNode(int argc, char** argv, const std::string& default_name) {
  ros::init(argc, argv, default_name);
  ros::NodeHandle nh;
  ros::NodeHandle private_nh("~");
  try {
    Node node(nh, private_nh);
    ros::spin();
  } catch (const ParamError& e) {
    ROS_FATAL("%s: %s", ros::this_node::getName().c_str(), e.what());
    return 1;
  } catch (const ros::InvalidNameException& e) {
    // A topic or frame name that no parameter check caught: still a configuration error,
    // not a crash (roscpp would otherwise abort with exit 134).
    ROS_FATAL("%s: invalid ROS name in the configuration: %s", ros::this_node::getName().c_str(),
              e.what());
    return 1;
  }
  return 0;
}

}  // namespace radio_follow
