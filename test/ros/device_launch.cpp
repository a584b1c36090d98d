// SPDX-License-Identifier: BSD-3-Clause
// The per-device launch files' defaults follow the topic convention the locator
// subscribes to (a robot wired from them used to publish /uwb_5722/ranges while the
// locator listened on /uwb/5722/ranges: it never moved and nothing said why).
#include <gtest/gtest.h>
#include <ros/ros.h>

#include <algorithm>
#include <set>
#include <string>
#include <vector>

#include "../support/spin_until.hpp"
#include "radio_follow/config/layout.hpp"

namespace {

std::set<std::string> advertised() {
  ros::master::V_TopicInfo topics;
  ros::master::getTopics(topics);
  std::set<std::string> names;
  for (const auto& t : topics) {
    names.insert(t.name);
  }
  return names;
}

TEST(DeviceLaunch, DefaultsPublishWhereTheLocatorListens) {
  std::string layout_file;
  ASSERT_TRUE(ros::param::get("~layout_file", layout_file));
  const radio_follow::SensorTopics expected =
      radio_follow::conventionalTopics(radio_follow::loadLayoutFile(layout_file));
  const auto has = [](const std::vector<std::string>& list, const std::string& topic) {
    return std::find(list.begin(), list.end(), topic) != list.end();
  };
  // What the locator resolves (relative names in the root namespace).
  ASSERT_TRUE(has(expected.uwb, "uwb/5A84/ranges"));
  ASSERT_TRUE(has(expected.aoa, "aoa/left/bearing"));
  std::set<std::string> names;
  ASSERT_TRUE(radio_follow::test::spinUntil(
      [&] {
        names = advertised();
        return names.count("/uwb/5A84/ranges") && names.count("/aoa/left/bearing");
      },
      30.0))
      << "the drivers started from the per-device launch files do not publish on "
         "/uwb/5A84/ranges and /aoa/left/bearing";
  EXPECT_FALSE(names.count("/uwb_5A84/ranges"));
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "device_launch_rostest");
  ros::NodeHandle nh;
  return RUN_ALL_TESTS();
}
