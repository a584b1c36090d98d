// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <diagnostic_updater/diagnostic_updater.h>
#include <nav_msgs/Path.h>
#include <ros/ros.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_broadcaster.h>
#include <tf2_ros/transform_listener.h>
#include <visualization_msgs/MarkerArray.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "radio_follow/TargetEstimate.h"
#include "radio_follow/common/geometry.hpp"
#include "radio_follow/common/input_watch.hpp"
#include "radio_follow/estimation/locator.hpp"
#include "radio_follow/estimation/locator_node_params.hpp"
#include "radio_follow/estimation/odometry_estimate.hpp"
#include "radio_follow/ros/common/callback_barrier.hpp"
#include "radio_follow/ros/common/output_diagnostic.hpp"
#include "radio_follow/ros/common/params.hpp"
#include "radio_follow/ros/locator/locator_inputs.hpp"
#include "radio_follow/ros/locator/locator_reconfigure.hpp"

namespace radio_follow {

/// ROS wiring of the Locator: subscribes to the drivers' measurements (one SensorInput per
/// measurement kind, locator_inputs.hpp), runs the solver at
/// a fixed rate and publishes the target estimate, its pose, TF, markers, the path of
/// recent estimates and diagnostics; warns which expected inputs are silent.
/// Sensor positions come from the layout file (not from TF). See doc/nodes/locator.md.
class LocatorNode {
 public:
  using Params = estimation::LocatorNodeParams;

  LocatorNode(ros::NodeHandle& nh, ros::NodeHandle& private_nh);

 private:
  void onTimer(const ros::TimerEvent& event);
  void publish(const estimation::LocatorEstimate& estimate, const ros::Time& now);
  void diagnose(diagnostic_updater::DiagnosticStatusWrapper& status);
  /// A message arrived on input `index` (subscribers_ order).
  void noteInput(std::size_t index);
  /// Warns about silent inputs (rationed per input) and logs new measurement drops.
  void watchInputs(const ros::Time& now);
  /// The robot's pose in odom_frame at `stamp` from TF, or nothing.
  std::optional<Pose2> odometryPose(const ros::Time& stamp) const;
  void extendPath(const estimation::LocatorEstimate& estimate, const ros::Time& stamp);
  /// Subscribes every input to its topics (all topics parameters empty: the layout's).
  void subscribeInputs(ros::NodeHandle& nh);

  Params params_;
  Layout layout_;
  std::unique_ptr<estimation::Locator> locator_;
  /// The estimates in the odometry frame (the message's odom_* part).
  estimation::OdometryTrack odometry_track_;
  std::unique_ptr<LocatorInputs> inputs_;
  std::unique_ptr<LocatorReconfigure> reconfigure_;  ///< live tuning, after the params load
  /// Every subscriber and the update timer run inside it: a message that makes a
  /// callback throw is logged, counted in diagnostics and dropped; the node goes on.
  CallbackBarrier barrier_;
  std::vector<ros::Subscriber> subscribers_;
  ros::Publisher target_pub_;
  std::unique_ptr<tf2_ros::Buffer> tf_buffer_;
  std::unique_ptr<tf2_ros::TransformListener> tf_listener_;
  ros::Publisher pose_pub_;
  ros::Publisher markers_pub_;
  ros::Publisher path_pub_;
  nav_msgs::Path path_;  ///< recent estimates, at most path_length
  tf2_ros::TransformBroadcaster tf_;
  ros::Time last_tf_stamp_;  ///< stamp of the last target TF sent
  diagnostic_updater::Updater diagnostics_;
  std::optional<OutputDiagnostic> target_diagnostic_;
  std::optional<OutputDiagnostic> pose_diagnostic_;
  std::optional<InputWatch> inputs_watch_;  ///< one entry per subscriber, resolved names
  ros::Time last_tick_;                     ///< zero until the first timer tick
  estimation::LocatorStats last_stats_;     ///< drop counters at the last tick
  ros::Timer timer_;
  TargetStatus last_status_ = TargetStatus::kLost;
  PolarSpread last_spread_;  ///< of the newest estimate, for diagnostics
  std::size_t ignored_messages_ = 0;
  double solve_seconds_sum_ = 0.0;
  double solve_seconds_max_ = 0.0;
  std::size_t solves_seen_ = 0;
};

/// The locator's rviz markers (pure function, unit-testable without a master): a circle
/// (2D) or sphere (3D) per range around its module, an arrow per fresh bearing from its
/// board (selected ones green, ignored ones grey), the estimate (a small sphere) and the
/// 2-sigma ellipse of its xy position as a ring above it (3D mode: the ellipsoid too).
visualization_msgs::MarkerArray locatorMarkers(const Layout& layout,
                                               const estimation::LocatorConfig& config,
                                               const estimation::LocatorEstimate& estimate,
                                               const ros::Time& stamp);

/// Converts the core's estimate to the message (frame = the layout's fixed frame).
TargetEstimate toMessage(const estimation::LocatorEstimate& estimate, const std::string& frame,
                         const ros::Time& stamp);
/// Fills the message's odometry-frame part (`odom_*`; NaN velocity when not tracked).
void setOdometry(TargetEstimate& msg, const estimation::OdometryEstimate& odom,
                 const std::string& odom_frame);

}  // namespace radio_follow
