// SPDX-License-Identifier: BSD-3-Clause
// Publishes /clock (sim time at wall speed), a far target's estimates and ranges stamped
// with it, then sets the clock back by 60 s as a looped bag does. The controller must
// stop, then follow again on the new clock (before the fix it froze: every new stamp
// was older than the newest one it had kept).
#include <gtest/gtest.h>
#include <ros/ros.h>
#include <rosgraph_msgs/Clock.h>

#include <atomic>
#include <thread>

#include "controller_test_utils.hpp"
#include "radio_follow/TargetEstimate.h"
#include "radio_follow/UwbRanges.h"

namespace {

using radio_follow_test::isZero;
using radio_follow_test::waitFor;

class SimWorld {
 public:
  explicit SimWorld(ros::NodeHandle& nh)
      : clock_pub_(nh.advertise<rosgraph_msgs::Clock>("/clock", 10)),
        estimate_pub_(nh.advertise<radio_follow::TargetEstimate>("target", 10)),
        range_pub_(nh.advertise<radio_follow::UwbRanges>("uwb_ranges", 10)),
        thread_([this] { run(); }) {}
  ~SimWorld() {
    running_ = false;
    thread_.join();
  }
  void jumpBack(double seconds) { offset_ = offset_ - seconds; }

 private:
  void run() {
    const ros::WallTime start = ros::WallTime::now();
    int tick = 0;
    while (running_ && ros::ok()) {
      const double t = 100.0 + (ros::WallTime::now() - start).toSec() + offset_;
      rosgraph_msgs::Clock clock;
      clock.clock = ros::Time(t);
      clock_pub_.publish(clock);
      if (++tick % 5 == 0) {  // 20 Hz data, 100 Hz clock
        radio_follow::TargetEstimate e;
        e.header.stamp = clock.clock;
        e.header.frame_id = "base_link";
        e.position.x = 4.0;
        e.range = 4.0;
        e.status = radio_follow::TargetEstimate::STATUS_OK;
        estimate_pub_.publish(e);
        radio_follow::UwbRanges r;
        r.header.stamp = clock.clock;
        r.tag_id = "5722";
        r.ranges.resize(1);
        r.ranges[0].anchor_id = "ABCD";
        r.ranges[0].range = 4.0;
        range_pub_.publish(r);
      }
      ros::WallDuration(0.01).sleep();
    }
  }

  ros::Publisher clock_pub_;
  ros::Publisher estimate_pub_;
  ros::Publisher range_pub_;
  std::atomic<bool> running_{true};
  std::atomic<double> offset_{0.0};
  std::thread thread_;
};

TEST(ClockJump, StopsThenFollowsOnTheNewClock) {
  ros::NodeHandle nh;
  radio_follow_test::ControllerRecorder rec(nh, "velocity_controller/status");
  SimWorld world(nh);
  ASSERT_TRUE(waitFor([&] { return rec.lastCmd().linear.x > 0.3; }, 20.0))
      << "never drove toward the far target";
  world.jumpBack(60.0);
  ASSERT_TRUE(waitFor([&] { return isZero(rec.lastCmd()); }, 2.0))
      << "kept driving through a clock jump";
  EXPECT_TRUE(waitFor([&] { return rec.lastCmd().linear.x > 0.3; }, 10.0))
      << "frozen after the clock jump: never followed again; status '" << rec.lastStatus().text
      << "'";
}

}  // namespace

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "clock_jump_test");
  ros::AsyncSpinner spinner(2);
  spinner.start();
  return RUN_ALL_TESTS();
}
