// SPDX-License-Identifier: BSD-3-Clause
// record.launch: the driver topics of any module or board are recorded, other topics not.
#include <gtest/gtest.h>
#include <ros/ros.h>
#include <rosbag/bag.h>
#include <rosbag/view.h>
#include <std_msgs/String.h>

#include <filesystem>
#include <set>
#include <string>

#include "radio_follow/AoaBearing.h"
#include "radio_follow/UwbRanges.h"

namespace fs = std::filesystem;

namespace {

/// Finished bags (rosbag renames <name>.bag.active to <name>.bag when it closes).
std::set<std::string> finishedBags(const fs::path& dir, const std::string& stem) {
  std::set<std::string> bags;
  if (fs::is_directory(dir)) {
    for (const auto& entry : fs::directory_iterator(dir)) {
      const std::string name = entry.path().filename().string();
      if (name.rfind(stem, 0) == 0 && entry.path().extension() == ".bag") {
        bags.insert(entry.path().string());
      }
    }
  }
  return bags;
}

TEST(Record, RecordsTheDriverTopicsAndNothingElse) {
  ros::NodeHandle nh;
  std::string prefix;
  ASSERT_TRUE(ros::param::get("~prefix", prefix));
  const fs::path dir = fs::path(prefix).parent_path();
  const std::string stem = fs::path(prefix).filename().string();
  const std::set<std::string> earlier = finishedBags(dir, stem);  // of earlier runs

  ros::Publisher ranges = nh.advertise<radio_follow::UwbRanges>("uwb/1A2B/ranges", 10);
  ros::Publisher bearing = nh.advertise<radio_follow::AoaBearing>("aoa/rear/bearing", 10);
  ros::Publisher other = nh.advertise<std_msgs::String>("chatter", 10);
  // Published until the recorder has stopped by itself (after its 4 s) and its bag is
  // finished, however late this node started next to it.
  std::string bag_path;
  const auto finished = [&] {
    for (const std::string& b : finishedBags(dir, stem)) {
      if (!earlier.count(b)) {
        bag_path = b;
      }
    }
    return !bag_path.empty();
  };
  ros::Rate rate(20.0);
  const ros::WallTime give_up = ros::WallTime::now() + ros::WallDuration(30.0);
  while (ros::ok() && !finished() && ros::WallTime::now() < give_up) {
    radio_follow::UwbRanges r;
    r.header.stamp = ros::Time::now();
    r.tag_id = "1A2B";
    ranges.publish(r);
    bearing.publish(radio_follow::AoaBearing());
    other.publish(std_msgs::String());
    rate.sleep();
  }
  ASSERT_FALSE(bag_path.empty()) << "no finished bag " << prefix << "_*.bag";

  rosbag::Bag bag(bag_path, rosbag::bagmode::Read);
  std::set<std::string> topics;
  std::size_t count = 0;
  for (const auto& m : rosbag::View(bag)) {
    topics.insert(m.getTopic());
    ++count;
  }
  EXPECT_TRUE(topics.count("/uwb/1A2B/ranges")) << count << " messages";
  EXPECT_TRUE(topics.count("/aoa/rear/bearing"));
  EXPECT_FALSE(topics.count("/chatter"));
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "record_rostest");
  return RUN_ALL_TESTS();
}
