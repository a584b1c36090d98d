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
  monitor.onRange(0.0, 0.0, "a", 3.0);
  monitor.onEstimate(0.0, 0.0, EstimateQuality::kUsable);
  const SafetyDecision d = monitor.evaluate(0.1);
  EXPECT_FALSE(d.may_move);
  EXPECT_EQ(d.reason, StopReason::kDisabled);
}

TEST(SafetyMonitor, NewSafeDistanceAppliesAndAnInvalidOneIsRefused) {
  SafetyMonitor monitor = enabledMonitor();
  monitor.onRange(0.0, 0.0, "a", 2.0);
  monitor.onEstimate(0.0, 0.0, EstimateQuality::kUsable);
  ASSERT_TRUE(monitor.evaluate(0.1).may_move);
  SafetyParams wider;
  wider.safe_distance = 2.5;
  monitor.setParams(wider);
  monitor.onRange(0.2, 0.2, "a", 2.0);
  EXPECT_EQ(monitor.evaluate(0.2).reason, StopReason::kTooClose);
  SafetyParams invalid = wider;
  invalid.safe_distance = -1.0;
  EXPECT_THROW(monitor.setParams(invalid), ParamError);
  monitor.onRange(0.3, 0.3, "a", 2.0);
  EXPECT_FALSE(monitor.evaluate(0.3).may_move);  // still 2.5 m
}

TEST(SafetyMonitor, MovesWithFreshFarRangeAndEstimate) {
  SafetyMonitor monitor = enabledMonitor();
  monitor.onRange(0.0, 0.0, "a", 3.0);
  monitor.onEstimate(0.0, 0.0, EstimateQuality::kUsable);
  EXPECT_TRUE(monitor.evaluate(0.1).may_move);
}

TEST(SafetyMonitor, CloseRangeStopsEvenWithAGoodEstimate) {
  SafetyMonitor monitor = enabledMonitor();
  monitor.onRange(0.0, 0.0, "a", 3.0);
  monitor.onEstimate(0.0, 0.0, EstimateQuality::kUsable);
  EXPECT_TRUE(monitor.onRange(0.05, 0.05, "b", 1.0));
  const SafetyDecision d = monitor.evaluate(0.1);
  EXPECT_FALSE(d.may_move);
  EXPECT_EQ(d.reason, StopReason::kTooClose);
}

TEST(SafetyMonitor, NanRangeCountsAsTooClose) {
  SafetyMonitor monitor = enabledMonitor();
  EXPECT_TRUE(monitor.onRange(0.0, 0.0, "a", std::numeric_limits<double>::quiet_NaN()));
}

TEST(SafetyMonitor, ResumesOnlyAfterHoldTime) {
  SafetyParams params;
  params.hold_time = 1.0;
  SafetyMonitor monitor = enabledMonitor(params);
  monitor.onRange(0.0, 0.0, "a", 1.0);
  monitor.onEstimate(0.0, 0.0, EstimateQuality::kUsable);
  EXPECT_FALSE(monitor.evaluate(0.0).may_move);
  monitor.onRange(0.2, 0.2, "a", 2.0);
  monitor.onEstimate(0.5, 0.5, EstimateQuality::kUsable);
  const SafetyDecision held = monitor.evaluate(0.6);
  EXPECT_FALSE(held.may_move);
  EXPECT_EQ(held.reason, StopReason::kTooClose);
  monitor.onRange(1.0, 1.0, "a", 2.0);
  monitor.onEstimate(1.0, 1.0, EstimateQuality::kUsable);
  EXPECT_TRUE(monitor.evaluate(1.05).may_move);
}

TEST(SafetyMonitor, StaleAndLostEstimatesStop) {
  SafetyMonitor monitor = enabledMonitor();
  monitor.onRange(0.0, 0.0, "a", 3.0);
  EXPECT_EQ(monitor.evaluate(0.0).reason, StopReason::kNoEstimateYet);
  monitor.onEstimate(0.0, 0.0, EstimateQuality::kUsable);
  monitor.onRange(0.6, 0.6, "a", 3.0);
  EXPECT_EQ(monitor.evaluate(0.6).reason, StopReason::kEstimateStale);
  monitor.onEstimate(0.7, 0.7, EstimateQuality::kLost);
  EXPECT_EQ(monitor.evaluate(0.7).reason, StopReason::kTargetLost);
}

