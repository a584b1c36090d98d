// SPDX-License-Identifier: BSD-3-Clause
#pragma once

// For rostest nodes: spin until a condition holds; the deadline only turns a hang into a
// failure, it is not a timing assertion.

#include <ros/ros.h>

namespace radio_follow::test {

template <typename Predicate>
bool spinUntil(Predicate predicate, double timeout = 20.0) {
  const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(timeout);
  while (ros::ok() && ros::WallTime::now() < deadline) {
    ros::spinOnce();
    if (predicate()) {
      return true;
    }
    ros::WallDuration(0.01).sleep();
  }
  return false;
}

}  // namespace radio_follow::test
