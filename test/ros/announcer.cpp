// SPDX-License-Identifier: BSD-3-Clause
// Publishes status texts to the running announcer (whose speaker is
// test/ros/fake_speaker.sh) and checks what was "spoken": in order, one at a time,
// identical texts once per repeat_interval.
#include <gtest/gtest.h>
#include <ros/ros.h>

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "../support/read_lines.hpp"
#include "controller_test_utils.hpp"
#include "radio_follow/FollowerStatus.h"

namespace {

using radio_follow::test::readLines;

TEST(Announcer, SpeaksOneAtATimeAndRateLimitsRepeats) {
  ros::NodeHandle nh;
  ros::NodeHandle pnh("~");
  std::string log;
  ASSERT_TRUE(pnh.getParam("log", log));
  std::remove(log.c_str());

  ros::Publisher velocity =
      nh.advertise<radio_follow::FollowerStatus>("velocity_controller/status", 10);
  ros::Publisher homing =
      nh.advertise<radio_follow::FollowerStatus>("homing_controller/status", 10);
  ASSERT_TRUE(radio_follow_test::waitFor(
      [&] { return velocity.getNumSubscribers() > 0 && homing.getNumSubscribers() > 0; }, 20.0));

  radio_follow::FollowerStatus status;
  for (const char* text : {"Following.", "Following.", "Too close, stopping."}) {
    status.text = text;
    velocity.publish(status);
  }
  // Two topics have no order between them: publish on the second once the first
  // topic's messages are being spoken.
  ASSERT_TRUE(radio_follow_test::waitFor(
      [&] {
        const auto lines = readLines(log);
        return std::find(lines.begin(), lines.end(), "start Too close, stopping.") != lines.end();
      },
      20.0));
  status.text = "Homing to the target.";
  homing.publish(status);
  status.text = "Following.";  // spoken moments ago: rate-limited
  velocity.publish(status);

  const std::vector<std::string> expected = {"start Following.",
                                             "end Following.",
                                             "start Too close, stopping.",
                                             "end Too close, stopping.",
                                             "start Homing to the target.",
                                             "end Homing to the target."};
  ASSERT_TRUE(radio_follow_test::waitFor([&] { return readLines(log).size() >= 6; }, 20.0));
  ros::WallDuration(1.0).sleep();  // nothing more may follow
  EXPECT_EQ(readLines(log), expected);
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "announcer_rostest");
  ros::AsyncSpinner spinner(1);
  spinner.start();
  return RUN_ALL_TESTS();
}
