// SPDX-License-Identifier: BSD-3-Clause
#include <gtest/gtest.h>

#include <cmath>

#include "radio_follow/common/angles.hpp"
#include "radio_follow/common/param_error.hpp"
#include "radio_follow/sim/robot.hpp"
#include "radio_follow/sim/target_path.hpp"

namespace radio_follow {
namespace sim {
namespace {

TEST(UnicycleRobot, RampsWithinAccelerationAndSpeedLimits) {
  RobotLimits limits;
  limits.max_linear = 1.0;
  limits.max_linear_accel = 0.5;
  UnicycleRobot robot(limits);
  double previous = 0.0;
  for (int i = 0; i < 100; ++i) {
    robot.step(5.0, 0.0, 0.05);
    EXPECT_LE(robot.linear() - previous, 0.5 * 0.05 + 1e-12);
    EXPECT_LE(robot.linear(), 1.0 + 1e-12);
    previous = robot.linear();
  }
  EXPECT_DOUBLE_EQ(robot.linear(), 1.0);
  // 2 s of ramp covers 1 m, the remaining 3 s at 1 m/s another 3 m.
  EXPECT_NEAR(robot.pose().x, 4.0, 1e-9);
  EXPECT_NEAR(robot.pose().y, 0.0, 1e-12);
}

TEST(UnicycleRobot, BrakesAtItsOwnDecelerationLimit) {
  RobotLimits limits;
  limits.max_linear_accel = 0.5;
  limits.max_linear_decel = 2.0;
  UnicycleRobot robot(limits);
  for (int i = 0; i < 100; ++i) {
    robot.step(1.0, 0.0, 0.05);
  }
  ASSERT_NEAR(robot.linear(), 1.0, 1e-12);
  const double before = robot.odometer();
  robot.step(0.0, 0.0, 0.25);  // 2 m/s^2 for 0.25 s: 1 m/s -> 0.5 m/s
  EXPECT_NEAR(robot.linear(), 0.5, 1e-12);
  for (int i = 0; i < 10; ++i) {
    robot.step(0.0, 0.0, 0.05);
  }
  EXPECT_EQ(robot.linear(), 0.0);
  // Stopping distance from 1 m/s at 2 m/s^2 is 0.25 m.
  EXPECT_NEAR(robot.odometer() - before, 0.25, 1e-9);
}

TEST(UnicycleRobot, DrivesAClosedCircle) {
  RobotLimits limits;
  limits.max_linear_accel = 1e6;
  limits.max_angular_accel = 1e6;
  UnicycleRobot robot(limits);
  const double w = 0.5;
  const double period = 2.0 * kPi / w;
  const int steps = 1000;
  for (int i = 0; i < steps; ++i) {
    robot.step(1.0, w, period / steps);
  }
  // One full turn of radius 2 m; the first step's ramp shifts the end by < 1 mm.
  EXPECT_NEAR(robot.pose().x, 0.0, 1e-2);
  EXPECT_NEAR(robot.pose().y, 0.0, 1e-2);
  EXPECT_NEAR(robot.odometer(), 2.0 * kPi * 2.0, 1e-2);
}

TEST(UnicycleRobot, NonFiniteCommandStops) {
  UnicycleRobot robot(RobotLimits{});
  robot.step(1.0, 0.0, 0.1);
  robot.step(std::nan(""), std::nan(""), 10.0);
  EXPECT_DOUBLE_EQ(robot.linear(), 0.0);
  EXPECT_TRUE(std::isfinite(robot.pose().x));
}

TEST(UnicycleRobot, RejectsBadLimits) {
  RobotLimits limits;
  limits.max_angular = -1.0;
  try {
    UnicycleRobot robot(limits);
    FAIL();
  } catch (const ParamError& e) {
    EXPECT_EQ(e.name(), "~max_angular");
  }
}

TEST(TargetPath, WalksWaitsAndTurns) {
  TargetPath path(Pose2{0, 0, 0});
  path.walkTo(4, 0, 2.0);   // 2 s
  path.wait(1.0);           // until 3 s
  path.arc(1.0, kPi, 1.0);  // half circle to the left, pi s
  EXPECT_NEAR(path.duration(), 3.0 + kPi, 1e-9);
  EXPECT_NEAR(path.at(1.0).pose.x, 2.0, 1e-12);
  EXPECT_NEAR(path.at(2.5).pose.x, 4.0, 1e-12);
  EXPECT_DOUBLE_EQ(path.at(2.5).speed, 0.0);
  const TargetSample end = path.at(100.0);
  EXPECT_NEAR(end.pose.x, 4.0, 1e-9);
  EXPECT_NEAR(end.pose.y, 2.0, 1e-9);
  EXPECT_NEAR(std::abs(end.pose.yaw), kPi, 1e-9);
  EXPECT_NEAR(path.length(), 4.0 + kPi, 0.01);
}

TEST(TargetPath, RandomWalkIsDeterministicPerSeed) {
  TargetPath a(Pose2{}), b(Pose2{}), c(Pose2{});
  a.randomWalk(10, 1.0, 0.5, 1.0, 42);
  b.randomWalk(10, 1.0, 0.5, 1.0, 42);
  c.randomWalk(10, 1.0, 0.5, 1.0, 43);
  EXPECT_DOUBLE_EQ(a.at(7.3).pose.x, b.at(7.3).pose.x);
  EXPECT_NE(a.at(7.3).pose.x, c.at(7.3).pose.x);
  EXPECT_NEAR(a.length(), 10.0, 1e-9);
}

TEST(Scenario, ParsesLegsAndDefaults) {
  const Scenario s = parseScenario(R"(
name: loop
robot_start: [0, 0, 90]
target:
  start: [2, 0]
  height: 1.1
  speed: 1.0
  legs:
    - {to: [12, 0]}
    - {arc_deg: 270, radius: 3}
    - {wait: 2}
    - {to: [0, 0], speed: 0.5}
)",
                                   "test", 1);
  EXPECT_EQ(s.name, "loop");
  EXPECT_NEAR(s.robot_start.yaw, kPi / 2.0, 1e-12);
  EXPECT_DOUBLE_EQ(s.target_height, 1.1);
  EXPECT_GT(s.target.duration(), 10.0 + 1.5 * kPi * 3.0);
  EXPECT_DOUBLE_EQ(s.duration, s.target.duration() + s.settle_time);
  EXPECT_DOUBLE_EQ(s.target_accel, 1.0);
  EXPECT_LT(s.target.at(0.5).speed, 0.6);  // still speeding up from the start
}

TEST(TargetPath, LimitedAccelerationRampsIntoAndOutOfStands) {
  // 10 m at 1 m/s, a 2 s wait, 10 m back: with 1 m/s^2 each start and stop takes 1 s and
  // 0.5 m, so every ramp adds 0.5 s to the walk.
  TargetPath path(Pose2{});
  path.walkTo(10.0, 0.0, 1.0);
  path.wait(2.0);
  path.walkTo(0.0, 0.0, 1.0);
  const double instant = path.duration();
  path.limitAcceleration(1.0);
  EXPECT_NEAR(path.duration(), instant + 4 * 0.5, 0.02);
  double previous_speed = 0.0;
  double previous_t = 0.0;
  for (const TargetSample& s : path.samples()) {
    EXPECT_LE(s.speed, 1.0 + 1e-9);
    if (s.t > previous_t) {
      EXPECT_LE(std::abs(s.speed - previous_speed) / (s.t - previous_t), 1.0 + 1e-6) << s.t;
    }
    previous_speed = s.speed;
    previous_t = s.t;
  }
  // Positions are unchanged: half way out, at the turn, and back home.
  EXPECT_NEAR(path.at(path.duration()).pose.x, 0.0, 1e-9);
  EXPECT_NEAR(path.at(5.5).pose.x, 5.0, 1e-6);    // 0.5 s ramp, then 1 m/s
  EXPECT_NEAR(path.at(11.0).pose.x, 10.0, 1e-9);  // standing at the turn
  EXPECT_NEAR(path.length(), 20.0, 1e-9);
}

TEST(Scenario, RejectsBadLegsNamingThem) {
  auto rejected = [](const std::string& yaml) -> std::string {
    try {
      parseScenario(yaml, "test", 1);
    } catch (const ParamError& e) {
      return e.name();
    }
    return "(accepted)";
  };
  EXPECT_EQ(rejected("target: {start: [0, 0], legs: [{jump: 3}]}"), "target.legs[0].jump");
  EXPECT_EQ(rejected("target: {start: [0, 0], legs: []}"), "(accepted)");
  // Misspelt keys are refused, not ignored (one mechanism for every file, issue 12).
  EXPECT_EQ(rejected("target: {start: [0, 0], legs: [{to: [1, 0], sped: 2}]}"),
            "target.legs[0].sped");
  EXPECT_EQ(rejected("target: {start: [0, 0], sped: 2}"), "target.sped");
  EXPECT_EQ(rejected("target: {start: [0, 0]}\ndurration: 3"), "durration");
  EXPECT_EQ(rejected("target: {start: [0, 0], legs: [{to: [1, 0], speed: -1}]}"), "walk.speed");
  EXPECT_EQ(rejected("target: {start: [0]}"), "target.start");
  EXPECT_EQ(rejected("target: {speed: 1}"), "target.start");
  EXPECT_EQ(rejected("target: {start: [0, 0], legs: [{wait: x}]}"), "target.legs[0].wait");
  EXPECT_EQ(rejected("target: {start: [0, 0]}\nduration: -3"), "duration");
  EXPECT_EQ(rejected("name: only"), "scenario");
}

}  // namespace
}  // namespace sim
}  // namespace radio_follow

namespace radio_follow {
namespace sim {
namespace {

TEST(Scenario, ShippedScenariosLoad) {
  for (const char* name :
       {"straight_walk", "outdoor_loop", "stop_and_approach", "random_walk", "static_beacon"}) {
    SCOPED_TRACE(name);
    const Scenario s =
        loadScenarioFile(std::string(RF_CONFIG_DIR) + "/scenarios/" + name + ".yaml", 1);
    EXPECT_GT(s.duration, 0.0);
  }
}

}  // namespace
}  // namespace sim
}  // namespace radio_follow
