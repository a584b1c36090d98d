// SPDX-License-Identifier: BSD-3-Clause
// Drives the running velocity_controller through enable -> follow -> too close ->
// resume -> target lost -> disable, checking cmd_vel and status at each step.
#include <gtest/gtest.h>
#include <ros/ros.h>
#include <std_msgs/Bool.h>
#include <std_srvs/SetBool.h>

#include <atomic>
#include <mutex>

#include "controller_test_utils.hpp"
#include "radio_follow/TargetEstimate.h"
#include "radio_follow/UwbRanges.h"

namespace {

using radio_follow::FollowerStatus;
using radio_follow_test::isZero;
using radio_follow_test::waitFor;

class Feeder {
 public:
  explicit Feeder(ros::NodeHandle& nh)
      : estimate_pub_(nh.advertise<radio_follow::TargetEstimate>("target", 10)),
        range_pub_(nh.advertise<radio_follow::UwbRanges>("uwb_ranges", 10)),
        timer_(nh.createTimer(ros::Duration(0.05), &Feeder::tick, this)) {}
  /// The spinner threads keep running after a failed ASSERT returns: stop the ticks
  /// first, so a failure is reported instead of a publish on a destroyed publisher.
  ~Feeder() {
    const std::lock_guard<std::mutex> lock(mutex_);
    stopped_ = true;
    timer_.stop();
  }
  Feeder(const Feeder&) = delete;
  Feeder& operator=(const Feeder&) = delete;

  std::atomic<double> range{4.0};
  std::atomic<bool> send_estimates{true};
  std::atomic<bool> send_ranges{true};

 private:
  void tick(const ros::TimerEvent&) {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (stopped_) {
      return;
    }
    const ros::Time now = ros::Time::now();
    if (send_estimates) {
      radio_follow::TargetEstimate e;
      e.header.stamp = now;
      e.header.frame_id = "base_link";
      e.position.x = 4.0;
      e.range = 4.0;  // the estimate always claims the target is far away
      e.bearing = 0.0;
      e.status = radio_follow::TargetEstimate::STATUS_OK;
      estimate_pub_.publish(e);
    }
    if (send_ranges) {
      radio_follow::UwbRanges r;
      r.header.stamp = now;
      r.tag_id = "5722";
      r.ranges.resize(2);
      r.ranges[0].anchor_id = "ABCD";
      r.ranges[0].range = range;
      r.ranges[1].anchor_id = "FFFF";  // another anchor: must be ignored
      r.ranges[1].range = 0.2;
      range_pub_.publish(r);
    }
  }

  std::mutex mutex_;
  bool stopped_ = false;
  ros::Publisher estimate_pub_;
  ros::Publisher range_pub_;
  ros::Timer timer_;
};

TEST(VelocityController, SafetyLayerAroundFollowing) {
  ros::NodeHandle nh;
  radio_follow_test::ControllerRecorder rec(nh, "velocity_controller/status");
  Feeder feeder(nh);

  ASSERT_TRUE(waitFor([&] { return rec.hasStatus() && rec.cmdCount() > 0; }, 20.0));
  EXPECT_TRUE(
      waitFor([&] { return rec.lastStatus().state == FollowerStatus::STATE_DISABLED; }, 2.0))
      << "status " << int(rec.lastStatus().state);  // announced once settled (kStatusSettleTime)
  EXPECT_TRUE(isZero(rec.lastCmd()));

  ros::ServiceClient enable =
      nh.serviceClient<std_srvs::SetBool>("velocity_controller/set_enabled");
  ASSERT_TRUE(enable.waitForExistence(ros::Duration(20.0)));
  std_srvs::SetBool srv;
  srv.request.data = true;
  ASSERT_TRUE(enable.call(srv));
  EXPECT_TRUE(srv.response.success);

  ASSERT_TRUE(waitFor([&] { return rec.lastCmd().linear.x > 0.2; }, 10.0))
      << "no forward command while enabled with a far target";
  EXPECT_TRUE(
      waitFor([&] { return rec.lastStatus().state == FollowerStatus::STATE_FOLLOWING; }, 2.0))
      << "status " << int(rec.lastStatus().state);  // announced once settled (kStatusSettleTime)
  // Acceleration limit: the speed builds up gradually, never a jump to the maximum.
  EXPECT_LE(rec.cmdsSince(0).front().linear.x, 0.1);

  // A raw range below safe_distance stops the robot although the estimate says 4 m.
  feeder.range = 1.0;
  ASSERT_TRUE(
      waitFor([&] { return rec.lastStatus().state == FollowerStatus::STATE_TOO_CLOSE; }, 5.0));
  EXPECT_EQ(rec.lastStatus().text, "Too close, stopping.");
  ros::WallDuration(0.1).sleep();
  const int mark = rec.cmdCount();
  ros::WallDuration(0.5).sleep();
  const auto while_close = rec.cmdsSince(mark);
  ASSERT_FALSE(while_close.empty());
  for (const auto& cmd : while_close) {
    EXPECT_TRUE(isZero(cmd));
  }

  feeder.range = 4.0;
  ASSERT_TRUE(waitFor([&] { return rec.lastCmd().linear.x > 0.05; }, 10.0));
  EXPECT_TRUE(
      waitFor([&] { return rec.lastStatus().state == FollowerStatus::STATE_FOLLOWING; }, 2.0))
      << "status " << int(rec.lastStatus().state);  // announced once settled (kStatusSettleTime)

  // No estimates: stale -> target lost, zero.
  feeder.send_estimates = false;
  ASSERT_TRUE(
      waitFor([&] { return rec.lastStatus().state == FollowerStatus::STATE_TARGET_LOST; }, 5.0));
  ros::WallDuration(0.2).sleep();
  EXPECT_TRUE(isZero(rec.lastCmd()));

  // Disable through the topic (a physical button).
  feeder.send_estimates = true;
  ros::Publisher enable_topic = nh.advertise<std_msgs::Bool>("velocity_controller/enable", 1, true);
  std_msgs::Bool off;
  off.data = false;
  enable_topic.publish(off);
  ASSERT_TRUE(
      waitFor([&] { return rec.lastStatus().state == FollowerStatus::STATE_DISABLED; }, 5.0));
  ros::WallDuration(0.2).sleep();
  EXPECT_TRUE(isZero(rec.lastCmd()));
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "velocity_controller_rostest");
  ros::AsyncSpinner spinner(2);
  spinner.start();
  return RUN_ALL_TESTS();
}
