// SPDX-License-Identifier: BSD-3-Clause
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

#include "radio_follow/estimation/initializer.hpp"
#include "radio_follow/ros/locator/locator_node.hpp"

namespace radio_follow {
namespace {

constexpr int kCirclePoints = 48;
constexpr double kEstimateSize = 0.06;  // diameter of the estimate's sphere, m

visualization_msgs::Marker marker(const Layout& layout, const std::string& ns, int id, int type,
                                  const ros::Time& stamp) {
  visualization_msgs::Marker m;
  m.header.frame_id = layout.fixed_frame;
  m.header.stamp = stamp;
  m.ns = ns;
  m.id = id;
  m.type = type;
  m.action = visualization_msgs::Marker::ADD;
  m.pose.orientation.w = 1.0;
  return m;
}

geometry_msgs::Point point(const Eigen::Vector3d& p) {
  geometry_msgs::Point out;
  out.x = p.x();
  out.y = p.y();
  out.z = p.z();
  return out;
}

void color(visualization_msgs::Marker& m, float r, float g, float b, float a) {
  m.color.r = r;
  m.color.g = g;
  m.color.b = b;
  m.color.a = a;
}

}  // namespace

visualization_msgs::MarkerArray locatorMarkers(const Layout& layout,
                                               const estimation::LocatorConfig& config,
                                               const estimation::LocatorEstimate& estimate,
                                               const ros::Time& stamp) {
  visualization_msgs::MarkerArray array;
  // Sensors come and go between epochs: start from a clean slate every time.
  visualization_msgs::Marker clear = marker(layout, "", 0, 0, stamp);
  clear.action = visualization_msgs::Marker::DELETEALL;
  array.markers.push_back(clear);

  for (std::size_t k = 0; k < estimate.ranges_used.size(); ++k) {
    const TwrModule& module = layout.twr_modules[estimate.ranges_used[k]];
    const double range = estimate.ranges_m[k];
    const int id = static_cast<int>(k);
    if (config.planar) {
      // Where the range sphere meets the target plane.
      const double dz = config.height - module.position.z();
      const double radius = std::sqrt(std::max(0.0, range * range - dz * dz));
      auto m = marker(layout, "ranges", id, visualization_msgs::Marker::LINE_STRIP, stamp);
      m.scale.x = 0.02;
      for (int i = 0; i <= kCirclePoints; ++i) {
        const double a = 2.0 * kPi * i / kCirclePoints;
        m.points.push_back(
            point(Eigen::Vector3d(module.position.x() + radius * std::cos(a),
                                  module.position.y() + radius * std::sin(a), config.height)));
      }
      color(m, 0.1f, 0.5f, 1.0f, 0.8f);
      array.markers.push_back(m);
    } else {
      auto m = marker(layout, "ranges", id, visualization_msgs::Marker::SPHERE, stamp);
      m.pose.position = point(module.position);
      m.scale.x = m.scale.y = m.scale.z = 2.0 * range;
      color(m, 0.1f, 0.5f, 1.0f, 0.15f);
      array.markers.push_back(m);
    }
  }

  const double arrow_length = estimate.status == TargetStatus::kLost
                                  ? config.default_range
                                  : std::max(0.5, estimate.position.head<2>().norm());
  for (std::size_t k = 0; k < estimate.bearings_fresh.size(); ++k) {
    const std::size_t index = estimate.bearings_fresh[k];
    const AoaBoard& board = layout.aoa_boards[index];
    estimation::BearingObservation z;
    z.board = board.position;
    z.rotation = board.orientation.toRotationMatrix();
    z.azimuth = estimate.bearing_angles[k](0);
    z.elevation = estimate.bearing_angles[k](1);
    z.use_elevation = config.use_elevation;
    auto m =
        marker(layout, "bearings", static_cast<int>(k), visualization_msgs::Marker::ARROW, stamp);
    m.points.push_back(point(board.position));
    m.points.push_back(point(board.position + arrow_length * bearingDirection(z)));
    m.scale.x = 0.03;
    m.scale.y = 0.08;
    m.scale.z = 0.1;
    const bool used = std::find(estimate.bearings_used.begin(), estimate.bearings_used.end(),
                                index) != estimate.bearings_used.end();
    if (used) {
      color(m, 0.1f, 0.9f, 0.2f, 1.0f);
    } else {
      color(m, 0.6f, 0.6f, 0.6f, 0.5f);
    }
    array.markers.push_back(m);
  }

  if (estimate.status == TargetStatus::kLost) {
    return array;
  }
  // Small, so that the covariance ring around it stays visible from above.
  auto target = marker(layout, "estimate", 0, visualization_msgs::Marker::SPHERE, stamp);
  target.pose.position = point(estimate.position);
  target.scale.x = target.scale.y = target.scale.z = kEstimateSize;
  if (estimate.status == TargetStatus::kOk) {
    color(target, 1.0f, 0.2f, 0.2f, 1.0f);
  } else {
    color(target, 1.0f, 0.8f, 0.1f, 1.0f);  // heading only or degraded
  }
  array.markers.push_back(target);

  // 2-sigma ellipse of the xy position, a flat ring drawn just above the estimate's
  // sphere: a filled ellipsoid hid under the sphere whenever sigma < its radius.
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig2(
      estimate.covariance.topLeftCorner<2, 2>());
  const Eigen::Vector2d sigma2 = eig2.eigenvalues().cwiseMax(0.0).cwiseSqrt();
  auto ring = marker(layout, "covariance", 0, visualization_msgs::Marker::LINE_STRIP, stamp);
  ring.scale.x = 0.015;  // line width, m
  const double z = estimate.position.z() + kEstimateSize;
  for (int i = 0; i <= kCirclePoints; ++i) {
    const double a = 2.0 * kPi * i / kCirclePoints;
    const Eigen::Vector2d p = estimate.position.head<2>() +
                              eig2.eigenvectors() * Eigen::Vector2d(2.0 * sigma2(0) * std::cos(a),
                                                                    2.0 * sigma2(1) * std::sin(a));
    ring.points.push_back(point(Eigen::Vector3d(p.x(), p.y(), z)));
  }
  color(ring, 1.0f, 0.4f, 0.9f, 1.0f);
  array.markers.push_back(ring);
  if (config.planar) {
    return array;  // z is not estimated: the ring is the whole ellipsoid
  }

  // 3D: the 2-sigma ellipsoid too, a translucent sphere scaled along the principal axes.
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(estimate.covariance);
  Eigen::Matrix3d axes = eig.eigenvectors();
  if (axes.determinant() < 0.0) {
    axes.col(0) = -axes.col(0);  // a rotation, not a reflection
  }
  const Eigen::Quaterniond q(axes);
  const Eigen::Vector3d sigma = eig.eigenvalues().cwiseMax(0.0).cwiseSqrt();
  auto ellipse = marker(layout, "covariance", 1, visualization_msgs::Marker::SPHERE, stamp);
  ellipse.pose.position = point(estimate.position);
  ellipse.pose.orientation.x = q.x();
  ellipse.pose.orientation.y = q.y();
  ellipse.pose.orientation.z = q.z();
  ellipse.pose.orientation.w = q.w();
  ellipse.scale.x = std::max(0.01, 4.0 * sigma(0));  // 2-sigma diameter
  ellipse.scale.y = std::max(0.01, 4.0 * sigma(1));
  ellipse.scale.z = std::max(0.01, 4.0 * sigma(2));
  color(ellipse, 1.0f, 0.2f, 0.2f, 0.3f);
  array.markers.push_back(ellipse);
  return array;
}

}  // namespace radio_follow
