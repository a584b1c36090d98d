// SPDX-License-Identifier: BSD-3-Clause
// calibrate_layout end to end: bags written here with known module biases and scales and
// known board mounting errors (plus noise, reflections, another anchor), calibrated by the
// tool binary against a ground-truth topic and against tape points; the written layout
// loads and holds the truth. Then the shipped simulator bag, and every refusal.
#include <geometry_msgs/PointStamped.h>
#include <geometry_msgs/PoseStamped.h>
#include <gtest/gtest.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <rosbag/bag.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <type_traits>
#include <vector>

#include "../support/private_param.hpp"
#include "../support/run_tool.hpp"
#include "../support/uwb_ranges.hpp"
#include "radio_follow/AoaBearing.h"
#include "radio_follow/UwbRanges.h"
#include "radio_follow/common/angles.hpp"
#include "radio_follow/config/layout.hpp"
#include "radio_follow/estimation/calibration_pairing.hpp"
#include "radio_follow/ros/replay/calibration_bag.hpp"

namespace rf = radio_follow;

namespace {

std::string param(const std::string& name) {
  return rf::test::privateParam(name);
}

int runTool(const std::string& args, std::string& output) {
  return rf::test::runTool("calibrate_layout", args, output);
}

/// What the bag's sensors get wrong: reading = bias + (1 + slope) * distance per module;
/// each board mounted yaw_error rad about its z from the layout's orientation.
struct Errors {
  std::vector<double> bias{0.15, -0.10, 0.30};
  std::vector<double> slope{0.02, 0.0, -0.015};
  std::vector<double> yaw_error{rf::deg2rad(3.0), rf::deg2rad(-2.0), 0.0, rf::deg2rad(5.0)};
};

/// The tag at time t of a slow spiral walk around the robot, 1 to 8 m out.
Eigen::Vector3d walk(double t) {
  const double d = 1.0 + 7.0 * (0.5 - 0.5 * std::cos(t / 20.0));
  return {d * std::cos(t / 7.0), d * std::sin(t / 7.0), 1.1};
}

/// Writes a bag at `path` of `seconds`: ranges of every module at 10 Hz (5 % reflections,
/// and ranges to another anchor), bearings of every board at 10 Hz, and, with `truth`,
/// the tag on ground_truth/target_relative at 20 Hz. `position(t)` is where the tag is.
template <typename Position>
void writeBag(const std::string& path, const rf::Layout& layout, const Errors& e, double seconds,
              bool truth, Position position, const std::vector<std::size_t>& silent_modules = {}) {
  rosbag::Bag bag(path, rosbag::bagmode::Write);
  std::mt19937_64 rng(11);
  std::normal_distribution<double> noise(0.0, 1.0);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double t0 = 1000.0;
  for (int step = 0; step < static_cast<int>(seconds * 20.0); ++step) {
    const double t = 0.05 * step;
    const ros::Time stamp(t0 + t);
    const Eigen::Vector3d tag = position(t);
    if (truth) {
      geometry_msgs::PointStamped p;
      p.header.stamp = stamp;
      p.header.frame_id = layout.fixed_frame;
      p.point.x = tag.x();
      p.point.y = tag.y();
      p.point.z = tag.z();
      bag.write("/ground_truth/target_relative", stamp, p);
    }
    if (step % 2 == 1) {
      continue;
    }
    const ros::Time measured(t0 + t + 0.01);
    for (std::size_t i = 0; i < layout.twr_modules.size(); ++i) {
      if (std::find(silent_modules.begin(), silent_modules.end(), i) != silent_modules.end()) {
        continue;
      }
      const rf::TwrModule& m = layout.twr_modules[i];
      double range = e.bias[i] + (1.0 + e.slope[i]) * (tag - m.position).norm() + 0.05 * noise(rng);
      if (unit(rng) < 0.05) {
        range += 0.5 + 2.0 * unit(rng);
      }
      rf::UwbRanges r = rf::test::uwbRanges(m, layout.target_anchor_id, range, measured);
      r.ranges.push_back(r.ranges.front());
      r.ranges.back().anchor_id = "0B0B";  // another anchor of the network: not the target's
      bag.write("/uwb/" + m.id + "/ranges", measured, r);
    }
    for (std::size_t i = 0; i < layout.aoa_boards.size(); ++i) {
      const rf::AoaBoard& b = layout.aoa_boards[i];
      rf::AoaBearing a;
      a.header.stamp = measured;
      a.header.frame_id = b.frame_id;
      a.tag_id = "CCF9578E0D8A";
      a.azimuth = rf::wrapAngle(rf::estimation::trueAzimuth(b, tag) - e.yaw_error[i] +
                                rf::deg2rad(2.0) * noise(rng));
      bag.write("/aoa/" + b.id + "/bearing", measured, a);
    }
  }
}

class CalibrateLayout : public ::testing::Test {
 protected:
  void SetUp() override {
    config_ = param("config_dir");
    layout_file_ = config_ + "/layouts/spot.yaml";
    layout_ = rf::loadLayoutFile(layout_file_);
    dir_ = std::filesystem::temp_directory_path() / "calibrate_layout_test";
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
  }
  std::string args(const std::string& bag, const std::string& reference) const {
    return "--bag " + bag + " --layout " + layout_file_ + " --out " + dir_ + "/out.yaml " +
           reference;
  }
  std::string config_, layout_file_, dir_;
  rf::Layout layout_;
  Errors errors_;
};

TEST_F(CalibrateLayout, FitsEveryModuleAndBoardFromAGroundTruthTopic) {
  const std::string bag = dir_ + "/truth.bag";
  writeBag(bag, layout_, errors_, 180.0, true, walk);

  const rf::CalibrationBag data =
      rf::loadCalibrationBag(bag, layout_,
                             {rf::conventionalTopics(layout_).uwb,
                              rf::conventionalTopics(layout_).aoa, "ground_truth/target_relative"});
  EXPECT_EQ(data.truth.size(), 3600u);
  EXPECT_EQ(data.messages.at("uwb/5722/ranges"), 1800u);
  EXPECT_EQ(data.other_anchors, 3u * 1800u);
  EXPECT_EQ(data.measurements.size(), (3u + 4u) * 1800u);

  std::string output;
  ASSERT_EQ(runTool(args(bag, "--truth-topic ground_truth/target_relative"), output), 0) << output;
  const rf::Layout out = rf::loadLayoutFile(dir_ + "/out.yaml");
  for (std::size_t i = 0; i < out.twr_modules.size(); ++i) {
    const std::vector<double>& c = out.twr_modules[i].calibration;
    ASSERT_EQ(c.size(), 2u);
    // corrected = (raw - bias) / (1 + slope)
    EXPECT_NEAR(c[1], 1.0 / (1.0 + errors_.slope[i]), 0.005) << out.twr_modules[i].id;
    EXPECT_NEAR(c[0], -errors_.bias[i] / (1.0 + errors_.slope[i]), 0.02) << out.twr_modules[i].id;
    EXPECT_EQ(out.twr_modules[i].position, layout_.twr_modules[i].position);
  }
  for (std::size_t i = 0; i < out.aoa_boards.size(); ++i) {
    const Eigen::Quaterniond mounted =
        layout_.aoa_boards[i].orientation *
        Eigen::AngleAxisd(errors_.yaw_error[i], Eigen::Vector3d::UnitZ());
    EXPECT_LT(rf::rad2deg(out.aoa_boards[i].orientation.angularDistance(mounted)), 0.3)
        << out.aoa_boards[i].id;
  }
  EXPECT_NE(output.find("5722"), std::string::npos) << output;
  EXPECT_NE(output.find("rms before"), std::string::npos) << output;
  EXPECT_NE(output.find("wrote"), std::string::npos) << output;
  std::cout << output;  // the figures doc/deployment.md quotes
}

TEST_F(CalibrateLayout, FitsTheModulesFromTapePoints) {
  // The person stands 20 s at each of 8 points, 1-8 m out in several directions, and
  // walks 5 s between them (the walk is not compared: it is outside every window).
  std::vector<Eigen::Vector3d> spots;
  std::ofstream points(dir_ + "/points.yaml");
  points << "points:\n";
  for (int k = 0; k < 8; ++k) {
    const double d = 1.0 + k;
    const double heading = rf::deg2rad(-150.0 + 45.0 * k);
    spots.emplace_back(d * std::cos(heading), d * std::sin(heading), 1.1);
    points << "  - {position: [" << spots.back().x() << ", " << spots.back().y()
           << ", 1.1], from: " << 25 * k + 1 << ", until: " << 25 * k + 19 << "}\n";
  }
  points.close();
  auto at = [&](double t) {
    const int k = std::min(7, static_cast<int>(t / 25.0));
    const double phase = t - 25.0 * k;
    return phase < 20.0 || k == 7 ? spots[k] : Eigen::Vector3d(50.0, 0.0, 1.1);  // walking
  };
  const std::string bag = dir_ + "/points.bag";
  writeBag(bag, layout_, errors_, 200.0, false, at);
  std::string output;
  ASSERT_EQ(runTool(args(bag, "--no-aoa --points " + dir_ + "/points.yaml"), output), 0) << output;
  const rf::Layout out = rf::loadLayoutFile(dir_ + "/out.yaml");
  for (std::size_t i = 0; i < out.twr_modules.size(); ++i) {
    const std::vector<double>& c = out.twr_modules[i].calibration;
    EXPECT_NEAR(c[1], 1.0 / (1.0 + errors_.slope[i]), 0.01) << out.twr_modules[i].id;
    EXPECT_NEAR(c[0], -errors_.bias[i] / (1.0 + errors_.slope[i]), 0.03) << out.twr_modules[i].id;
  }
  // --no-aoa: the boards keep their orientation.
  for (std::size_t i = 0; i < out.aoa_boards.size(); ++i) {
    EXPECT_LT(out.aoa_boards[i].orientation.angularDistance(layout_.aoa_boards[i].orientation),
              1e-9);
  }
  std::cout << output;
}

TEST_F(CalibrateLayout, ASilentModuleKeepsItsCalibrationAndTheRestIsFitted) {
  const std::string bag = dir_ + "/silent.bag";
  writeBag(bag, layout_, errors_, 120.0, true, walk, {1});
  std::string output;
  ASSERT_EQ(runTool(args(bag, "--truth-topic ground_truth/target_relative"), output), 0) << output;
  EXPECT_NE(output.find("5A84       not fitted, keeps ["), std::string::npos) << output;
  EXPECT_NE(output.find("]: no message on uwb/5A84/ranges"), std::string::npos) << output;
  const rf::Layout out = rf::loadLayoutFile(dir_ + "/out.yaml");
  EXPECT_EQ(out.twr_modules[1].calibration, layout_.twr_modules[1].calibration);
  EXPECT_NE(out.twr_modules[0].calibration, layout_.twr_modules[0].calibration);
}

/// Appends the walk as a motion-capture system would publish it: `T` (PoseStamped or
/// Odometry) on `topic` at 100 Hz in `frame`.
template <typename T>
void appendMocap(const std::string& path, const std::string& topic, const std::string& frame,
                 double seconds) {
  rosbag::Bag bag(path, rosbag::bagmode::Append);
  for (int step = 0; step < static_cast<int>(seconds * 100.0); ++step) {
    const double t = 0.01 * step;
    T m;
    m.header.stamp = ros::Time(1000.0 + t);
    m.header.frame_id = frame;
    const Eigen::Vector3d p = walk(t);
    geometry_msgs::Pose& pose = [&]() -> geometry_msgs::Pose& {
      if constexpr (std::is_same_v<T, nav_msgs::Odometry>) {
        return m.pose.pose;
      } else {
        return m.pose;
      }
    }();
    pose.position.x = p.x();
    pose.position.y = p.y();
    pose.position.z = p.z();
    pose.orientation.w = 1.0;
    bag.write(topic, m.header.stamp, m);
  }
}

TEST_F(CalibrateLayout, ReadsAMotionCaptureTopicInTheLayoutsFrameOnly) {
  const std::string bag = dir_ + "/mocap.bag";
  writeBag(bag, layout_, errors_, 120.0, false, walk);
  appendMocap<geometry_msgs::PoseStamped>(bag, "/mocap/tag_pose", "base_link", 120.0);
  appendMocap<nav_msgs::Odometry>(bag, "/mocap/tag_odom", "base_link", 120.0);
  appendMocap<geometry_msgs::PoseStamped>(bag, "/mocap/tag_in_map", "map", 120.0);
  for (const std::string topic : {"/mocap/tag_pose", "mocap/tag_odom"}) {
    std::string output;
    ASSERT_EQ(runTool(args(bag, "--no-aoa --truth-topic " + topic), output), 0) << output;
    const rf::Layout out = rf::loadLayoutFile(dir_ + "/out.yaml");
    EXPECT_NEAR(out.twr_modules[2].calibration[0], -errors_.bias[2] / (1.0 + errors_.slope[2]),
                0.02)
        << topic << "\n"
        << output;
  }
  std::string output;
  EXPECT_EQ(runTool(args(bag, "--truth-topic mocap/tag_in_map"), output), 1);
  EXPECT_NE(output.find("/mocap/tag_in_map is in frame 'map', the layout's fixed frame is "
                        "'base_link'"),
            std::string::npos)
      << output;
}

TEST_F(CalibrateLayout, OnTheShippedSimulatorBagEveryModuleImproves) {
  std::string output;
  ASSERT_EQ(runTool(args(param("bag"), "--truth-topic ground_truth/target_relative"), output), 0)
      << output;
  const rf::Layout out = rf::loadLayoutFile(dir_ + "/out.yaml");
  // The simulated robot's modules (realistic profile, hardware_seed 1) read long by a bias
  // of +0.08 to +0.31 m and +0.6 to +2 % of the range; the walk stays 1.5-4 m from the
  // robot, so the fit is checked by its residual. What no range polynomial removes is the
  // time-correlated noise, sigma 0.065 m (sensor_profile_test), and the direction
  // dependence, nearly constant with the person ahead: 0.059-0.074 m after on this bag, from
  // 0.14-0.28 m before.
  for (const rf::TwrModule& m : out.twr_modules) {
    const std::string row = output.substr(output.find("\n" + m.id + " "), 80);
    double used = 0, rejected = 0, before = 0, after = 0;
    ASSERT_EQ(std::sscanf(row.c_str() + 1 + m.id.size(), "%lf %lf %lf m %lf m", &used, &rejected,
                          &before, &after),
              4)
        << row;
    EXPECT_GT(used, 300) << row;
    EXPECT_LT(after, 0.08) << row;  // the noise's sigma 0.065 m, and some margin
    EXPECT_LT(after, 0.6 * before) << row;
  }
  std::cout << output;
}

TEST_F(CalibrateLayout, RefusesWhatItCannotUseNamingIt) {
  const std::string bag = dir_ + "/short.bag";
  writeBag(bag, layout_, errors_, 30.0, true, walk);
  std::string output;
  EXPECT_EQ(runTool(args(bag, "--truth-topic mocap/tag"), output), 1);
  EXPECT_NE(output.find("has no topic mocap/tag (ground-truth topics of a usable type in it: "
                        "/ground_truth/target_relative)"),
            std::string::npos)
      << output;
  EXPECT_EQ(runTool(args(bag, "--truth-topic aoa/front/bearing"), output), 1);
  EXPECT_NE(output.find("is radio_follow/AoaBearing, expected geometry_msgs/PointStamped"),
            std::string::npos)
      << output;
  EXPECT_EQ(runTool(args(bag,
                         "--truth-topic ground_truth/target_relative --uwb-topics "
                         "uwb/5722/ranges,uwb/9999/ranges"),
                    output),
            1);
  EXPECT_NE(output.find("no message on uwb/9999/ranges (radio_follow/UwbRanges topics in it: "
                        "/uwb/5722/ranges, /uwb/5A84/ranges, /uwb/C4B5/ranges)"),
            std::string::npos)
      << output;
  // The reference 100 s away from every measurement: all dropped, nothing fitted, no file.
  EXPECT_EQ(runTool(args(bag, "--points " + dir_ + "/late.yaml"), output), 2);
  EXPECT_NE(output.find("'points' = '" + dir_ + "/late.yaml'"), std::string::npos) << output;
  std::ofstream(dir_ + "/late.yaml")
      << "points:\n  - {position: [2, 0, 1], from: 100, until: 200}\n";
  EXPECT_EQ(runTool(args(bag, "--points " + dir_ + "/late.yaml"), output), 1);
  EXPECT_NE(output.find("nothing could be fitted"), std::string::npos) << output;
  EXPECT_FALSE(std::filesystem::exists(dir_ + "/out.yaml"));

  EXPECT_EQ(runTool(args(bag, "--truth-topic t --degree 5"), output), 2);
  EXPECT_NE(output.find("--degree '5': expected a whole number from 0 to 3"), std::string::npos)
      << output;
  EXPECT_EQ(runTool(args(bag, "--truth-topic t --max-gap -1"), output), 2);
  EXPECT_NE(output.find("--max-gap '-1': expected seconds > 0"), std::string::npos) << output;
  EXPECT_EQ(runTool(args(bag, "--truth-topic t --points p.yaml"), output), 2);
  EXPECT_NE(output.find("exactly one reference"), std::string::npos) << output;
  EXPECT_EQ(runTool(args(bag, "--truth-topic t --frobnicate"), output), 2);
  EXPECT_NE(output.find("unrecognised option '--frobnicate'"), std::string::npos) << output;
  EXPECT_EQ(runTool("--help", output), 0);
  EXPECT_NE(output.find("COMMENTS ARE NOT"), std::string::npos) << output;
  EXPECT_EQ(runTool(args("/nonexistent.bag", "--truth-topic t"), output), 1);
  EXPECT_NE(output.find("cannot read bag '/nonexistent.bag'"), std::string::npos) << output;
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "calibrate_layout_rostest");
  return RUN_ALL_TESTS();
}
