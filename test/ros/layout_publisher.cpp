// SPDX-License-Identifier: BSD-3-Clause
// Checks the running layout_publisher node: the latched markers and the static TF
// of the Spot layout (config/layouts/spot.yaml).
#include <gtest/gtest.h>
#include <ros/ros.h>
#include <tf2_ros/transform_listener.h>
#include <visualization_msgs/MarkerArray.h>

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
