// SPDX-License-Identifier: BSD-3-Clause
// Checks the running layout_publisher node: the latched markers and the static TF
// of the Spot layout (config/layouts/spot.yaml), and the robot's footprint.
#include <geometry_msgs/PolygonStamped.h>
#include <gtest/gtest.h>
#include <ros/ros.h>
#include <tf2_ros/transform_listener.h>
#include <visualization_msgs/MarkerArray.h>

#include <algorithm>
#include <cmath>

namespace {

TEST(LayoutPublisher, PublishesLatchedSensorMarkers) {
  ros::NodeHandle nh;
  visualization_msgs::MarkerArrayConstPtr markers =
      ros::topic::waitForMessage<visualization_msgs::MarkerArray>("layout_markers", nh,
                                                                  ros::Duration(20.0));
  ASSERT_TRUE(markers) << "no layout_markers within 20 s";
  int spheres = 0;
  int arrows = 0;
  for (const auto& m : markers->markers) {
    EXPECT_EQ(m.header.frame_id, "base_link");
    EXPECT_TRUE(m.frame_locked) << m.ns;  // rviz moves them with the robot
    spheres += m.type == visualization_msgs::Marker::SPHERE;
    arrows += m.type == visualization_msgs::Marker::ARROW;
  }
  EXPECT_EQ(spheres, 3);  // three TWR modules
  EXPECT_EQ(arrows, 4);   // four AoA boards
}

TEST(LayoutPublisher, PublishesTheFootprintAroundEverySensor) {
  ros::NodeHandle nh;
  const auto polygon = ros::topic::waitForMessage<geometry_msgs::PolygonStamped>(
      "footprint", nh, ros::Duration(20.0));
  ASSERT_TRUE(polygon) << "no footprint within 20 s";
  EXPECT_EQ(polygon->header.frame_id, "base_link");
  ASSERT_GE(polygon->polygon.points.size(), 3u);
  // The Spot layout spans x in [-0.30, 0.175], y in [-0.065, 0.08]; margin 0.1 m.
  double min_x = 1e9, max_x = -1e9, min_y = 1e9, max_y = -1e9;
  for (const auto& p : polygon->polygon.points) {
    min_x = std::min(min_x, double(p.x));
    max_x = std::max(max_x, double(p.x));
    min_y = std::min(min_y, double(p.y));
    max_y = std::max(max_y, double(p.y));
  }
  EXPECT_NEAR(min_x, -0.40, 0.01);
  EXPECT_NEAR(max_x, 0.275, 0.01);
  EXPECT_NEAR(min_y, -0.165, 0.01);
  EXPECT_NEAR(max_y, 0.18, 0.01);

  // The same outline is a closed, frame-locked line in the markers.
  const auto markers = ros::topic::waitForMessage<visualization_msgs::MarkerArray>(
      "layout_markers", nh, ros::Duration(5.0));
  ASSERT_TRUE(markers);
  int outlines = 0;
  for (const auto& m : markers->markers) {
    if (m.ns != "footprint") {
      continue;
    }
    ++outlines;
    EXPECT_EQ(m.type, visualization_msgs::Marker::LINE_STRIP);
    ASSERT_EQ(m.points.size(), polygon->polygon.points.size() + 1);
    EXPECT_EQ(m.points.front().x, m.points.back().x);
  }
  EXPECT_EQ(outlines, 1);
}

TEST(LayoutPublisher, PublishesStaticSensorFrames) {
  tf2_ros::Buffer buffer;
  tf2_ros::TransformListener listener(buffer);
  std::string error;
  ASSERT_TRUE(
      buffer.canTransform("base_link", "uwb_5A84", ros::Time(0), ros::Duration(20.0), &error))
      << error;
  const auto module = buffer.lookupTransform("base_link", "uwb_5A84", ros::Time(0));
  EXPECT_NEAR(module.transform.translation.x, -0.07, 1e-9);
  EXPECT_NEAR(module.transform.translation.z, 0.093, 1e-9);

  // The left board's boresight (x) points along base_link's +y: yaw 90 deg.
  const auto board = buffer.lookupTransform("base_link", "aoa_left", ros::Time(0));
  const double yaw = 2.0 * std::atan2(board.transform.rotation.z, board.transform.rotation.w);
  EXPECT_NEAR(yaw, M_PI / 2.0, 1e-9);
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "layout_publisher_rostest");
  ros::AsyncSpinner spinner(1);
  spinner.start();
  return RUN_ALL_TESTS();
}
