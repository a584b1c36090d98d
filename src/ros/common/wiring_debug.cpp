// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/ros/common/wiring_debug.hpp"

namespace radio_follow {

void debugSubscribed(const ros::Subscriber& subscriber) {
  ROS_DEBUG_NAMED("wiring", "%s: subscribed to %s", ros::this_node::getName().c_str(),
                  subscriber.getTopic().c_str());
}

void debugAdvertised(const ros::Publisher& publisher) {
  ROS_DEBUG_NAMED("wiring", "%s: publishes %s", ros::this_node::getName().c_str(),
                  publisher.getTopic().c_str());
}

void FirstMessageLog::operator()(const std::string& topic) {
  if (!seen_.exchange(true)) {
    ROS_DEBUG_NAMED("wiring", "%s: first message on %s", ros::this_node::getName().c_str(),
                    topic.c_str());
  }
}

}  // namespace radio_follow
