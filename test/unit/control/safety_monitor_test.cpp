// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/control/safety_monitor.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <map>
#include <random>
#include <string>

#include "radio_follow/common/param_error.hpp"

namespace radio_follow {
namespace control {
namespace {

SafetyMonitor enabledMonitor(const SafetyParams& params = SafetyParams()) {
  SafetyMonitor monitor(params);
  monitor.setEnabled(true);
  return monitor;
}

TEST(SafetyMonitor, StartsDisabled) {
  SafetyMonitor monitor{SafetyParams()};
  monitor.onRange(0.0, "a", 3.0);
  monitor.onEstimate(0.0, true);
  const SafetyDecision d = monitor.evaluate(0.1);
  EXPECT_FALSE(d.may_move);
  EXPECT_EQ(d.reason, StopReason::kDisabled);
}

TEST(SafetyMonitor, NewSafeDistanceAppliesAndAnInvalidOneIsRefused) {
  SafetyMonitor monitor = enabledMonitor();
  monitor.onRange(0.0, "a", 2.0);
  monitor.onEstimate(0.0, true);
  ASSERT_TRUE(monitor.evaluate(0.1).may_move);
  SafetyParams wider;
  wider.safe_distance = 2.5;
  monitor.setParams(wider);
  monitor.onRange(0.2, "a", 2.0);
  EXPECT_EQ(monitor.evaluate(0.2).reason, StopReason::kTooClose);
  SafetyParams invalid = wider;
  invalid.safe_distance = -1.0;
  EXPECT_THROW(monitor.setParams(invalid), ParamError);
  monitor.onRange(0.3, "a", 2.0);
  EXPECT_FALSE(monitor.evaluate(0.3).may_move);  // still 2.5 m
}

TEST(SafetyMonitor, MovesWithFreshFarRangeAndEstimate) {
  SafetyMonitor monitor = enabledMonitor();
  monitor.onRange(0.0, "a", 3.0);
  monitor.onEstimate(0.0, true);
  EXPECT_TRUE(monitor.evaluate(0.1).may_move);
}

TEST(SafetyMonitor, CloseRangeStopsEvenWithAGoodEstimate) {
  SafetyMonitor monitor = enabledMonitor();
  monitor.onRange(0.0, "a", 3.0);
  monitor.onEstimate(0.0, true);
  EXPECT_TRUE(monitor.onRange(0.05, "b", 1.0));
  const SafetyDecision d = monitor.evaluate(0.1);
  EXPECT_FALSE(d.may_move);
  EXPECT_EQ(d.reason, StopReason::kTooClose);
}

TEST(SafetyMonitor, NanRangeCountsAsTooClose) {
  SafetyMonitor monitor = enabledMonitor();
  EXPECT_TRUE(monitor.onRange(0.0, "a", std::numeric_limits<double>::quiet_NaN()));
}

TEST(SafetyMonitor, ResumesOnlyAfterHoldTime) {
  SafetyParams params;
  params.hold_time = 1.0;
  SafetyMonitor monitor = enabledMonitor(params);
  monitor.onRange(0.0, "a", 1.0);
  monitor.onEstimate(0.0, true);
  EXPECT_FALSE(monitor.evaluate(0.0).may_move);
  monitor.onRange(0.2, "a", 2.0);
  monitor.onEstimate(0.5, true);
  const SafetyDecision held = monitor.evaluate(0.6);
  EXPECT_FALSE(held.may_move);
  EXPECT_EQ(held.reason, StopReason::kTooClose);
  monitor.onRange(1.0, "a", 2.0);
  monitor.onEstimate(1.0, true);
  EXPECT_TRUE(monitor.evaluate(1.05).may_move);
}

TEST(SafetyMonitor, StaleAndLostEstimatesStop) {
  SafetyMonitor monitor = enabledMonitor();
  monitor.onRange(0.0, "a", 3.0);
  EXPECT_EQ(monitor.evaluate(0.0).reason, StopReason::kNoEstimateYet);
  monitor.onEstimate(0.0, true);
  monitor.onRange(0.6, "a", 3.0);
  EXPECT_EQ(monitor.evaluate(0.6).reason, StopReason::kEstimateStale);
  monitor.onEstimate(0.7, false);
  EXPECT_EQ(monitor.evaluate(0.7).reason, StopReason::kTargetLost);
}

TEST(SafetyMonitor, SilentRangeSourcesStop) {
  SafetyMonitor monitor = enabledMonitor();
  monitor.onRange(0.0, "a", 3.0);
  monitor.onEstimate(1.5, true);
  EXPECT_EQ(monitor.evaluate(1.5).reason, StopReason::kRangesSilent);
}

TEST(SafetyMonitor, ForgetsASilentCloseSourceWhileOthersReport) {
  SafetyParams params;
  params.hold_time = 0.0;
  SafetyMonitor monitor = enabledMonitor(params);
  monitor.onRange(0.0, "dead", 1.0);
  monitor.onRange(1.5, "alive", 3.0);
  monitor.onEstimate(1.5, true);
  EXPECT_TRUE(monitor.evaluate(1.6).may_move);
}

TEST(SafetyMonitor, WithoutRangeWatchOnlyTheEstimateCounts) {
  SafetyParams params;
  params.watch_ranges = false;
  SafetyMonitor monitor = enabledMonitor(params);
  monitor.onEstimate(0.0, true);
  EXPECT_TRUE(monitor.evaluate(0.1).may_move);
}

TEST(SafetyMonitor, NearestRangeIsTheSmallestFreshOne) {
  SafetyMonitor monitor = enabledMonitor();  // range_timeout 1 s
  EXPECT_EQ(monitor.nearestRange(0.0), std::numeric_limits<double>::infinity());
  monitor.onRange(0.0, "a", 1.5);
  monitor.onRange(0.5, "b", 2.0);
  EXPECT_EQ(monitor.nearestRange(0.6), 1.5);
  EXPECT_EQ(monitor.nearestRange(1.2), 2.0);  // "a" is older than range_timeout
  EXPECT_EQ(monitor.nearestRange(2.0), std::numeric_limits<double>::infinity());
}

TEST(SafetyParams, ValidateRejectsNegativeSafeDistance) {
  SafetyParams params;
  params.safe_distance = -1.0;
  EXPECT_THROW(params.validate(), ParamError);
  EXPECT_NO_THROW(SafetyParams().validate());
}

// Property: over random event sequences, whenever the newest range of any source heard
// within range_timeout is below safe_distance, or the newest estimate is older than
// estimate_timeout, or the monitor is disabled, the gated command is exactly zero.
TEST(SafetyMonitorProperty, StopConditionAlwaysGivesZeroCommand) {
  std::mt19937 rng(12345);
  std::uniform_real_distribution<double> range_dist(0.0, 4.0);
  std::uniform_real_distribution<double> dt_dist(0.0, 0.3);
  std::uniform_real_distribution<double> cmd_dist(-2.0, 2.0);
  std::uniform_int_distribution<int> event_dist(0, 9);
  const char* sources[] = {"m1", "m2", "m3"};
  int checked_stops = 0;
  int moves = 0;
  for (int run = 0; run < 200; ++run) {
    SafetyParams params;
    params.hold_time = std::uniform_real_distribution<double>(0.0, 1.0)(rng);
    SafetyMonitor monitor(params);
    monitor.setEnabled(true);
    std::map<std::string, std::pair<double, double>> newest;  // source -> (time, range)
    double estimate_stamp = -1e9;
    bool enabled = true;
    double now = 0.0;
    for (int step = 0; step < 300; ++step) {
      now += dt_dist(rng);
      const int event = event_dist(rng);
      if (event < 5) {
        const std::string source = sources[event % 3];
        const double range = range_dist(rng);
        monitor.onRange(now, source, range);
        newest[source] = {now, range};
      } else if (event < 8) {
        // Stamps may lag the receive time, as estimates do.
        const double stamp = now - dt_dist(rng);
        monitor.onEstimate(stamp, true);
        estimate_stamp = std::max(estimate_stamp, stamp);
      } else if (event == 8) {
        enabled = !enabled;
        monitor.setEnabled(enabled);
      }
      bool stop = !enabled || now - estimate_stamp > params.estimate_timeout;
      bool any_fresh = false;
      for (const auto& [source, entry] : newest) {
        if (now - entry.first <= params.range_timeout) {
          any_fresh = true;
          stop = stop || entry.second < params.safe_distance;
        }
      }
      stop = stop || !any_fresh;
      const VelocityCommand cmd =
          gateCommand(monitor.evaluate(now), VelocityCommand{cmd_dist(rng), cmd_dist(rng)});
      if (stop) {
        ++checked_stops;
        ASSERT_TRUE(cmd.isZero()) << "run " << run << " step " << step << " t=" << now;
      } else if (!cmd.isZero()) {
        ++moves;
      }
    }
  }
  // The generator must exercise both outcomes, or the property says nothing.
  EXPECT_GT(checked_stops, 1000);
  EXPECT_GT(moves, 100);
}

}  // namespace
}  // namespace control
}  // namespace radio_follow
