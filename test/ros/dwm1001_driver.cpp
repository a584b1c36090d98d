// SPDX-License-Identifier: BSD-3-Clause
// The real dwm1001_driver node against a fake DWM1001 on a pseudo-terminal: shell
// dialogue, decoding, rejection of cut lines, and recovery after unplug/replug at the
// same symlink path without restarting the node.
#include "radio_follow/ros/drivers/dwm1001_driver.hpp"

#include <gtest/gtest.h>
#include <ros/ros.h>

#include <atomic>
#include <mutex>

#include "../support/expect_refused.hpp"
#include "../support/fake_dwm1001.hpp"
#include "../support/spin_until.hpp"
#include "radio_follow/UwbRanges.h"
#include "radio_follow/UwbTagLocation.h"
#include "radio_follow/common/param_error.hpp"

namespace radio_follow {
namespace {

using radio_follow::test::spinUntil;

struct Received {
  std::mutex mutex;
  UwbRanges last_ranges;
  UwbTagLocation last_location;
  int ranges = 0;
  int locations = 0;
};

TEST(Dwm1001DriverParams, Validation) {
  Dwm1001DriverNode::Params p;
  EXPECT_THROW(p.validate(), ParamError);  // no port
  p.port = "/dev/dwm1001_5722";
  EXPECT_NO_THROW(p.validate());
  auto invalid = [&p](auto change, const std::string& name) {
    radio_follow::test::expectRefused(p, change, name);
  };
  invalid([](auto& q) { q.output_mode = "lep"; }, "~output_mode");
  invalid([](auto& q) { q.baud = 0; }, "~baud");
  invalid([](auto& q) { q.configure = false; }, "~frame_id");  // no frame, no tag_id
  invalid([](auto& q) { q.reconnect_backoff = 0.0; }, "~reconnect_backoff");
  invalid([](auto& q) { q.silence_timeout = -1.0; }, "~silence_timeout");
  invalid([](auto& q) { q.shell_timeout = 0.0; }, "~shell_timeout");
  invalid([](auto& q) { q.max_line_length = 10; }, "~max_line_length");
  p.configure = false;
  p.tag_id = "5722";
  EXPECT_NO_THROW(p.validate());
}

TEST(Dwm1001Driver, ConfiguresDecodesAndRecoversFromReplug) {
  ros::NodeHandle nh;
  ros::NodeHandle private_nh("~");
  std::string port;
  ASSERT_TRUE(private_nh.getParam("port", port));

  Received rx;
  auto on_ranges = [&rx](const UwbRanges::ConstPtr& msg) {
    std::lock_guard<std::mutex> lock(rx.mutex);
    rx.last_ranges = *msg;
    ++rx.ranges;
  };
  auto on_location = [&rx](const UwbTagLocation::ConstPtr& msg) {
    std::lock_guard<std::mutex> lock(rx.mutex);
    rx.last_location = *msg;
    ++rx.locations;
  };
  ros::Subscriber s1 = nh.subscribe<UwbRanges>("uwb_front/ranges", 100, on_ranges);
  ros::Subscriber s2 = nh.subscribe<UwbTagLocation>("uwb_front/tag_location", 100, on_location);

  test::FakeDwm1001 module;
  test::PtyDevice device(port, module.behaviour());

  ASSERT_TRUE(spinUntil([&] { return rx.ranges >= 5 && rx.locations >= 5; }))
      << "device saw: " << device.received();
  {
    std::lock_guard<std::mutex> lock(rx.mutex);
    EXPECT_EQ(rx.last_ranges.tag_id, "5722");
    EXPECT_EQ(rx.last_ranges.header.frame_id, "uwb_5722");
    EXPECT_FALSE(rx.last_ranges.header.stamp.isZero());
    ASSERT_EQ(rx.last_ranges.ranges.size(), 4u);
    EXPECT_EQ(rx.last_ranges.ranges[1].anchor_id, "0CA8");
    EXPECT_DOUBLE_EQ(rx.last_ranges.ranges[1].range, 6.51);
    EXPECT_DOUBLE_EQ(rx.last_ranges.ranges[0].anchor_position.y, 8.0);
    EXPECT_EQ(rx.last_location.header.frame_id, "uwb_network");
    EXPECT_DOUBLE_EQ(rx.last_location.position.x, 2.57);
    EXPECT_EQ(rx.last_location.quality, 100);
  }
  const std::string dialogue = device.received();
  EXPECT_EQ(dialogue, "\r\rsi\rlec\r");

  // Unplug, stay away for a while, replug as a module that lost its configuration.
  device.vanish();
  module.powerCycle();
  ros::WallDuration(1.5).sleep();
  // Drain what is still queued on either connection (spinOnce takes one batch each). A
  // busy machine can hold one connection's messages for seconds (a loaded run saw 5
  // ranges vs 7 locations after 1 s), so this waits for the counts to meet, up to 20 s.
  spinUntil([&] {
    std::lock_guard<std::mutex> lock(rx.mutex);
    return rx.ranges == rx.locations;
  });
  int before;
  {
    std::lock_guard<std::mutex> lock(rx.mutex);
    // Every published ranges message is whole: the fake's cut lines never get through.
    // The two topics come over two connections, so the counts are compared here, with the
    // stream stopped, not while it runs (a loaded CI machine saw 7 ranges vs 5 locations).
    EXPECT_EQ(rx.ranges, rx.locations);
    before = rx.ranges;
  }
  ASSERT_TRUE(device.appear());
  const ros::WallTime replugged = ros::WallTime::now();
  ASSERT_TRUE(spinUntil([&] { return rx.ranges >= before + 3; }))
      << "no data after replug; device saw: " << device.received();
  // Reported, not asserted: the goal (< 2 s) is a performance figure, not a test.
  std::printf("dwm1001_driver: publishing again %.2f s after replug\n",
              (ros::WallTime::now() - replugged).toSec());
  // The dialogue ran again on the new PTY (received() accumulates over both).
  EXPECT_EQ(device.received(), dialogue + "\r\rsi\rlec\r");

  // The module resets while connected (brown-out): silent, back in its binary API.
  // After silence_timeout the driver runs the dialogue again on the open port.
  // Ranges still in flight from before the reset must not pass for new ones: the
  // dialogue first, then ranges counted from there.
  device.locked([&] { module.powerCycle(); });
  ASSERT_TRUE(spinUntil([&] { return device.received() == dialogue + dialogue + dialogue; }))
      << "the dialogue did not run again after the module's reset; device saw: "
      << device.received();
  {
    std::lock_guard<std::mutex> lock(rx.mutex);
    before = rx.ranges;
  }
  ASSERT_TRUE(spinUntil([&] { return rx.ranges >= before + 3; }))
      << "no data after module reset; device saw: " << device.received();
}

}  // namespace
}  // namespace radio_follow

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "dwm1001_driver_rostest");
  ros::NodeHandle nh;
  return RUN_ALL_TESTS();
}
