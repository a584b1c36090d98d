// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/ros/common/layout_publisher.hpp"

#include <geometry_msgs/TransformStamped.h>

#include <vector>

#include "radio_follow/common/param_error.hpp"
#include "radio_follow/ros/common/params.hpp"

namespace radio_follow {
namespace {

geometry_msgs::TransformStamped sensorTransform(const std::string& parent, const std::string& child,
                                                const Eigen::Vector3d& position,
                                                const Eigen::Quaterniond& orientation,
                                                const ros::Time& stamp) {
  geometry_msgs::TransformStamped t;
  t.header.stamp = stamp;
  t.header.frame_id = parent;
  t.child_frame_id = child;
  t.transform.translation.x = position.x();
  t.transform.translation.y = position.y();
  t.transform.translation.z = position.z();
  t.transform.rotation.x = orientation.x();
  t.transform.rotation.y = orientation.y();
  t.transform.rotation.z = orientation.z();
  t.transform.rotation.w = orientation.w();
  return t;
}

visualization_msgs::Marker baseMarker(const Layout& layout, const std::string& ns, int id,
                                      const ros::Time& stamp) {
  visualization_msgs::Marker m;
  m.header.frame_id = layout.fixed_frame;
  m.header.stamp = stamp;
  m.ns = ns;
  m.id = id;
  m.action = visualization_msgs::Marker::ADD;
  m.pose.orientation.w = 1.0;
  m.color.a = 1.0;
  // Latched once, in the robot's frame: without this rviz places the markers with the
  // transform of their arrival and leaves them behind when the robot drives off.
  m.frame_locked = true;
  return m;
}

void setPose(visualization_msgs::Marker& m, const Eigen::Vector3d& p, const Eigen::Quaterniond& q) {
  m.pose.position.x = p.x();
  m.pose.position.y = p.y();
  m.pose.position.z = p.z();
  m.pose.orientation.x = q.x();
  m.pose.orientation.y = q.y();
  m.pose.orientation.z = q.z();
  m.pose.orientation.w = q.w();
}

void addLabel(visualization_msgs::MarkerArray& array, const Layout& layout, int id,
              const Eigen::Vector3d& p, const std::string& text, double size,
              const ros::Time& stamp) {
  visualization_msgs::Marker label = baseMarker(layout, "sensor_labels", id, stamp);
  label.type = visualization_msgs::Marker::TEXT_VIEW_FACING;
  setPose(label, p + Eigen::Vector3d(0, 0, 1.5 * size), Eigen::Quaterniond::Identity());
  label.scale.z = size;
  label.color.r = label.color.g = label.color.b = 1.0;
  label.text = text;
  array.markers.push_back(label);
}

}  // namespace

const ParamTable<LayoutPublisherNode::Params>& LayoutPublisherNode::Params::table() {
  using P = LayoutPublisherNode::Params;
  static const ParamTable<P> t =
      ParamTable<P>()
          .add("layout_file", &P::layout_file, "", "Path of the layout YAML (required).")
          .add("marker_size", &P::marker_size, "m", "Marker size.", Range::open(0.0, 10.0))
          .add("footprint_margin", &P::footprint_margin, "m",
               "Footprint margin around the sensors' convex hull.", Range::closed(0.0, 5.0));
  return t;
}

void LayoutPublisherNode::Params::validate() const {
  require(!layout_file.empty(), "~layout_file", layout_file, "the path of a layout YAML file");
  table().check(*this);
}

geometry_msgs::PolygonStamped footprintPolygon(const Layout& layout, double margin,
                                               const ros::Time& stamp) {
  geometry_msgs::PolygonStamped polygon;
  polygon.header.frame_id = layout.fixed_frame;
  polygon.header.stamp = stamp;
  for (const Eigen::Vector2d& p : layoutFootprint(layout, margin)) {
    geometry_msgs::Point32 q;
    q.x = static_cast<float>(p.x());
    q.y = static_cast<float>(p.y());
    polygon.polygon.points.push_back(q);
  }
  return polygon;
}

visualization_msgs::MarkerArray layoutMarkers(const Layout& layout, double size,
                                              double footprint_margin, const ros::Time& stamp) {
  visualization_msgs::MarkerArray array;
  // The outline first, on the ground, closed; frame_locked like the sensors (a latched
  // PolygonStamped would stay where the robot started in a fixed frame such as odom).
  visualization_msgs::Marker outline = baseMarker(layout, "footprint", 0, stamp);
  outline.type = visualization_msgs::Marker::LINE_STRIP;
  outline.scale.x = 0.2 * size;
  outline.color.r = outline.color.g = outline.color.b = 0.9;
  const std::vector<Eigen::Vector2d> hull = layoutFootprint(layout, footprint_margin);
  for (std::size_t i = 0; i <= hull.size() && !hull.empty(); ++i) {
    geometry_msgs::Point p;
    p.x = hull[i % hull.size()].x();
    p.y = hull[i % hull.size()].y();
    outline.points.push_back(p);
  }
  array.markers.push_back(outline);
  int id = 0;
  for (const auto& module : layout.twr_modules) {
    visualization_msgs::Marker m = baseMarker(layout, "twr_modules", id, stamp);
    m.type = visualization_msgs::Marker::SPHERE;
    setPose(m, module.position, Eigen::Quaterniond::Identity());
    m.scale.x = m.scale.y = m.scale.z = size;
    m.color.r = 0.1;
    m.color.g = 0.5;
    m.color.b = 1.0;
    array.markers.push_back(m);
    addLabel(array, layout, id++, module.position, "UWB " + module.id, size, stamp);
  }
  for (const auto& board : layout.aoa_boards) {
    visualization_msgs::Marker m = baseMarker(layout, "aoa_boards", id, stamp);
    m.type = visualization_msgs::Marker::ARROW;  // points along the boresight (board x)
    setPose(m, board.position, board.orientation);
    m.scale.x = 2.0 * size;
    m.scale.y = m.scale.z = 0.4 * size;
    m.color.r = 1.0;
    m.color.g = 0.6;
    m.color.b = 0.0;
    array.markers.push_back(m);
    addLabel(array, layout, id++, board.position, "AoA " + board.id, size, stamp);
  }
  for (const auto& anchor : layout.tdoa_anchors) {
    visualization_msgs::Marker m = baseMarker(layout, "tdoa_anchors", id, stamp);
    m.type = visualization_msgs::Marker::CUBE;
    setPose(m, anchor.position, Eigen::Quaterniond::Identity());
    m.scale.x = m.scale.y = m.scale.z = size;
    m.color.r = 0.2;
    m.color.g = 0.9;
    m.color.b = 0.3;
    array.markers.push_back(m);
    addLabel(array, layout, id++, anchor.position, "TDoA " + anchor.id, size, stamp);
  }
  return array;
}

LayoutPublisherNode::LayoutPublisherNode(ros::NodeHandle& nh, ros::NodeHandle& private_nh) {
  const ParamReader reader(private_nh);
  Params::table().load(reader, params_);
  reader.requireAllKnown();
  params_.validate();
  layout_ = loadLayoutFile(params_.layout_file);

  const ros::Time now = ros::Time::now();
  std::vector<geometry_msgs::TransformStamped> transforms;
  for (const auto& module : layout_.twr_modules) {
    transforms.push_back(sensorTransform(layout_.fixed_frame, module.frame_id, module.position,
                                         Eigen::Quaterniond::Identity(), now));
  }
  for (const auto& board : layout_.aoa_boards) {
    transforms.push_back(sensorTransform(layout_.fixed_frame, board.frame_id, board.position,
                                         board.orientation, now));
  }
  static_tf_.sendTransform(transforms);

  markers_pub_ = nh.advertise<visualization_msgs::MarkerArray>("layout_markers", 1, true);
  markers_pub_.publish(layoutMarkers(layout_, params_.marker_size, params_.footprint_margin, now));
  footprint_pub_ = nh.advertise<geometry_msgs::PolygonStamped>("footprint", 1, true);
  footprint_pub_.publish(footprintPolygon(layout_, params_.footprint_margin, now));
  ROS_INFO("layout_publisher: %zu UWB modules, %zu AoA boards, %zu TDoA anchors from %s",
           layout_.twr_modules.size(), layout_.aoa_boards.size(), layout_.tdoa_anchors.size(),
           params_.layout_file.c_str());
}

}  // namespace radio_follow
