// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/control/follow_metrics.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace radio_follow {
namespace control {
namespace {

/// The person walks along +x at 1 m/s; the robot trails `lag` metres behind at a
/// lateral offset; the estimate is off by `estimate_error` in x.
FollowMetrics straightRun(double lag, double lateral, double estimate_error) {
  FollowMetrics metrics{FollowSettings{}};
  for (int i = 0; i <= 400; ++i) {  // 20 s at 20 Hz
    FollowSample s;
    s.t = i * 0.05;
    s.target_x = 2.0 + s.t;
    s.target_speed = 1.0;
    s.robot_x = s.target_x - lag;
    s.robot_y = lateral;
    s.cmd_linear = 1.0;
    s.truth_x = lag;
    s.truth_y = -lateral;
    s.estimate_x = lag + estimate_error;
    s.estimate_y = -lateral;
    metrics.add(s);
  }
  return metrics;
}

TEST(FollowMetrics, PerfectFollowerScoresPerfectly) {
  const FollowReport r = straightRun(1.6, 0.0, 0.0).report();
  EXPECT_NEAR(r.duration, 20.0, 1e-9);
  EXPECT_NEAR(r.min_gap_while_moving, 1.6, 1e-9);
  EXPECT_DOUBLE_EQ(r.gap_within_tolerance, 1.0);
  EXPECT_GT(r.gap_samples, 280);  // after the 5 s settle time
  EXPECT_NEAR(r.estimate_error_median, 0.0, 1e-12);
  EXPECT_NEAR(r.path_deviation_median, 0.0, 1e-9);
  EXPECT_GT(r.path_samples, 200);
  EXPECT_NEAR(r.robot_distance, 20.0, 1e-9);
}

TEST(FollowMetrics, AWorkingClosedLoopPasses) {
  const FollowReport r = straightRun(1.6, 0.0, 0.0).report();
  EXPECT_TRUE(r.failures.empty());
  EXPECT_NE(r.toJson().find("\"passed\": true"), std::string::npos);
}

// What the review saw: a launch that ran to the end, exit 0, the robot never moved.
TEST(FollowMetrics, ARobotThatNeverMovesOrNeverHasAnEstimateFails) {
  FollowMetrics metrics{FollowSettings{}};
  for (int i = 0; i <= 400; ++i) {
    FollowSample s;
    s.t = i * 0.05;
    s.target_x = 2.0 + s.t;  // walks 20 m away from a robot standing at 0
    s.target_speed = 1.0;
    s.estimate_status = "AMBIGUOUS";
    metrics.add(s);
  }
  const FollowReport r = metrics.report();
  ASSERT_EQ(r.failures.size(), 2u);
  EXPECT_NE(r.failures[0].find("never moved"), std::string::npos) << r.failures[0];
  EXPECT_NE(r.failures[1].find("never became usable"), std::string::npos) << r.failures[1];
  EXPECT_DOUBLE_EQ(r.estimate_status_share.at("AMBIGUOUS"), 1.0);
  const std::string json = r.toJson();
  EXPECT_NE(json.find("\"passed\": false"), std::string::npos) << json;
  EXPECT_NE(json.find("never moved"), std::string::npos) << json;
  EXPECT_TRUE(FollowMetrics{FollowSettings{}}.report().failures.size() == 1u);  // no samples
}

// A person standing at the follow distance: a robot that stays put is right.
TEST(FollowMetrics, StandingStillIsNoFailureWhenThereWasNothingToDo) {
  FollowMetrics metrics{FollowSettings{}};
  for (int i = 0; i <= 100; ++i) {
    FollowSample s;
    s.t = i * 0.05;
    s.target_x = 1.6;
    s.truth_x = 1.6;
    s.estimate_x = 1.6;
    s.estimate_y = 0.0;
    metrics.add(s);
  }
  EXPECT_TRUE(metrics.report().failures.empty());
}

TEST(FollowMetrics, GapOutsideToleranceIsMeasured) {
  // 2.5 m behind: never within 0.3 m of 1.6 m, so the robot never counts as following.
  const FollowReport r = straightRun(2.5, 0.0, 0.0).report();
  EXPECT_DOUBLE_EQ(r.gap_within_tolerance, 0.0);
  EXPECT_TRUE(std::isnan(r.path_deviation_max));
}

TEST(FollowMetrics, LateralOffsetAndEstimateErrorAreMeasured) {
  const FollowReport r = straightRun(1.6, 0.4, 0.2).report();
  EXPECT_DOUBLE_EQ(r.gap_within_tolerance, 1.0);
  EXPECT_NEAR(r.path_deviation_median, 0.4, 1e-9);
  EXPECT_NEAR(r.path_deviation_max, 0.4, 1e-9);
  EXPECT_NEAR(r.estimate_error_p95, 0.2, 1e-9);
}

TEST(FollowMetrics, GapStatisticsStartOnceTheRobotHasCaughtUp) {
  // The robot starts 6 m behind and closes at 0.5 m/s until it holds 1.6 m (after 8.8 s);
  // from then on it is perfect, so the fraction is 1 and the window starts at 8.8 s.
  FollowMetrics metrics{FollowSettings{}};
  for (int i = 0; i <= 600; ++i) {
    FollowSample s;
    s.t = i * 0.05;
    s.target_x = 6.0 + s.t;
    s.target_speed = 1.0;
    s.robot_x = s.target_x - std::max(1.6, 6.0 - 0.5 * s.t);
    s.cmd_linear = 1.0;
    metrics.add(s);
  }
  const FollowReport r = metrics.report();
  EXPECT_DOUBLE_EQ(r.gap_within_tolerance, 1.0);
  EXPECT_NEAR(r.gap_window_start, (6.0 - 1.9) / 0.5, 0.051);
  EXPECT_NEAR(r.gap_samples, (30.0 - 8.2) / 0.05, 2.0);
}

TEST(FollowMetrics, ARobotThatNeverCatchesUpHasNoGapWindow) {
  const FollowReport r = straightRun(2.5, 0.0, 0.0).report();
  EXPECT_EQ(r.gap_samples, 0);
  EXPECT_TRUE(std::isnan(r.gap_window_start));
}

TEST(FollowMetrics, CornerCuttingIsExcludedButStraightDeviationIsNot) {
  // The person walks 10 m along +x, turns 90 deg left, walks 10 m along +y. The robot
  // cuts the corner diagonally (far off the path only near the turn).
  FollowMetrics metrics{FollowSettings{}};
  auto personAt = [](double d) {
    return d <= 10.0 ? std::make_pair(d, 0.0) : std::make_pair(10.0, d - 10.0);
  };
  for (int i = 0; i <= 600; ++i) {
    FollowSample s;
    s.t = i * 0.05;
    const double walked = 2.0 + s.t * 0.8;
    std::tie(s.target_x, s.target_y) = personAt(walked);
    const double behind = walked - 1.6;
    std::tie(s.robot_x, s.robot_y) = personAt(behind);
    if (behind > 9.0 && behind < 11.0) {  // cut the corner by up to ~0.7 m
      const double u = (behind - 9.0) / 2.0;
      s.robot_x = 9.0 + u;
      s.robot_y = u;
    }
    s.target_speed = 0.8;
    s.cmd_linear = 0.8;
    metrics.add(s);
  }
  const FollowReport r = metrics.report();
  EXPECT_LT(r.path_deviation_max, 0.05);
  EXPECT_GT(r.path_samples, 300);
}

TEST(FollowMetrics, StandingStillIsNotMoving) {
  FollowMetrics metrics{FollowSettings{}};
  FollowSample s;
  s.target_x = 0.5;  // far too close, but the robot is not commanded to move
  metrics.add(s);
  const FollowReport r = metrics.report();
  EXPECT_TRUE(std::isinf(r.min_gap_while_moving));
  EXPECT_NEAR(r.min_gap, 0.5, 1e-12);
  EXPECT_NE(r.toJson().find("\"min_gap_while_moving_m\": null"), std::string::npos);
}

TEST(FollowMetrics, FinalGapIsTheLastSamplesDistance) {
  FollowMetrics metrics{FollowSettings{}};
  FollowSample s;
  s.target_x = 6.0;
  s.target_y = -4.0;
  metrics.add(s);  // start: 7.2 m away
  s.t = 20.0;
  s.robot_x = 5.8;
  s.robot_y = -3.9;
  metrics.add(s);
  const FollowReport r = metrics.report();
  EXPECT_NEAR(r.final_gap, std::hypot(0.2, 0.1), 1e-12);
  EXPECT_NE(r.toJson().find("\"final_gap_m\": 0.2236"), std::string::npos);
}

TEST(FollowMetrics, ClearanceIsInfiniteWithoutObstaclesAndTheFirstTouchIsTheCollision) {
  FollowMetrics metrics = straightRun(1.6, 0.0, 0.0);
  FollowReport r = metrics.report();
  EXPECT_TRUE(std::isinf(r.min_clearance) && r.min_clearance > 0.0) << "no obstacles";
  EXPECT_FALSE(r.collided);
  EXPECT_TRUE(std::isnan(r.collision_time));
  EXPECT_NE(r.toJson().find("\"min_clearance_m\": null"), std::string::npos);
  EXPECT_NE(r.toJson().find("\"collided\": false"), std::string::npos);

  metrics.addClearance(1.0, 0.5);
  metrics.addClearance(1.01, 0.02);
  r = metrics.report();
  EXPECT_DOUBLE_EQ(r.min_clearance, 0.02);
  EXPECT_FALSE(r.collided) << "close is not touching";
  metrics.addClearance(1.02, -0.01);
  metrics.addClearance(1.03, -0.03);
  r = metrics.report();
  EXPECT_DOUBLE_EQ(r.min_clearance, -0.03);
  EXPECT_TRUE(r.collided);
  EXPECT_DOUBLE_EQ(r.collision_time, 1.02) << "the first touch";
  EXPECT_NE(r.toJson().find("\"collided\": true"), std::string::npos);
  EXPECT_NE(r.toJson().find("\"collision_time_s\": 1.02"), std::string::npos);
}

TEST(FollowMetrics, CsvHasAHeaderAndOneRowPerSample) {
  const FollowMetrics metrics = straightRun(1.6, 0.0, 0.0);
  const std::string csv = metrics.toCsv();
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 402);
  EXPECT_EQ(csv.rfind("t,robot_x", 0), 0u);
}

}  // namespace
}  // namespace control
}  // namespace radio_follow
