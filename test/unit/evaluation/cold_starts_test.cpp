// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/evaluation/cold_starts.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "radio_follow/evaluation/closed_loop.hpp"

namespace radio_follow {
namespace evaluation {
namespace {

ColdStartResult run(sim::SensorProfile profile, std::size_t trials) {
  const ClosedLoopConfig c = loadClosedLoopConfig(RF_CONFIG_DIR, "spot", "outdoor_loop",
                                                  FollowController::kVelocity, 1, "", "", profile);
  ColdStartParams params;
  params.trials = trials;
  params.robots = 2;
  return runColdStarts(c.layout, c.world, c.locator, params);
}

TEST(ColdStarts, TheShippedLocatorFindsThePersonAndNeverSitsOnTheMirror) {
  const ColdStartResult r = run(sim::SensorProfile::kRealistic, 40);
  EXPECT_EQ(r.trials, 40u);
  EXPECT_EQ(r.usable, 40u);
  EXPECT_TRUE(r.locks.empty());
  EXPECT_LT(r.median_time_to_usable, 1.0);
  EXPECT_LT(r.error_median, 0.4);
  EXPECT_GT(r.nees_samples, 1000u);
  EXPECT_TRUE(std::isfinite(r.nees_mean));
}

TEST(ColdStarts, TheSolverEstimatorIsMeasuredTheSameWay) {
  ClosedLoopConfig c =
      loadClosedLoopConfig(RF_CONFIG_DIR, "spot", "outdoor_loop", FollowController::kVelocity, 1,
                           "", "", sim::SensorProfile::kIdeal);
  c.locator.estimator = estimation::Estimator::kSolver;
  ColdStartParams params;
  params.trials = 20;
  params.robots = 1;
  const ColdStartResult r = runColdStarts(c.layout, c.world, c.locator, params);
  EXPECT_EQ(r.trials, 20u);
  EXPECT_GT(r.usable, 15u);
  EXPECT_GT(r.updates, 20u * 59u);
}

TEST(ColdStarts, ListsEveryLockAndShowsEveryUpdateToTheObserver) {
  // Ranges only from three nearly collinear modules and the solver estimator without its
  // mirror test: the mirror is as good as the person, so some trials sit on it.
  ClosedLoopConfig c =
      loadClosedLoopConfig(RF_CONFIG_DIR, "spot_twr", "outdoor_loop", FollowController::kVelocity,
                           1, "", "", sim::SensorProfile::kRealistic);
  c.locator.estimator = estimation::Estimator::kSolver;
  c.locator.ambiguity_margin = 0.0;
  ColdStartParams params;
  params.trials = 40;
  params.robots = 1;
  std::size_t observed = 0;
  std::size_t last_trial = 0;
  params.observer = [&](std::size_t trial, double now, const estimation::LocatorEstimate&,
                        const Eigen::Vector3d& target) {
    ++observed;
    last_trial = trial;
    EXPECT_GT(now, 0.0);
    EXPECT_GE(target.head<2>().norm(), params.min_distance - 1e-9);
  };
  const ColdStartResult r = runColdStarts(c.layout, c.world, c.locator, params);
  EXPECT_EQ(observed, r.updates);
  EXPECT_EQ(last_trial, 39u);
  ASSERT_FALSE(r.locks.empty());
  for (const MirrorLock& lock : r.locks) {
    EXPECT_LT(lock.trial, 40u);
    EXPECT_GT(lock.longest_s, 1.0);
    EXPECT_LE(lock.start_s + lock.longest_s, params.duration + 0.05 + 1e-9);
    EXPECT_LE(lock.longest_s, r.longest_mirror_s);
  }
}

TEST(ColdStarts, ATrialRunAloneIsTheSameTrialAsInTheSeries) {
  const ClosedLoopConfig c =
      loadClosedLoopConfig(RF_CONFIG_DIR, "spot", "outdoor_loop", FollowController::kVelocity, 1,
                           "", "", sim::SensorProfile::kRealistic);
  std::vector<Eigen::Vector3d> in_series;
  std::vector<Eigen::Vector3d> alone;
  ColdStartParams params;
  params.trials = 6;
  params.robots = 3;
  params.observer = [&](std::size_t trial, double, const estimation::LocatorEstimate& e,
                        const Eigen::Vector3d&) {
    if (trial == 4) {
      in_series.push_back(e.position);
    }
  };
  runColdStarts(c.layout, c.world, c.locator, params);
  params.first_trial = 4;
  params.trials = 1;
  params.observer = [&](std::size_t trial, double, const estimation::LocatorEstimate& e,
                        const Eigen::Vector3d&) {
    EXPECT_EQ(trial, 4u);
    alone.push_back(e.position);
  };
  const ColdStartResult r = runColdStarts(c.layout, c.world, c.locator, params);
  EXPECT_EQ(r.trials, 1u);
  ASSERT_EQ(alone.size(), in_series.size());
  ASSERT_FALSE(alone.empty());
  for (std::size_t i = 0; i < alone.size(); ++i) {
    EXPECT_EQ(alone[i], in_series[i]) << "update " << i;
  }
}

// Trials 5263 and 7884 of `locator_cold_starts --trials 10000` (doc/locator_accuracy.md,
// "What the locks are"): the first epoch allows several places, the main cloud settles
// on one of them a metre or more from where it started, and the mirror filter, drawn as
// the image of the unsettled cloud, was left behind. Before the mirror was drawn again
// after such a jump they sat on the mirror for 1.10 s and 1.65 s (now 0.15 s each).
TEST(ColdStarts, AMirrorLeftBehindByAJumpingMainHypothesisIsDrawnAgain) {
  const ClosedLoopConfig c =
      loadClosedLoopConfig(RF_CONFIG_DIR, "spot", "outdoor_loop", FollowController::kVelocity, 1,
                           "", "", sim::SensorProfile::kRealistic);
  for (const std::size_t trial : {5263u, 7884u}) {
    ColdStartParams params;
    params.first_trial = trial;
    params.trials = 1;
    const ColdStartResult r = runColdStarts(c.layout, c.world, c.locator, params);
    EXPECT_TRUE(r.locks.empty()) << "trial " << trial;
    EXPECT_LT(r.longest_mirror_s, 0.5) << "trial " << trial;
  }
}

}  // namespace
}  // namespace evaluation
}  // namespace radio_follow
