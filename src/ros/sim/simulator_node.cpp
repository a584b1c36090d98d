// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/ros/sim/simulator_node.hpp"

#include <geometry_msgs/PointStamped.h>
#include <geometry_msgs/TransformStamped.h>
#include <nav_msgs/Odometry.h>
#include <radio_follow/AoaBearing.h>
#include <radio_follow/TdoaMeasurements.h>
#include <radio_follow/UwbRanges.h>
#include <rosgraph_msgs/Clock.h>
#include <sensor_msgs/LaserScan.h>
#include <std_msgs/Bool.h>
#include <std_msgs/Float64.h>

#include <cmath>
#include <filesystem>
#include <limits>

#include "radio_follow/common/param_error.hpp"

namespace radio_follow {
namespace {

/// Wall seconds between announcing the end and shutting down.
constexpr double kFinishLinger = 1.0;

geometry_msgs::Quaternion yawQuaternion(double yaw) {
  geometry_msgs::Quaternion q;
  q.z = std::sin(0.5 * yaw);
  q.w = std::cos(0.5 * yaw);
  return q;
}

}  // namespace

SimulatorNode::SimulatorNode(ros::NodeHandle& nh, ros::NodeHandle& private_nh)
    : nh_(nh),
      params_([&] {
        const ParamReader params(private_nh);
        SimulatorNode::Params p = loadSimulatorParams(params);
        params.requireAllKnown();
        return p;
      }()),
      min_clearance_(std::numeric_limits<double>::infinity()),
      scan_rng_(params_.world.seed + 1) {
  layout_ = loadLayoutFile(params_.layout_file);
  const sim::Scenario scenario =
      sim::loadScenarioFile(params_.scenario_file, static_cast<std::uint64_t>(params_.seed));
  require(layout_.fixed_frame != params_.odom_frame, "~odom_frame", params_.odom_frame,
          "a frame other than the layout's fixed_frame '" + layout_.fixed_frame + "'");
  world_ = std::make_unique<sim::World>(layout_, scenario, params_.world);
  if (params_.output == "serial") {
    std::error_code error;
    std::filesystem::create_directories(params_.serial_dir, error);
    serial_ = std::make_unique<sim::SerialDevices>(layout_, params_.serial_dir, params_.unplug);
  }
  ros::param::param("/use_sim_time", sim_time_, false);

  for (const auto& module : layout_.twr_modules) {
    if (!serial_) {
      range_pubs_.push_back(nh.advertise<UwbRanges>("uwb/" + module.id + "/ranges", 20));
    }
  }
  for (const auto& board : layout_.aoa_boards) {
    if (!serial_) {
      bearing_pubs_.push_back(nh.advertise<AoaBearing>("aoa/" + board.id + "/bearing", 20));
    }
  }
  if (layout_.tdoa_anchors.size() >= 2) {
    tdoa_pub_ = nh.advertise<TdoaMeasurements>("tdoa/measurements", 20);
  }
  odom_pub_ = nh.advertise<nav_msgs::Odometry>("odom", 20);
  truth_pub_ = nh.advertise<geometry_msgs::PointStamped>("ground_truth/target", 20);
  truth_relative_pub_ =
      nh.advertise<geometry_msgs::PointStamped>("ground_truth/target_relative", 20);
  if (sim_time_) {
    clock_pub_ = nh.advertise<rosgraph_msgs::Clock>("/clock", 10);
  }
  if (!scenario.obstacles.empty()) {
    scan_pub_ = nh.advertise<sensor_msgs::LaserScan>("scan", 5);
    clearance_pub_ = nh.advertise<std_msgs::Float64>("ground_truth/obstacle_clearance", 5);
  }
  finished_pub_ = nh.advertise<std_msgs::Bool>("ground_truth/finished", 1, true);
  cmd_sub_ = barrier_.subscribe(nh, "cmd_vel", 10, &SimulatorNode::onCmdVel, this);

  // On sim time the node owns the clock and runs time_factor x real time; on wall time
  // it runs in real time and stamps from the wall clock.
  const double wall_period = 1.0 / (params_.step_rate * (sim_time_ ? params_.time_factor : 1.0));
  start_ = sim_time_ ? ros::Time(1.0) : ros::Time::now();
  timer_ = barrier_.wallTimer(nh, ros::WallDuration(wall_period), "simulation step",
                              [this](const ros::WallTimerEvent& event) { onTick(event); });
  ROS_INFO(
      "simulator: scenario '%s' (%.1f s), %zu UWB modules, %zu AoA boards, %zu TDoA anchors, "
      "%s time x%.1f, output %s, %s sensors (hardware seed %llu)",
      scenario.name.c_str(), scenario.duration, layout_.twr_modules.size(),
      layout_.aoa_boards.size(), layout_.tdoa_anchors.size(), sim_time_ ? "sim" : "wall",
      sim_time_ ? params_.time_factor : 1.0, params_.output.c_str(),
      sim::toString(params_.world.profile).c_str(),
      static_cast<unsigned long long>(params_.world.hardware_seed));
}

ros::Time SimulatorNode::stampOf(double sim_seconds) const {
  return start_ + ros::Duration(sim_seconds);
}

void SimulatorNode::onCmdVel(const geometry_msgs::TwistConstPtr& msg) {
  cmd_linear_ = msg->linear.x;
  cmd_angular_ = msg->angular.z;
  cmd_time_ = world_->time();
}

void SimulatorNode::onTick(const ros::WallTimerEvent&) {
  if (world_->finished()) {
    timer_.stop();
    ROS_INFO("simulator: scenario finished at %.1f s; closest approach to an obstacle %.2f m",
             world_->time(), min_clearance_);
    std_msgs::Bool finished;
    finished.data = true;
    finished_pub_.publish(finished);
    if (params_.shutdown_on_finish) {
      // Give listeners (the evaluator) a moment to close their books, then end.
      shutdown_timer_ = nh_.createWallTimer(
          ros::WallDuration(kFinishLinger),
          [](const ros::WallTimerEvent&) { ros::requestShutdown(); }, true);
    }
    return;
  }
  // A real base stops when its command stream stops; so does the simulated one.
  const bool fresh = world_->time() - cmd_time_ <= params_.cmd_timeout;
  const sim::StepEvents events =
      world_->step(fresh ? cmd_linear_ : 0.0, fresh ? cmd_angular_ : 0.0, 1.0 / params_.step_rate);
  const ros::Time now = stampOf(world_->time());
  if (sim_time_) {
    rosgraph_msgs::Clock clock;
    clock.clock = now;
    clock_pub_.publish(clock);
  }
  publishState(now);
  if (serial_) {
    serial_->service(world_->time());
    serial_->write(events);
    publishTdoa(events);
  } else {
    publish(events);
  }
  if (scan_pub_ && world_->time() >= next_scan_) {
    next_scan_ = world_->time() + 1.0 / params_.scan.rate;
    publishScan(now);
  }
}

void SimulatorNode::publishScan(const ros::Time& stamp) {
  const sim::Obstacles& obstacles = world_->scenario().obstacles;
  const sim::Pose2& pose = world_->robot().pose();
  const double clearance = sim::clearance(obstacles, pose.x, pose.y);
  min_clearance_ = std::min(min_clearance_, clearance);
  std_msgs::Float64 clearance_msg;
  clearance_msg.data = clearance;
  clearance_pub_.publish(clearance_msg);

  sensor_msgs::LaserScan scan;
  scan.header.stamp = stamp;
  scan.header.frame_id = layout_.fixed_frame;
  scan.angle_min = static_cast<float>(params_.scan.angle_min);
  scan.angle_max = static_cast<float>(params_.scan.angle_max);
  scan.angle_increment = static_cast<float>(params_.scan.angleIncrement());
  scan.scan_time = static_cast<float>(1.0 / params_.scan.rate);
  scan.range_min = static_cast<float>(params_.scan.range_min);
  scan.range_max = static_cast<float>(params_.scan.range_max);
  std::normal_distribution<double> noise(0.0, params_.scan.sigma);
  scan.ranges = sim::noisyScan(obstacles, params_.scan, pose, noise, scan_rng_);
  scan_pub_.publish(scan);
}

void SimulatorNode::publish(const sim::StepEvents& events) {
  for (const auto& e : events.twr) {
    const TwrModule& module = layout_.twr_modules[e.module];
    UwbRanges msg;
    msg.header.stamp = stampOf(e.t);
    msg.header.frame_id = module.frame_id;
    msg.tag_id = module.id;
    UwbRange range;
    range.anchor_id = layout_.target_anchor_id;
    range.range = e.range;
    msg.ranges.push_back(range);
    range_pubs_[e.module].publish(msg);
  }
  for (const auto& e : events.aoa) {
    AoaBearing msg;
    msg.header.stamp = stampOf(e.t);
    msg.header.frame_id = layout_.aoa_boards[e.board].frame_id;
    msg.tag_id = layout_.target_tag_id.empty() ? "SIMTAG000001" : layout_.target_tag_id;
    msg.anchor_id = layout_.aoa_boards[e.board].id;
    msg.azimuth = e.sample.azimuth;
    msg.elevation = e.sample.elevation;
    msg.rssi = e.sample.rssi;
    msg.rssi_second = e.sample.rssi_second;
    msg.channel = 37;
    msg.device_timestamp_ms = static_cast<std::uint32_t>(e.t * 1000.0);
    msg.event_counter = -1;
    bearing_pubs_[e.board].publish(msg);
  }
  publishTdoa(events);
}

void SimulatorNode::publishTdoa(const sim::StepEvents& events) {
  for (const auto& e : events.tdoa) {
    TdoaMeasurements msg;
    msg.header.stamp = stampOf(e.t);
    msg.header.frame_id = layout_.fixed_frame;
    // The person's device, or one of the robot's own modules heard by the anchors.
    msg.tag_id = e.module ? layout_.twr_modules[*e.module].id : layout_.target_tdoa_tag_id;
    const std::size_t ref = params_.world.tdoa_reference;
    std::size_t k = 0;
    for (std::size_t i = 0; i < layout_.tdoa_anchors.size(); ++i) {
      if (i == ref) {
        continue;
      }
      TdoaDifference d;
      d.anchor_a = layout_.tdoa_anchors[i].id;
      d.anchor_b = layout_.tdoa_anchors[ref].id;
      d.distance_difference = e.differences[k++];
      d.variance = params_.world.tdoa_sigma * params_.world.tdoa_sigma;
      msg.differences.push_back(d);
    }
    tdoa_pub_.publish(msg);
  }
}

void SimulatorNode::publishState(const ros::Time& stamp) {
  const sim::Pose2& pose = world_->robot().pose();
  nav_msgs::Odometry odom;
  odom.header.stamp = stamp;
  odom.header.frame_id = params_.odom_frame;
  odom.child_frame_id = layout_.fixed_frame;
  odom.pose.pose.position.x = pose.x;
  odom.pose.pose.position.y = pose.y;
  odom.pose.pose.orientation = yawQuaternion(pose.yaw);
  odom.twist.twist.linear.x = world_->robot().linear();
  odom.twist.twist.angular.z = world_->robot().angular();
  odom_pub_.publish(odom);

  geometry_msgs::TransformStamped tf;
  tf.header = odom.header;
  tf.child_frame_id = layout_.fixed_frame;
  tf.transform.translation.x = pose.x;
  tf.transform.translation.y = pose.y;
  tf.transform.rotation = odom.pose.pose.orientation;
  tf_.sendTransform(tf);

  geometry_msgs::PointStamped truth;
  truth.header.stamp = stamp;
  truth.header.frame_id = params_.odom_frame;
  const Eigen::Vector3d world_target = world_->targetInWorld();
  truth.point.x = world_target.x();
  truth.point.y = world_target.y();
  truth.point.z = world_target.z();
  truth_pub_.publish(truth);

  truth.header.frame_id = layout_.fixed_frame;
  const Eigen::Vector3d relative = world_->targetInRobot();
  truth.point.x = relative.x();
  truth.point.y = relative.y();
  truth.point.z = relative.z();
  truth_relative_pub_.publish(truth);
}

}  // namespace radio_follow
