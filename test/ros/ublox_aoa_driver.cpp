// SPDX-License-Identifier: BSD-3-Clause
// The real ublox_aoa_driver node against a fake u-connectLocate board on a
// pseudo-terminal: init commands, tag filtering, azimuth sign, rejection of cut lines,
// and recovery after unplug/replug at the same symlink path.
#include "radio_follow/ros/drivers/ublox_aoa_driver.hpp"

#include <gtest/gtest.h>
#include <ros/ros.h>

#include <cmath>
#include <memory>
#include <mutex>
#include <set>

#include "../support/expect_refused.hpp"
#include "../support/pty_device.hpp"
#include "../support/spin_until.hpp"
#include "radio_follow/AoaBearing.h"
#include "radio_follow/common/param_error.hpp"

namespace radio_follow {
namespace {

using radio_follow::test::spinUntil;

// Streams events of an accepted and an unknown tag, advertising data, an echo and a
// cut event, as a board with two tags in range on a noisy cable would.
test::PtyDevice::Behaviour boardBehaviour() {
  test::PtyDevice::Behaviour b;
  b.on_input = [](const std::string& input) { return input + "\r\nOK\r\n"; };
  auto count = std::make_shared<unsigned>(0);
  b.periodic = [count] {
    ++*count;
    switch (*count % 5) {
      case 0:
        return std::string(
            "+UUDF:CCF9578E0D8A,-42,20,-10,-43,37,\"CCF9578E0D89\",\",\",15869,23\r\n");
      case 1:
        return std::string(
            "+UUDF:0123456789AB,-60,-30,5,-61,38,\"CCF9578E0D89\",\"\",15870,24\r\n");
      case 2:
        return std::string("+UUDFP:CCF9578E0D8A,\"0201060303AAFE\"\r\n");
      case 3:
        return std::string("+UUDF:CCF9578E0D8A,-42,20,-10,-4\r\n");  // cut
      default:
        return std::string("\r\n");
    }
  };
  b.period = std::chrono::milliseconds(10);
  return b;
}

TEST(UbloxAoaDriverParams, Validation) {
  UbloxAoaDriverNode::Params p;
  EXPECT_THROW(p.validate(), ParamError);  // no port, no frame
  p.port = "/dev/aoa_front";
  p.frame_id = "aoa_front";
  p.tag_ids = {"CCF9578E0D8A"};
  p.init_commands = {"AT+UDFENABLE=1"};
  EXPECT_NO_THROW(p.validate());
  auto invalid = [&p](auto change, const std::string& name) {
    radio_follow::test::expectRefused(p, change, name);
  };
  invalid([](auto& q) { q.frame_id.clear(); }, "~frame_id");
  invalid([](auto& q) { q.tag_ids = {"CCF9578E0D8"}; }, "~tag_ids");
  invalid([](auto& q) { q.tag_ids = {"CCF9578E0D8G"}; }, "~tag_ids");
  invalid([](auto& q) { q.init_commands = {"AT\r"}; }, "~init_commands");
  invalid([](auto& q) { q.init_commands = {""}; }, "~init_commands");
  invalid([](auto& q) { q.reconnect_backoff = 11.0; }, "~reconnect_backoff");
  invalid([](auto& q) { q.baud = -1; }, "~baud");
}

TEST(UbloxAoaDriver, FiltersConvertsAndRecoversFromReplug) {
  ros::NodeHandle nh;
  ros::NodeHandle private_nh("~");
  std::string port;
  ASSERT_TRUE(private_nh.getParam("port", port));

  std::mutex mutex;
  std::set<std::string> tags;
  AoaBearing last;
  int count = 0;
  ros::Subscriber sub =
      nh.subscribe<AoaBearing>("aoa_front/bearing", 100, [&](const AoaBearing::ConstPtr& msg) {
        std::lock_guard<std::mutex> lock(mutex);
        tags.insert(msg->tag_id);
        last = *msg;
        ++count;
      });

  test::PtyDevice device(port, boardBehaviour());
  ASSERT_TRUE(spinUntil([&] { return count >= 10; }));
  {
    std::lock_guard<std::mutex> lock(mutex);
    EXPECT_EQ(tags, std::set<std::string>{"CCF9578E0D8A"});
    EXPECT_EQ(last.header.frame_id, "aoa_front");
    EXPECT_NEAR(last.azimuth, -20.0 * M_PI / 180.0, 1e-12);  // inverted: counter-clockwise
    EXPECT_NEAR(last.elevation, -10.0 * M_PI / 180.0, 1e-12);
    EXPECT_EQ(last.anchor_id, "CCF9578E0D89");
    EXPECT_DOUBLE_EQ(last.rssi, -42.0);
    EXPECT_DOUBLE_EQ(last.rssi_second, -43.0);
    EXPECT_EQ(last.channel, 37);
    EXPECT_EQ(last.device_timestamp_ms, 15869u);
    EXPECT_EQ(last.event_counter, 23);
  }
  EXPECT_EQ(device.received(), "AT+UDFENABLE=1\r");

  device.vanish();
  ros::WallDuration(1.5).sleep();
  ros::spinOnce();
  int before;
  {
    std::lock_guard<std::mutex> lock(mutex);
    before = count;
  }
  ASSERT_TRUE(device.appear());
  const ros::WallTime replugged = ros::WallTime::now();
  ASSERT_TRUE(spinUntil([&] { return count >= before + 5; }));
  std::printf("ublox_aoa_driver: publishing again %.2f s after replug\n",
              (ros::WallTime::now() - replugged).toSec());
  EXPECT_EQ(device.received(), "AT+UDFENABLE=1\rAT+UDFENABLE=1\r");  // sent on each connect
}

}  // namespace
}  // namespace radio_follow

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "ublox_aoa_driver_rostest");
  ros::NodeHandle nh;
  return RUN_ALL_TESTS();
}
