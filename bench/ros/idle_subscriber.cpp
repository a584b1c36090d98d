// SPDX-License-Identifier: BSD-3-Clause
// The floor of the locator's load: a roscpp node that subscribes to the locator's inputs
// in scripts/measure_locator_load.sh (uwb/ranges, aoa/<board>/bearing) and does nothing
// with them. What it costs is what receiving and deserialising the messages costs; the
// script measures it in the same run as the locator and prints the ratio.
#include <ros/ros.h>

#include <string>
#include <vector>

#include "radio_follow/AoaBearing.h"
#include "radio_follow/UwbRanges.h"

int main(int argc, char** argv) {
  ros::init(argc, argv, "idle_subscriber");
  ros::NodeHandle nh;
  std::vector<ros::Subscriber> subscribers;
  subscribers.push_back(nh.subscribe<radio_follow::UwbRanges>(
      "uwb/ranges", 10, [](const radio_follow::UwbRanges::ConstPtr&) {}, ros::VoidPtr()));
  for (const std::string board : {"front", "left", "back", "right"}) {
    subscribers.push_back(nh.subscribe<radio_follow::AoaBearing>(
        "aoa/" + board + "/bearing", 10, [](const radio_follow::AoaBearing::ConstPtr&) {},
        ros::VoidPtr()));
  }
  ros::spin();
  return 0;
}