TEST(SafetyMonitor, SilentRangeSourcesStop) {
  SafetyMonitor monitor = enabledMonitor();
  monitor.onRange(0.0, 0.0, "a", 3.0);
  monitor.onEstimate(1.5, 1.5, EstimateQuality::kUsable);
  EXPECT_EQ(monitor.evaluate(1.5).reason, StopReason::kRangesSilent);
}

TEST(SafetyMonitor, ForgetsASilentCloseSourceWhileOthersReport) {
  SafetyParams params;
  params.hold_time = 0.0;
  SafetyMonitor monitor = enabledMonitor(params);
  monitor.onRange(0.0, 0.0, "dead", 1.0);
  monitor.onRange(1.5, 1.5, "alive", 3.0);
  monitor.onEstimate(1.5, 1.5, EstimateQuality::kUsable);
  EXPECT_TRUE(monitor.evaluate(1.6).may_move);
}

TEST(SafetyMonitor, WithoutRangeWatchOnlyTheEstimateCounts) {
  SafetyParams params;
  params.watch_ranges = false;
  SafetyMonitor monitor = enabledMonitor(params);
  monitor.onEstimate(0.0, 0.0, EstimateQuality::kUsable);
  EXPECT_TRUE(monitor.evaluate(0.1).may_move);
}

