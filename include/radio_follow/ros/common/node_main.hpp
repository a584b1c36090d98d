// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <ros/ros.h>

#include <exception>
#include <string>
#include <type_traits>
#include <utility>

#include "radio_follow/common/fatal_handlers.hpp"
#include "radio_follow/common/param_error.hpp"

namespace radio_follow {

/// Seconds a dying node lingers after its last words so that what they published leaves
/// the process (roscpp writes on its own thread).
constexpr double kLastWordsLinger = 0.2;

/// Whether `Node` has `void lastWords(const char* reason)`: what it sends before it dies
/// (a controller: zero cmd_vel).
template <typename Node, typename = void>
struct HasLastWords : std::false_type {};
template <typename Node>
struct HasLastWords<Node, std::void_t<decltype(std::declval<Node&>().lastWords(""))>>
    : std::true_type {};

/// The log line of a dying node (rosconsole is not signal-safe: best effort, after the
/// last words).
inline void logDying(const char* reason) {
  ROS_FATAL("%s: dying: %s", ros::this_node::getName().c_str(), reason);
}

/// The whole `main` of a node: init ROS, construct `Node(nh, private_nh)` (which loads
/// and validates its parameters before it subscribes to anything), spin, and turn a
/// configuration error into a fatal log line and exit code 1. An uncaught exception or a
/// fatal signal (installFatalHandlers) logs why and, once the node exists, runs its
/// lastWords first: a controller sends zero cmd_vel before the process dies.
template <typename Node>
int runNode(int argc, char** argv, const std::string& default_name) {
  ros::init(argc, argv, default_name);
  ros::NodeHandle nh;
  ros::NodeHandle private_nh("~");
  installFatalHandlers(logDying, 0.0);
  try {
    Node node(nh, private_nh);
    if constexpr (HasLastWords<Node>::value) {
      installFatalHandlers(
          [&node](const char* reason) {
            node.lastWords(reason);
            logDying(reason);
          },
          kLastWordsLinger);
    }
    ros::spin();
    installFatalHandlers(logDying, 0.0);  // the node goes: nothing of it to call
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
