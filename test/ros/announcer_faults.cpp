// SPDX-License-Identifier: BSD-3-Clause
// The announcer against the real dwm1001_driver and locator: a module unplugged and
// replugged is said to be lost and back; a locator without measurements says it lost the
// target and which input is silent. Fault texts come from their /diagnostics.
#include <gtest/gtest.h>
#include <ros/ros.h>

#include <algorithm>
#include <string>
#include <vector>

#include "../support/fake_dwm1001.hpp"
#include "../support/read_lines.hpp"
#include "../support/spin_until.hpp"

namespace radio_follow {
namespace {

using radio_follow::test::spinUntil;

using radio_follow::test::readLines;

/// Whether "start <text>" is in the log at or after line `from`.
bool saidSince(const std::string& log, const std::string& text, std::size_t from = 0) {
  const auto lines = readLines(log);
  return lines.size() > from && std::find(lines.begin() + static_cast<std::ptrdiff_t>(from),
                                          lines.end(), "start " + text) != lines.end();
}

TEST(AnnouncerFaults, SpeaksDeviceAndLocatorFaults) {
  ros::NodeHandle private_nh("~");
  std::string port;
  std::string log;
  ASSERT_TRUE(private_nh.getParam("port", port));
  ASSERT_TRUE(private_nh.getParam("log", log));

  test::FakeDwm1001 module;
  test::PtyDevice device(port, module.behaviour());

  // Nothing ever reaches the locator on aoa/front/bearing; the module's ranges have no
  // target anchor in the Spot layout, so the target stays lost.
  ASSERT_TRUE(spinUntil([&] { return saidSince(log, "Locator lost the target."); }, 30.0))
      << "log: " << readLines(log).size() << " lines";
  ASSERT_TRUE(
      spinUntil([&] { return saidSince(log, "Locator: no data from front bearing."); }, 30.0));

  // Let the start settle (the driver may have reported "not connected" before the test
  // created the device), then unplug.
  ros::WallDuration(3.0).sleep();
  const std::size_t before_unplug = readLines(log).size();
  EXPECT_FALSE(saidSince(log, "UWB module 5722 lost.", before_unplug));
  device.vanish();
  EXPECT_TRUE(
      spinUntil([&] { return saidSince(log, "UWB module 5722 lost.", before_unplug); }, 30.0));
  const std::size_t before_replug = readLines(log).size();
  ASSERT_TRUE(device.appear());
  EXPECT_TRUE(
      spinUntil([&] { return saidSince(log, "UWB module 5722 back.", before_replug); }, 30.0));
}

}  // namespace
}  // namespace radio_follow

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "announcer_faults_rostest");
  return RUN_ALL_TESTS();
}