TEST(SafetyMonitor, NearestRangeIsTheSmallestFreshOne) {
  SafetyMonitor monitor = enabledMonitor();  // range_timeout 1 s
  EXPECT_EQ(monitor.nearestRange(0.0), std::numeric_limits<double>::infinity());
  monitor.onRange(0.0, 0.0, "a", 1.5);
  monitor.onRange(0.5, 0.5, "b", 2.0);
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

TEST(SafetyParams, PhysicalBoundsNotJustSigns) {
  const auto refused = [](auto change) {
    SafetyParams p;
    change(p);
    EXPECT_THROW(p.validate(), ParamError);
  };
  refused([](SafetyParams& p) { p.safe_distance = 0.0; });
  refused([](SafetyParams& p) { p.safe_distance = 0.1; });
  refused([](SafetyParams& p) { p.estimate_timeout = 1e9; });
  refused([](SafetyParams& p) { p.range_timeout = 60.0; });
  refused([](SafetyParams& p) { p.hold_time = 1e6; });
}

// One estimate stamped in the future must not keep the robot driving after the locator
// dies (it used to win the "newest stamp" comparison for as long as it was ahead).
TEST(SafetyMonitorTime, EstimateFromTheFutureIsRefusedAndStops) {
  SafetyMonitor monitor = enabledMonitor();
  monitor.onRange(0.0, 0.0, "a", 3.0);
  monitor.onEstimate(0.0, 0.0, EstimateQuality::kUsable);
  ASSERT_TRUE(monitor.evaluate(0.05).may_move);
  EXPECT_FALSE(monitor.onEstimate(30.0, 0.1, EstimateQuality::kUsable));  // 29.9 s ahead
  monitor.onRange(0.1, 0.1, "a", 3.0);
  EXPECT_EQ(monitor.evaluate(0.15).reason, StopReason::kFutureStamp);
  // The locator is dead from here on; ranges keep coming. Never moves again.
  for (double t = 0.2; t < 10.0; t += 0.05) {
    monitor.onRange(t, t, "a", 3.0);
    ASSERT_FALSE(monitor.evaluate(t).may_move) << "t=" << t;
  }
  EXPECT_EQ(monitor.time().futureRefused(), 1u);
}

TEST(SafetyMonitorTime, RangeFromTheFutureStopsAtOnce) {
  SafetyMonitor monitor = enabledMonitor();
  monitor.onRange(0.0, 0.0, "a", 3.0);
  monitor.onEstimate(0.0, 0.0, EstimateQuality::kUsable);
  EXPECT_TRUE(monitor.onRange(5.0, 0.1, "a", 3.0));
  EXPECT_FALSE(monitor.evaluate(0.1).may_move);
  // Within tolerance (another machine's clock a few ms ahead) is fine.
  SafetyMonitor skewed = enabledMonitor();
  EXPECT_FALSE(skewed.onRange(0.02, 0.0, "a", 3.0));
}

// Issue 33: on simulated time a busy controller's clock trails the locator's by tens of
// ms times the time factor; such a lead must not stop the robot, and must not keep the
// estimate fresh for longer either (its age runs from its receipt).
TEST(SafetyMonitorTime, ASimulatedClocksLagIsToleratedButNeverExtendsFreshness) {
  SafetyMonitor monitor = enabledMonitor();  // estimate_timeout 0.5 s
  monitor.setFutureTolerance(kSimFutureStampTolerance);
  monitor.onRange(10.3, 10.0, "a", 3.0);
  EXPECT_TRUE(monitor.onEstimate(10.3, 10.0, EstimateQuality::kUsable));  // 0.3 s ahead
  EXPECT_TRUE(monitor.evaluate(10.45).may_move);
  EXPECT_FALSE(monitor.evaluate(10.55).may_move);  // 0.55 s after receipt: stale
  EXPECT_EQ(monitor.time().futureRefused(), 0u);
  // Truly ahead (beyond the simulated clock's tolerance) still stops.
  EXPECT_FALSE(monitor.onEstimate(11.2, 10.6, EstimateQuality::kUsable));
  EXPECT_FALSE(monitor.evaluate(10.6).may_move);
  EXPECT_EQ(monitor.time().futureRefused(), 1u);
}

// A short range that arrives late (stamp older than range_timeout) used to stop the robot
// for one tick in three: the hold ran from its stamp, already in the past.
TEST(SafetyMonitorTime, StaleShortRangeHoldsFromItsReceiveTimeWithoutFlapping) {
  SafetyMonitor monitor = enabledMonitor();  // hold_time 1 s, range_timeout 1 s
  double t = 0.0;
  for (; t < 2.0; t += 0.1) {
    monitor.onRange(t, t, "a", 3.0);
    monitor.onEstimate(t, t, EstimateQuality::kUsable);
  }
  ASSERT_TRUE(monitor.evaluate(t).may_move);
  const double received = t;
  EXPECT_TRUE(monitor.onRange(received - 1.5, received, "b", 0.8));
  for (; t < received + 1.0 - 1e-9; t += 0.05) {
    monitor.onRange(t, t, "a", 3.0);
    monitor.onEstimate(t, t, EstimateQuality::kUsable);
    ASSERT_FALSE(monitor.evaluate(t).may_move) << "t=" << t;
  }
  monitor.onRange(t + 0.05, t + 0.05, "a", 3.0);
  monitor.onEstimate(t + 0.05, t + 0.05, EstimateQuality::kUsable);
  EXPECT_TRUE(monitor.evaluate(t + 0.05).may_move);
}

// A bag looped under /use_sim_time: the clock goes from 100 s back to 0 s. The old
// stamps must not freeze the monitor (nothing would ever be newer) nor be trusted.
TEST(SafetyMonitorTime, ClockJumpBackResetsInsteadOfFreezing) {
  SafetyMonitor monitor = enabledMonitor();
  for (double t = 99.0; t <= 100.0; t += 0.1) {
    monitor.onRange(t, t, "a", 3.0);
    monitor.onEstimate(t, t, EstimateQuality::kUsable);
  }
  ASSERT_TRUE(monitor.evaluate(100.0).may_move);
  EXPECT_FALSE(monitor.evaluate(0.0).may_move);
  EXPECT_EQ(monitor.time().clockJumps(), 1u);
  double t = 0.05;
  for (; t < 1.0; t += 0.05) {
    monitor.onRange(t, t, "a", 3.0);
    monitor.onEstimate(t, t, EstimateQuality::kUsable);
    ASSERT_FALSE(monitor.evaluate(t).may_move) << "held after the jump, t=" << t;
  }
  for (; t < 1.3; t += 0.05) {
    monitor.onRange(t, t, "a", 3.0);
    monitor.onEstimate(t, t, EstimateQuality::kUsable);
  }
  EXPECT_TRUE(monitor.evaluate(t).may_move);  // resumed on the new clock
}

// Property over adversarial stamps (future, past, duplicates, clock jumps back) and
// values (NaN, short): whenever the monitor lets the robot move,
//  - an estimate was received within estimate_timeout (+ tolerance) whose stamp was not
//    from the future and is itself within estimate_timeout of now;
//  - no stamp from the future, no short or NaN range and no clock jump was received in
//    the last hold_time;
//  - at least one range stamped within range_timeout was received.
TEST(SafetyMonitorProperty, AdversarialStampsNeverLetItMoveUnsafely) {
  std::mt19937 rng(4242);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int moves = 0;
  int events = 0;
  for (int run = 0; run < 300; ++run) {
    SafetyParams params;
    SafetyMonitor monitor(params);
    monitor.setEnabled(true);
    double now = 10.0;
    double last_hazard = -1e9;  // receive time of a future stamp / short range / jump
    double last_good_estimate_stamp = -1e9;
    double last_good_estimate_rx = -1e9;
    double last_fresh_range_stamp = -1e9;
    for (int step = 0; step < 400; ++step) {
      const double u = unit(rng);
      if (u < 0.01 && step > 0) {
        now -= 5.0 + 20.0 * unit(rng);  // jump back
        last_hazard = now;
        last_good_estimate_stamp = last_good_estimate_rx = -1e9;
        last_fresh_range_stamp = -1e9;
      } else {
        now += 0.02 + 0.1 * unit(rng);
      }
      // Stamp: mostly fresh, sometimes old, sometimes far or slightly in the future.
      const double kind = unit(rng);
      double stamp = now - 0.05 * unit(rng);
      if (kind < 0.05) {
        stamp = now + 0.2 + 50.0 * unit(rng);
      } else if (kind < 0.1) {
        stamp = now - 2.0 * unit(rng);
      } else if (kind < 0.12) {
        stamp = std::numeric_limits<double>::quiet_NaN();
      }
      const bool future = !(stamp <= now + kFutureStampTolerance);
      ++events;
      if (unit(rng) < 0.5) {
        double range = 1.0 + 3.0 * unit(rng);
        if (unit(rng) < 0.02) {
          range = std::numeric_limits<double>::quiet_NaN();
        }
        monitor.onRange(stamp, now, "m" + std::to_string(step % 3), range);
        if (future || !(range >= params.safe_distance)) {
          last_hazard = now;
        } else if (now - stamp <= params.range_timeout) {
          last_fresh_range_stamp = std::max(last_fresh_range_stamp, stamp);
        }
      } else {
        monitor.onEstimate(stamp, now, EstimateQuality::kUsable);
        if (future) {
          last_hazard = now;
        } else {
          last_good_estimate_stamp = std::max(last_good_estimate_stamp, stamp);
          last_good_estimate_rx = now;
        }
      }
      if (monitor.evaluate(now).may_move) {
        ++moves;
        ASSERT_GE(now - last_hazard, params.hold_time) << "run " << run << " step " << step;
        ASSERT_LE(now - last_good_estimate_stamp, params.estimate_timeout)
            << "run " << run << " step " << step;
        ASSERT_LE(now - last_good_estimate_rx, params.estimate_timeout + 2.0)
            << "run " << run << " step " << step;
        ASSERT_LE(now - last_fresh_range_stamp, params.range_timeout)
            << "run " << run << " step " << step;
      }
    }
  }
  EXPECT_GT(moves, 1000);  // the generator must let it move, or the property says nothing
  EXPECT_GT(events, 100000);
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
        monitor.onRange(now, now, source, range);
        newest[source] = {now, range};
      } else if (event < 8) {
        // Stamps may lag the receive time, as estimates do.
        const double stamp = now - dt_dist(rng);
        monitor.onEstimate(stamp, now, EstimateQuality::kUsable);
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
