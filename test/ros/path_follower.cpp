// SPDX-License-Identifier: BSD-3-Clause
// Feeds the running path_follower a person walking ahead and to the left (after half a
// second of a DEGRADED estimate behind the robot, as a cold start may give), checks the
// stored path (nav_msgs/Path in odom, from the estimates' own odometry-frame part, without
// the DEGRADED start), the forward command and status, then estimates tracked in another
// odometry frame and estimates without one for the straight fallback.
#include <gtest/gtest.h>
#include <nav_msgs/Path.h>
#include <ros/ros.h>
#include <tf2_ros/static_transform_broadcaster.h>

#include <atomic>
#include <mutex>
#include <string>

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

  /// The locator's odometry frame the estimates carry ("": none).
  void setOdomFrame(const std::string& frame) {
    std::lock_guard<std::mutex> lock(mutex_);
    odom_frame_ = frame;
  }
  std::atomic<double> range{3.0};

 private:
  void tick(const ros::TimerEvent&) {
    // The person walks from (2, 0) to (3, 1) and stays there.
    step_ = std::min(step_ + 1, 40);
    const double s = step_ / 40.0;
    radio_follow::TargetEstimate e;
    e.header.stamp = ros::Time::now();
    e.header.frame_id = "base_link";
    e.position.x = 2.0 + s;
    e.position.y = s;
    e.range = std::hypot(e.position.x, e.position.y);
    e.bearing = std::atan2(e.position.y, e.position.x);
    e.status = radio_follow::TargetEstimate::STATUS_OK;
    if (step_ <= 10) {
      // First a young track's wide cloud, DEGRADED and behind the robot: it must never
      // become a point of the path (control::TrackGate).
      e.position.x = -2.0;
      e.position.y = 0.5;
      e.range = std::hypot(e.position.x, e.position.y);
      e.bearing = std::atan2(e.position.y, e.position.x);
      e.status = radio_follow::TargetEstimate::STATUS_DEGRADED;
    }
    {
      // The robot stands at the odom origin (the static TF below): the estimate as it is.
      std::lock_guard<std::mutex> lock(mutex_);
      e.odom_frame = odom_frame_;
    }
    e.odom_position = e.position;
    e.odom_velocity.x = step_ < 40 ? 0.5 : 0.0;
    e.odom_velocity.y = step_ < 40 ? 0.5 : 0.0;
    estimate_pub_.publish(e);
    radio_follow::UwbRanges r;
    r.header.stamp = e.header.stamp;
    r.ranges.resize(1);
    r.ranges[0].anchor_id = "ABCD";
    r.ranges[0].range = range;
    range_pub_.publish(r);
  }

  std::mutex mutex_;
  std::string odom_frame_ = "odom";
  int step_ = 0;
  ros::Publisher estimate_pub_;
  ros::Publisher range_pub_;
  ros::Timer timer_;
};

TEST(PathFollower, StoresPathFollowsAndFallsBack) {
  ros::NodeHandle nh;
  radio_follow_test::ControllerRecorder rec(nh, "path_follower/status");
  std::mutex path_mutex;
  nav_msgs::Path last_path;
  ros::Subscriber path_sub = nh.subscribe<nav_msgs::Path>(
      "path_follower/path", 10, [&](const nav_msgs::Path::ConstPtr& msg) {
        std::lock_guard<std::mutex> lock(path_mutex);
        last_path = *msg;
      });
  tf2_ros::StaticTransformBroadcaster static_tf;
  geometry_msgs::TransformStamped odom_to_base;
  odom_to_base.header.stamp = ros::Time::now();
  odom_to_base.header.frame_id = "odom";
  odom_to_base.child_frame_id = "base_link";
  odom_to_base.transform.rotation.w = 1.0;
  static_tf.sendTransform(odom_to_base);
  Feeder feeder(nh);

  ASSERT_TRUE(waitFor([&] { return rec.lastStatus().text == "Following the path."; }, 20.0))
      << "last status: " << rec.lastStatus().text;
  ASSERT_TRUE(waitFor([&] { return rec.lastCmd().linear.x > 0.1; }, 10.0));
  EXPECT_GT(rec.lastCmd().angular.z, 0.0);  // the path bends to the left

  ASSERT_TRUE(waitFor(
      [&] {
        std::lock_guard<std::mutex> lock(path_mutex);
        return last_path.poses.size() >= 10;
      },
      10.0));
  {
    std::lock_guard<std::mutex> lock(path_mutex);
    EXPECT_EQ(last_path.header.frame_id, "odom");
    for (std::size_t i = 1; i < last_path.poses.size(); ++i) {
      const auto& a = last_path.poses[i - 1].pose.position;
      const auto& b = last_path.poses[i].pose.position;
      EXPECT_GE(std::hypot(b.x - a.x, b.y - a.y), 0.1 - 1e-9);
    }
    for (const auto& pose : last_path.poses) {
      EXPECT_GT(pose.pose.position.x, 1.5) << "the young track's DEGRADED estimate is on the path";
    }
  }

  // Too close on a raw range: zero at once.
  feeder.range = 0.9;
  ASSERT_TRUE(
      waitFor([&] { return rec.lastStatus().state == FollowerStatus::STATE_TOO_CLOSE; }, 5.0));
  ros::WallDuration(0.2).sleep();
  EXPECT_TRUE(isZero(rec.lastCmd()));
  feeder.range = 3.0;

  // Estimates tracked in another frame than the path's: straight-line fallback, said in
  // the status; back on the path with the path's frame again.
  const auto straight = [&] {
    return rec.lastStatus().text == "No odometry, driving straight to the target.";
  };
  feeder.setOdomFrame("map");
  ASSERT_TRUE(waitFor(straight, 10.0)) << "last status: " << rec.lastStatus().text;
  feeder.setOdomFrame("odom");
  ASSERT_TRUE(waitFor([&] { return rec.lastStatus().text == "Following the path."; }, 10.0))
      << "last status: " << rec.lastStatus().text;
  // The locator has no odometry (no odometry-frame part): the same fallback.
  feeder.setOdomFrame("");
  ASSERT_TRUE(waitFor(straight, 10.0)) << "last status: " << rec.lastStatus().text;
  EXPECT_TRUE(
      waitFor([&] { return rec.lastStatus().state == FollowerStatus::STATE_FOLLOWING; }, 2.0))
      << "status " << int(rec.lastStatus().state);  // announced once settled (kStatusSettleTime)
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "path_follower_rostest");
  ros::AsyncSpinner spinner(2);
  spinner.start();
  return RUN_ALL_TESTS();
}
