// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/control/homing_controller.hpp"

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <functional>
#include <limits>

#include "radio_follow/common/angles.hpp"
#include "radio_follow/common/param_error.hpp"
#include "radio_follow/common/plausibility.hpp"
#include "radio_follow/common/yaml_params.hpp"

namespace radio_follow {
namespace control {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

Pose2 pose(double x, double y, double yaw = 0.0) {
  Pose2 p;
  p.x = x;
  p.y = y;
  p.yaw = yaw;
  return p;
}

/// Azimuth of `target` seen from a board at the centre of a robot at `robot`, facing forward.
double azimuthTo(const Pose2& robot, const Eigen::Vector2d& target) {
  return wrapAngle(std::atan2(target.y() - robot.y, target.x() - robot.x) - robot.yaw);
}

HomingControllerParams uwbParams() {
  HomingControllerParams p;
  p.distance_source = "uwb";
  return p;
}

/// One noise-free reading of `target` from `robot` at time `t`: odometry, range, bearing.
void observe(HomingController& law, const Pose2& robot, const Eigen::Vector2d& target, double t) {
  ASSERT_TRUE(law.onOdometry(robot, t, t).accepted);
  law.onRange((target - robot.position()).norm(), t);
  ASSERT_EQ(law.onBearing(azimuthTo(robot, target), kNaN, t),
            HomingController::BearingResult::kUsed);
}

TEST(HomingController, WaitsWithoutOdometry) {
  HomingController law(HomingControllerParams{});
  EXPECT_EQ(law.onBearing(0.0, -60.0, 0.0), HomingController::BearingResult::kNoOdometry);
  const HomingOutput out = law.compute(0.0);
  EXPECT_EQ(out.state, FollowerState::kWaitingForTarget);
  EXPECT_EQ(out.text, "No odometry, waiting.");
  EXPECT_EQ(out.command.linear, 0.0);
}

TEST(HomingController, StaleOdometryStopsTheRobot) {
  HomingControllerParams params = uwbParams();
  HomingController law(params);
  observe(law, pose(0.0, 0.0), {4.0, 0.0}, 0.0);
  EXPECT_EQ(law.compute(0.1).text, "Homing to the target.");
  const HomingOutput stale = law.compute(params.odom_timeout + 0.1);
  EXPECT_EQ(stale.text, "No odometry, waiting.");
  EXPECT_EQ(stale.command.linear, 0.0);
  EXPECT_EQ(stale.command.angular, 0.0);
}

TEST(HomingController, SearchesWithoutABearingAndCreepsAlongOne) {
  HomingControllerParams params;  // RSSI distance, and bearings without RSSI: no vector goal
  params.search_speed = 0.1;
  HomingController law(params);
  ASSERT_TRUE(law.onOdometry(pose(0.0, 0.0), 0.0, 0.0).accepted);
  HomingOutput out = law.compute(0.0);
  EXPECT_EQ(out.state, FollowerState::kWaitingForTarget);
  EXPECT_EQ(out.text, "Searching for the target.");
  EXPECT_EQ(out.command.linear, 0.0);
  EXPECT_EQ(out.command.angular, 0.0);

  ASSERT_EQ(law.onBearing(0.0, kNaN, 0.0), HomingController::BearingResult::kUsed);
  EXPECT_FALSE(law.goal());
  out = law.compute(0.05);
  EXPECT_EQ(out.text, "Searching for the target.");
  EXPECT_NEAR(out.command.linear, 0.1, 1e-12);  // search_speed, straight ahead
  EXPECT_NEAR(out.command.angular, 0.0, 1e-12);
}

TEST(HomingController, TurnsTowardsTheBearing) {
  HomingController left(uwbParams());
  observe(left, pose(0.0, 0.0), {2.0, 3.0}, 0.0);
  const HomingOutput to_left = left.compute(0.0);
  EXPECT_EQ(to_left.text, "Homing to the target.");
  EXPECT_EQ(to_left.state, FollowerState::kFollowing);
  EXPECT_GT(to_left.command.angular, 0.1);
  EXPECT_GT(to_left.command.linear, 0.0);

  HomingController right(uwbParams());
  observe(right, pose(0.0, 0.0), {2.0, -3.0}, 0.0);
  EXPECT_LT(right.compute(0.0).command.angular, -0.1);
}

TEST(HomingController, BoardMountingRotatesTheBearing) {
  HomingControllerParams params = uwbParams();
  params.board_yaw = kPi / 2.0;  // board looks left
  HomingController law(params);
  ASSERT_TRUE(law.onOdometry(pose(1.0, 1.0), 0.0, 0.0).accepted);
  law.onRange(2.0, 0.0);
  ASSERT_EQ(law.onBearing(0.0, kNaN, 0.0), HomingController::BearingResult::kUsed);
  ASSERT_TRUE(law.goal());
  EXPECT_NEAR(law.goal()->x(), 1.0, 1e-9);
  EXPECT_NEAR(law.goal()->y(), 3.0, 1e-9);
  EXPECT_GT(law.compute(0.0).command.angular, 0.5);
  const auto goal_pose = law.goalPose();
  ASSERT_TRUE(goal_pose);
  EXPECT_NEAR(goal_pose->yaw, kPi / 2.0, 1e-9);  // facing the target from the robot
}

TEST(HomingController, DistanceFromTheRssiModel) {
  HomingControllerParams params;
  params.rssi.rssi_at_1m = -50.0;
  params.rssi.exponent = 2.0;
  HomingController law(params);
  ASSERT_TRUE(law.onOdometry(pose(0.0, 0.0), 0.0, 0.0).accepted);
  law.onBearing(0.0, -50.0 - 20.0 * std::log10(4.0), 0.0);
  ASSERT_TRUE(law.goal());
  EXPECT_EQ(law.homing().source(), HomingSource::kVector);
  EXPECT_NEAR(law.goal()->x(), 4.0, 1e-9);
}

TEST(HomingController, RssiFilterSmoothsAFadeBeforeTheModel) {
  // Ten readings of a tag 4 m ahead, then one 12 dB fade: unfiltered, the fade alone
  // makes the vector goal jump to 16 m; the Kalman filter (gain 0.18) moves it far less.
  const auto lastGoalX = [](RssiFilterParams::Type type) {
    HomingControllerParams params;
    params.rssi.rssi_at_1m = -50.0;
    params.rssi.exponent = 2.0;
    params.rssi_filter.type = type;
    params.homing.tau = 1e-3;  // the vector goal follows the newest distance alone
    HomingController law(params);
    EXPECT_TRUE(law.onOdometry(pose(0.0, 0.0), 0.0, 0.0).accepted);
    const double at_4m = -50.0 - 20.0 * std::log10(4.0);
    for (int i = 0; i < 10; ++i) {
      law.onBearing(0.0, at_4m, 0.0);
    }
    law.onBearing(0.0, kNaN, 0.0);  // no RSSI: refused by the filter, no distance
    law.onBearing(0.0, at_4m - 12.0, 0.0);
    return law.homing().vectorGoal()->x();
  };
  EXPECT_NEAR(lastGoalX(RssiFilterParams::Type::kNone), 16.0, 0.1);
  EXPECT_LT(lastGoalX(RssiFilterParams::Type::kKalman), 6.5);
  EXPECT_NEAR(lastGoalX(RssiFilterParams::Type::kMedian), 4.0, 1e-9);
}

TEST(HomingControllerParams, RssiFilterLoadsFromItsMappingAndRefusesTyposAndBadValues) {
  const MotionLimits limits;
  HomingControllerParams params;
  YamlParams good(YAML::Load("{rssi_filter: {type: median, window: 5}}"));
  params.load(good, limits);
  good.requireAllKnown();
  EXPECT_EQ(params.rssi_filter.type, RssiFilterParams::Type::kMedian);
  EXPECT_EQ(params.rssi_filter.window.window, 5);

  YamlParams typo(YAML::Load("{rssi_filter: {typ: kalman}}"));
  HomingControllerParams().load(typo, limits);
  EXPECT_THROW(typo.requireAllKnown(), ParamError);
  try {
    HomingControllerParams().load(YamlParams(YAML::Load("{rssi_filter: {type: kalmann}}")), limits);
    ADD_FAILURE() << "type kalmann accepted";
  } catch (const ParamError& e) {
    EXPECT_EQ(e.name(), "~rssi_filter/type") << e.what();
  }
}

// The range comes from a module behind and below the board, the robot turned: the goal
// is where that slant range from the module meets the bearing ray, not the range
// measured off from the board (which would put it 0.3 m too far here).
TEST(HomingController, UwbRangeIsPlacedFromItsModulesAntenna) {
  HomingControllerParams params = uwbParams();
  params.board_x = 0.1;
  params.target_height = 0.9;
  HomingController law(params);
  const Pose2 robot = pose(1.0, 2.0, kPi / 2.0);  // facing +y; the board is at (1.0, 2.1)
  const Eigen::Vector2d target(1.0, 5.1);         // 3 m ahead of the board
  const Eigen::Vector3d module(-0.2, 0.0, 0.5);   // in base_link: at (1.0, 1.8), 0.4 m below
  const double range = std::hypot(target.y() - 1.8, 0.9 - 0.5);
  ASSERT_TRUE(law.onOdometry(robot, 0.0, 0.0).accepted);
  law.onRange(range, 0.0, module);
  ASSERT_EQ(law.onBearing(0.0, kNaN, 0.0), HomingController::BearingResult::kUsed);
  ASSERT_TRUE(law.goal());
  EXPECT_NEAR((*law.goal() - target).norm(), 0.0, 1e-9);
  // Without the antenna the same range counts from the board: too far.
  HomingController flat(params);
  ASSERT_TRUE(flat.onOdometry(robot, 0.0, 0.0).accepted);
  flat.onRange(range, 0.0);
  ASSERT_EQ(flat.onBearing(0.0, kNaN, 0.0), HomingController::BearingResult::kUsed);
  EXPECT_NEAR(flat.goal()->y(), 2.1 + range, 1e-9);
  // A non-finite antenna position is refused with its range.
  HomingController refused(params);
  ASSERT_TRUE(refused.onOdometry(robot, 0.0, 0.0).accepted);
  refused.onRange(range, 0.0, Eigen::Vector3d(kNaN, 0.0, 0.0));
  refused.onBearing(0.0, kNaN, 0.0);
  EXPECT_FALSE(refused.goal());
}

TEST(HomingController, StaleUwbRangeGivesNoDistance) {
  HomingControllerParams params = uwbParams();
  HomingController law(params);
  law.onRange(3.0, 0.0);
  ASSERT_TRUE(law.onOdometry(pose(0.0, 0.0), 1.0, 1.0).accepted);
  law.onBearing(0.0, -40.0, 1.0);  // range 1 s old > distance_max_age; the RSSI is not used
  EXPECT_FALSE(law.goal());
  law.onRange(kNaN, 1.0);  // ignored
  law.onRange(-1.0, 1.0);  // ignored
  law.onBearing(0.0, -40.0, 1.0);
  EXPECT_FALSE(law.goal());
}

TEST(HomingController, HybridPicksParallaxOnceTheBaselineIsEnough) {
  HomingControllerParams params = uwbParams();
  HomingController law(params);
  const Eigen::Vector2d target(3.0, 2.0);
  observe(law, pose(0.0, 0.0), target, 0.0);
  EXPECT_EQ(law.homing().source(), HomingSource::kVector);
  observe(law, pose(0.5 * params.homing.min_baseline, 0.0), target, 0.1);
  EXPECT_EQ(law.homing().source(), HomingSource::kVector);  // baseline too short
  observe(law, pose(2.0 * params.homing.min_baseline, 0.0), target, 0.2);
  EXPECT_EQ(law.homing().source(), HomingSource::kParallax);
  ASSERT_TRUE(law.goal());
  EXPECT_NEAR((*law.goal() - target).norm(), 0.0, 1e-6);
}

TEST(HomingController, BearingsOnlyFindAParallaxGoalAfterTheBaseline) {
  HomingController law(HomingControllerParams{});
  const Eigen::Vector2d target(2.0, 1.5);  // rays from x = 0 and 0.3 differ by 0.08 rad
  for (const double x : {0.0, 0.1}) {
    ASSERT_TRUE(law.onOdometry(pose(x, 0.0), x, x).accepted);
    law.onBearing(azimuthTo(pose(x, 0.0), target), kNaN, x);
  }
  EXPECT_FALSE(law.goal());
  EXPECT_EQ(law.compute(0.1).text, "Searching for the target.");
  ASSERT_TRUE(law.onOdometry(pose(0.3, 0.0), 0.3, 0.3).accepted);
  law.onBearing(azimuthTo(pose(0.3, 0.0), target), kNaN, 0.3);
  ASSERT_TRUE(law.goal());
  EXPECT_EQ(law.homing().source(), HomingSource::kParallax);
  EXPECT_NEAR((*law.goal() - target).norm(), 0.0, 1e-6);
}

TEST(HomingController, ArrivesAndStopsAtTheArrivalDistance) {
  // Closed loop on a kinematic unicycle at 10 Hz, noise-free readings.
  const HomingControllerParams params = uwbParams();
  HomingController law(params);
  const Eigen::Vector2d target(3.0, -2.0);
  Pose2 robot = pose(0.0, 0.0, 0.5);
  const double dt = 0.1;
  double t = 0.0;
  HomingOutput out;
  for (; t < 60.0; t += dt) {
    observe(law, robot, target, t);
    out = law.compute(t);
    if (out.state == FollowerState::kArrived) {
      break;
    }
    ASSERT_GT((robot.position() - target).norm(), params.homing.arrival_distance - 0.05);
    robot.x += out.command.linear * std::cos(robot.yaw) * dt;
    robot.y += out.command.linear * std::sin(robot.yaw) * dt;
    robot.yaw = wrapAngle(robot.yaw + out.command.angular * dt);
  }
  ASSERT_EQ(out.state, FollowerState::kArrived)
      << "distance " << (robot.position() - target).norm();
  EXPECT_EQ(out.text, "Arrived at the target.");
  EXPECT_EQ(out.command.linear, 0.0);
  EXPECT_EQ(out.command.angular, 0.0);
  const double distance = (robot.position() - target).norm();
  EXPECT_LT(distance, params.homing.arrival_distance);
  EXPECT_GT(distance, params.homing.arrival_distance - 0.05);  // stopped on reaching it
  EXPECT_LT(t, 30.0);
}

TEST(HomingController, NonFiniteOrImplausibleOdometryIsRefusedAndCounted) {
  HomingController law(uwbParams());
  ASSERT_TRUE(law.onOdometry(pose(1.0, 0.0), 0.0, 0.0).accepted);
  EXPECT_FALSE(law.onOdometry(pose(kNaN, 0.0), 0.1, 0.1).accepted);
  EXPECT_FALSE(law.onOdometry(pose(2.0, 0.0), 5.0, 0.1).accepted);  // from the future
  // Finite but no robot's odometry: 1.8e308 m made the goal inf (issue 34's fuzzer).
  EXPECT_FALSE(law.onOdometry(pose(0.0, 1.797e308), 0.1, 0.1).accepted);
  EXPECT_FALSE(law.onOdometry(pose(kMaxOdometryCoordinate * 1.01, 0.0), 0.1, 0.1).accepted);
  EXPECT_EQ(law.odometryRefused(), 4u);
  law.onRange(2.0, 0.1);
  law.onBearing(0.0, kNaN, 0.1);
  ASSERT_TRUE(law.goal());
  EXPECT_NEAR(law.goal()->x(), 3.0, 1e-9);  // from the last good pose
}

TEST(HomingController, ClockJumpForgetsTheTrack) {
  HomingController law(uwbParams());
  observe(law, pose(0.0, 0.0), {3.0, 0.0}, 10.0);
  ASSERT_TRUE(law.goal());
  const auto result = law.onOdometry(pose(0.0, 0.0), 1.0, 1.0);
  EXPECT_TRUE(result.clock_jumped);
  EXPECT_TRUE(result.accepted);
  EXPECT_FALSE(law.goal());
}

TEST(HomingController, NonFiniteAzimuthIsNotUsed) {
  HomingController law(uwbParams());
  ASSERT_TRUE(law.onOdometry(pose(0.0, 0.0), 0.0, 0.0).accepted);
  law.onRange(2.0, 0.0);
  EXPECT_EQ(law.onBearing(kNaN, kNaN, 0.0), HomingController::BearingResult::kNotFinite);
  EXPECT_FALSE(law.goal());
}

/// Constructing with one field changed throws ParamError naming `name`.
void expectParamError(const std::function<void(HomingControllerParams&)>& change,
                      const std::string& name) {
  HomingControllerParams params;
  change(params);
  try {
    HomingController law(params);
    ADD_FAILURE() << "no ParamError for " << name;
  } catch (const ParamError& e) {
    EXPECT_EQ(e.name(), name) << e.what();
  }
}

TEST(HomingControllerParams, BadValuesThrowNamingTheParameter) {
  EXPECT_NO_THROW(HomingController{HomingControllerParams{}});
  expectParamError([](auto& p) { p.distance_source = "sonar"; }, "~distance_source");
  expectParamError([](auto& p) { p.board_x = kNaN; }, "~board_x");
  expectParamError([](auto& p) { p.board_yaw = std::numeric_limits<double>::infinity(); },
                   "~board_yaw");
  expectParamError([](auto& p) { p.distance_max_age = 0.0; }, "~distance_max_age");
  expectParamError([](auto& p) { p.odom_timeout = -1.0; }, "~odom_timeout");
  expectParamError([](auto& p) { p.search_speed = -0.1; }, "~search_speed");
  expectParamError([](auto& p) { p.search_speed = kNaN; }, "~search_speed");
  expectParamError([](auto& p) { p.rssi.exponent = 0.0; }, "~rssi_exponent");
  expectParamError([](auto& p) { p.homing.k = 1.5; }, "~kohonen_k");
  expectParamError([](auto& p) { p.homing.arrival_distance = 0.0; }, "~arrival_distance");
  expectParamError([](auto& p) { p.homing.max_linear = 0.0; }, "~max_linear");
  expectParamError([](auto& p) { p.rssi_filter.window.window = 0; }, "~rssi_filter/window");
  expectParamError([](auto& p) { p.rssi_filter.kalman.process_noise = 0.0; },
                   "~rssi_filter/process_noise");
  expectParamError([](auto& p) { p.rssi_filter.kalman.measurement_noise = kNaN; },
                   "~rssi_filter/measurement_noise");
}

}  // namespace
}  // namespace control
}  // namespace radio_follow
