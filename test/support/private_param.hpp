// SPDX-License-Identifier: BSD-3-Clause
#pragma once

// For rostest nodes: a string parameter of the test node's private namespace (the
// paths a .test file passes: bags, config directories); a missing one fails the test.

#include <gtest/gtest.h>
#include <ros/ros.h>

#include <string>

namespace radio_follow::test {

inline std::string privateParam(const std::string& name) {
  std::string value;
  EXPECT_TRUE(ros::param::get("~" + name, value)) << name;
  return value;
}

}  // namespace radio_follow::test
