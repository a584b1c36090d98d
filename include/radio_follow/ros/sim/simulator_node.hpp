// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <geometry_msgs/Twist.h>
#include <ros/ros.h>
#include <tf2_ros/transform_broadcaster.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "radio_follow/config/layout.hpp"
#include "radio_follow/ros/common/callback_barrier.hpp"
#include "radio_follow/ros/common/params.hpp"
#include "radio_follow/sim/obstacles.hpp"
#include "radio_follow/sim/serial_devices.hpp"
#include "radio_follow/sim/simulator_params.hpp"
#include "radio_follow/sim/world.hpp"

namespace radio_follow {

/// Runs the simulated world and publishes what the drivers would: UwbRanges per module
/// (`uwb/<id>/ranges`), AoaBearing per board (`aoa/<id>/bearing`), TdoaMeasurements
/// (`tdoa/measurements`), plus odometry, TF odom -> base_link, ground truth and, on sim
/// time, /clock. Integrates `cmd_vel`.
class SimulatorNode {
 public:
  using Params = sim::SimulatorParams;

  SimulatorNode(ros::NodeHandle& nh, ros::NodeHandle& private_nh);

 private:
  void onCmdVel(const geometry_msgs::TwistConstPtr& msg);
  void onTick(const ros::WallTimerEvent&);
  void publish(const sim::StepEvents& events);
  void publishTdoa(const sim::StepEvents& events);
  void publishState(const ros::Time& stamp);
  void publishScan(const ros::Time& stamp);
  ros::Time stampOf(double sim_seconds) const;

  ros::NodeHandle nh_;
  Params params_;
  Layout layout_;
  std::unique_ptr<sim::World> world_;
  std::unique_ptr<sim::SerialDevices> serial_;
  bool sim_time_ = false;
  ros::Time start_;

  CallbackBarrier barrier_;  // the subscriber and the step timer run inside it
  ros::Subscriber cmd_sub_;
  std::vector<ros::Publisher> range_pubs_;
  std::vector<ros::Publisher> bearing_pubs_;
  ros::Publisher tdoa_pub_;
  ros::Publisher odom_pub_;
  ros::Publisher truth_pub_;
  ros::Publisher truth_relative_pub_;
  ros::Publisher clock_pub_;
  ros::Publisher scan_pub_;
  ros::Publisher clearance_pub_;
  double next_scan_ = 0.0;  ///< sim seconds of the next scan
  double min_clearance_;    ///< closest the robot came to an obstacle, m
  sim::Rng scan_rng_;
  tf2_ros::TransformBroadcaster tf_;
  ros::WallTimer timer_;
  ros::WallTimer shutdown_timer_;
  ros::Publisher finished_pub_;

  double cmd_linear_ = 0.0;
  double cmd_angular_ = 0.0;
  double cmd_time_ = -1e9;  ///< sim seconds of the last cmd_vel
};

/// Reads the simulator's private parameters and validates them (throws ParamError).
SimulatorNode::Params loadSimulatorParams(const ParamReader& private_nh);

}  // namespace radio_follow
