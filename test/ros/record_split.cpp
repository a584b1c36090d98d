// SPDX-License-Identifier: BSD-3-Clause
// record.launch with split_duration and duration: the recording ends after `duration`
// (rosbag's own --duration would only be the split interval) and every split file
// starts with the latched /tf_static, so each replays on its own.
#include <gtest/gtest.h>
#include <ros/ros.h>
#include <rosbag/bag.h>
#include <rosbag/view.h>
#include <tf2_ros/static_transform_broadcaster.h>

#include <algorithm>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "../support/spin_until.hpp"
#include "radio_follow/UwbRanges.h"

namespace fs = std::filesystem;

namespace {

/// Bag files with this stem: finished (<name>.bag) or still open (<name>.bag.active).
std::set<std::string> bagsOf(const fs::path& dir, const std::string& stem, bool active) {
  std::set<std::string> bags;
  if (fs::is_directory(dir)) {
    for (const auto& entry : fs::directory_iterator(dir)) {
      const std::string name = entry.path().filename().string();
      const std::string ending = active ? ".bag.active" : ".bag";
      if (name.rfind(stem, 0) == 0 && name.size() > ending.size() &&
          name.compare(name.size() - ending.size(), ending.size(), ending) == 0) {
        bags.insert(entry.path().string());
      }
    }
  }
  return bags;
}

bool recorderRunning() {
  std::vector<std::string> nodes;
  ros::master::getNodes(nodes);
  return std::find(nodes.begin(), nodes.end(), "/record") != nodes.end();
}

TEST(RecordSplit, StopsAfterTheDurationAndEveryFileHasTfStatic) {
  ros::NodeHandle nh;
  std::string prefix;
  double duration = 0.0;
  ASSERT_TRUE(ros::param::get("~prefix", prefix));
  ASSERT_TRUE(ros::param::get("~duration", duration));
  const fs::path dir = fs::path(prefix).parent_path();
  const std::string stem = fs::path(prefix).filename().string();
  const std::set<std::string> earlier = bagsOf(dir, stem, false);  // of earlier runs

  // Sent once, latched (as layout_publisher does): only --repeat-latched puts it in the
  // later files.
  tf2_ros::StaticTransformBroadcaster static_tf;
  geometry_msgs::TransformStamped module;
  module.header.stamp = ros::Time::now();
  module.header.frame_id = "base_link";
  module.child_frame_id = "uwb_1A2B";
  module.transform.rotation.w = 1.0;
  static_tf.sendTransform(module);

  // Publish for well past the duration: the recording must end on its own.
  ros::Publisher ranges = nh.advertise<radio_follow::UwbRanges>("uwb/1A2B/ranges", 10);
  ros::Rate rate(20.0);
  const ros::WallTime until = ros::WallTime::now() + ros::WallDuration(duration + 5.0);
  while (ros::ok() && ros::WallTime::now() < until) {
    radio_follow::UwbRanges r;
    r.header.stamp = ros::Time::now();
    r.tag_id = "1A2B";
    ranges.publish(r);
    rate.sleep();
  }
  ASSERT_TRUE(radio_follow::test::spinUntil(
      [&] { return !recorderRunning() && bagsOf(dir, stem, true).empty(); }, 20.0))
      << "the recorder was still running " << duration + 5.0 << " s after it started";

  std::vector<std::string> bags;
  for (const std::string& b : bagsOf(dir, stem, false)) {
    if (!earlier.count(b)) {
      bags.push_back(b);
    }
  }
  ASSERT_GE(bags.size(), 3u) << "7 s split every 2 s";
  ros::Time first = ros::TIME_MAX;
  ros::Time last = ros::TIME_MIN;
  // The recorder's split clock starts with the recorder: the files it closed before this
  // node (started beside it, late on a loaded machine) published anything hold nothing
  // of it, and are not judged.
  bool started = false;
  std::size_t judged = 0;
  for (const std::string& path : bags) {
    rosbag::Bag bag(path, rosbag::bagmode::Read);
    std::size_t tf_static = 0;
    std::size_t range_messages = 0;
    for (const auto& m : rosbag::View(bag)) {
      tf_static += m.getTopic() == "/tf_static";
      if (m.getTopic() == "/uwb/1A2B/ranges") {
        ++range_messages;
        first = std::min(first, m.getTime());
        last = std::max(last, m.getTime());
      }
    }
    started = started || range_messages > 0;
    if (!started) {
      continue;
    }
    ++judged;
    EXPECT_GE(tf_static, 1u) << path << " has no /tf_static: it cannot be replayed alone";
    EXPECT_GT(range_messages, 0u) << path;
  }
  EXPECT_GE(judged, 2u) << "a split after the first file with ranges";
  // Ranges were published for duration + 5 s; the bags hold about `duration` of them.
  EXPECT_LT((last - first).toSec(), duration + 1.5);
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "record_split_rostest");
  ros::NodeHandle nh;  // keeps the node alive for the whole test
  return RUN_ALL_TESTS();
}
