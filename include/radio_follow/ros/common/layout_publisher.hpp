// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <geometry_msgs/PolygonStamped.h>
#include <ros/ros.h>
#include <tf2_ros/static_transform_broadcaster.h>
#include <visualization_msgs/MarkerArray.h>

#include "radio_follow/common/param_table.hpp"
#include "radio_follow/config/layout.hpp"

namespace radio_follow {

/// Publishes the robot's sensor layout: one static TF per UWB module and AoA board
/// (fixed_frame -> sensor frame), and a latched MarkerArray `layout_markers` drawing
/// each sensor and its ID, so rviz and the drivers' frame_ids agree with the locator; and
/// the robot's outline (layoutFootprint: the sensors' hull plus `footprint_margin`) as a
/// latched PolygonStamped `footprint` and a `footprint` marker.
class LayoutPublisherNode {
 public:
  struct Params {
    /// Path of the layout YAML (required).
    std::string layout_file;
    /// Marker scale, metres.
    double marker_size = 0.08;
    /// Footprint margin around the sensors' convex hull, metres.
    double footprint_margin = 0.1;

    static const ParamTable<Params>& table();
    void validate() const;
  };

  LayoutPublisherNode(ros::NodeHandle& nh, ros::NodeHandle& private_nh);

 private:
  Params params_;
  Layout layout_;
  tf2_ros::StaticTransformBroadcaster static_tf_;
  ros::Publisher markers_pub_;
  ros::Publisher footprint_pub_;
};

/// The footprint as a message in the layout's fixed frame.
geometry_msgs::PolygonStamped footprintPolygon(const Layout& layout, double margin,
                                               const ros::Time& stamp);

/// Builds the layout's markers (pure function, unit-testable without a master).
visualization_msgs::MarkerArray layoutMarkers(const Layout& layout, double size,
                                              double footprint_margin, const ros::Time& stamp);

}  // namespace radio_follow
