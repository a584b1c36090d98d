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
#include "radio_follow/sim/world.hpp"

namespace radio_follow {

/// Runs the simulated world and publishes what the drivers would: UwbRanges per module
/// (`uwb/<id>/ranges`), AoaBearing per board (`aoa/<id>/bearing`), TdoaMeasurements
/// (`tdoa/measurements`), plus odometry, TF odom -> base_link, ground truth and, on sim
/// time, /clock. Integrates `cmd_vel`.
class SimulatorNode {
 public:
  struct Params {
    std::string layout_file;
    std::string scenario_file;
    int seed = 1;
    double step_rate = 100.0;        ///< physics steps per simulated second
    double time_factor = 1.0;        ///< simulated seconds per wall second (sim time only)
    double cmd_timeout = 0.5;        ///< s without cmd_vel before the base stops by itself
    bool shutdown_on_finish = true;  ///< end the node (and a launch that requires it) at the end
    /// World frame of odometry; the robot frame is the layout's fixed_frame.
    std::string odom_frame = "odom";
    sim::WorldConfig world;
    sim::ScanConfig scan;
    /// "messages": publish driver messages; "serial": speak the devices' protocols on
    /// pseudo-terminals under serial_dir so the real drivers run in the loop.
    std::string output = "messages";
    std::string serial_dir = "/tmp/radio_follow_sim";
    std::vector<sim::UnplugFault> unplug;

    /// Every parameter but the lists ~twr_occlusions and ~unplug (config/simulator.yaml).
    static const ParamTable<Params>& table();
    void validate() const;
  };

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
