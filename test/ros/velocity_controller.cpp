// SPDX-License-Identifier: BSD-3-Clause
// Drives the running velocity_controller through enable -> follow -> too close ->
// resume -> target lost -> disable, checking cmd_vel and status at each step; then the
// speed feed-forward from the estimate's own odometry-frame velocity (no TF runs here).
#include <gtest/gtest.h>
#include <ros/ros.h>
#include <std_msgs/Bool.h>
#include <std_srvs/SetBool.h>

#include <atomic>
#include <cmath>
#include <limits>
#include <mutex>
#include <numeric>
#include <vector>

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
  /// Where the estimate puts the target, m ahead.
  std::atomic<double> estimate_range{4.0};
  /// The estimate's odometry-frame part: the person walks straight away at this speed
  /// (m/s); NaN: the locator has no ground velocity yet.
  std::atomic<bool> with_odometry{false};
  std::atomic<double> walking_speed{0.0};
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
      e.position.x = estimate_range;
      e.range = estimate_range;  // far away, unless a test moves it
      e.bearing = 0.0;
      e.status = radio_follow::TargetEstimate::STATUS_OK;
      if (with_odometry) {
        e.odom_frame = "odom";
        e.odom_robot.x = 10.0;  // odom is base_link shifted by 10 m
        e.odom_position.x = 10.0 + estimate_range;
        e.odom_velocity.x = walking_speed;
      }
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

// The person is 0.1 m beyond the follow distance and walks away: the feed-forward is the
// locator's ground velocity as the estimate carries it. Without one (NaN: not known yet)
// there is none, and nothing non-finite reaches cmd_vel.
TEST(VelocityController, FeedForwardIsTheEstimatesGroundVelocity) {
  ros::NodeHandle nh;
  radio_follow_test::ControllerRecorder rec(nh, "velocity_controller/status");
  Feeder feeder(nh);
  ros::ServiceClient enable =
      nh.serviceClient<std_srvs::SetBool>("velocity_controller/set_enabled");
  ASSERT_TRUE(enable.waitForExistence(ros::Duration(10.0)));
  std_srvs::SetBool on;
  on.request.data = true;
  ASSERT_TRUE(enable.call(on));
  feeder.estimate_range = 1.7;  // follow_distance 1.6
  feeder.with_odometry = true;
  // The mean forward command of the last half second (10 ticks at 20 Hz); NaN until
  // there are that many. The test waits for each state rather than timing a window: a
  // loaded machine delays the ticks, not what they converge to.
  const auto recent_linear = [&] {
    const auto cmds = rec.cmdsSince(0);
    constexpr std::size_t kTicks = 10;
    if (cmds.size() < kTicks) {
      return std::numeric_limits<double>::quiet_NaN();
    }
    double sum = 0.0;
    for (std::size_t i = cmds.size() - kTicks; i < cmds.size(); ++i) {
      sum += cmds[i].linear.x;
    }
    return sum / kTicks;
  };
  feeder.walking_speed = 0.0;
  EXPECT_TRUE(waitFor([&] { return recent_linear() < 0.3; }, 10.0))
      << "standing: " << recent_linear();
  feeder.walking_speed = 0.8;
  EXPECT_TRUE(waitFor([&] { return recent_linear() > 0.7; }, 10.0))
      << "walking: " << recent_linear();
  feeder.walking_speed = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE(waitFor([&] { return recent_linear() < 0.3; }, 10.0))
      << "unknown velocity: " << recent_linear();
  for (const auto& c : rec.cmdsSince(0)) {
    EXPECT_TRUE(std::isfinite(c.linear.x) && std::isfinite(c.angular.z));
  }
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "velocity_controller_rostest");
  ros::AsyncSpinner spinner(2);
  spinner.start();
  return RUN_ALL_TESTS();
}
