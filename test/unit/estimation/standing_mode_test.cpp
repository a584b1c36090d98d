// SPDX-License-Identifier: BSD-3-Clause
// The particle estimator's standing mode (a person who walks and stands by turns) and
// its range decorrelation time (doc/real_recordings.md).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "../../support/true_ranges.hpp"
#include "radio_follow/estimation/locator.hpp"
#include "radio_follow/estimation/particle_filter.hpp"
#include "radio_follow/estimation/range_measurement.hpp"

namespace radio_follow {
namespace estimation {
namespace {

ParticleFilter::Config standingConfig() {
  ParticleFilter::Config config;
  config.particles = 3000;
  config.stand_time = 5.0;
  config.walk_time = 10.0;
  return config;
}

TEST(ParticleFilter, StandingParticlesStayPutWhileWalkersMove) {
  ParticleFilter filter(standingConfig());
  filter.initialize({{3, 0, 1}}, 1.0, 0.0);
  // The stationary share 5 / (5 + 10) of the cloud starts standing, at rest.
  std::vector<Eigen::Vector3d> before;
  std::size_t standing = 0;
  for (std::size_t i = 0; i < filter.size(); ++i) {
    before.push_back(filter.position(i));
    standing += !filter.walking(i);
  }
  EXPECT_NEAR(static_cast<double>(standing) / filter.size(), 1.0 / 3.0, 0.04);
  EXPECT_NEAR(filter.walkingShare(), 2.0 / 3.0, 0.04);
  filter.predict(1.0);
  double standing_moved = 0.0;
  double walking_moved = 0.0;
  std::size_t standing_now = 0;
  for (std::size_t i = 0; i < filter.size(); ++i) {
    const double moved = (filter.position(i) - before[i]).head<2>().norm();
    if (filter.walking(i)) {
      walking_moved += moved;
    } else {
      EXPECT_EQ(filter.velocity(i), Eigen::Vector2d::Zero());  // a stander has no velocity
      standing_moved += moved;
      ++standing_now;
    }
  }
  // Over 1 s a walker goes about its speed (1.25 m/s mean of |N(0, 1)| in 2D); a stander
  // (or one that stopped this step) sways by sqrt(0.003 * 1) = 5 cm per axis.
  ASSERT_GT(standing_now, 0u);
  EXPECT_LT(standing_moved / standing_now, 0.1);
  EXPECT_GT(walking_moved / (filter.size() - standing_now), 0.8);
}

/// Three modules 0.3-0.5 m apart range (10 Hz, sigma 0.05 m) to a target that stands
/// 10 s, then walks 5 s at 1.2 m/s; the filter's walking share at both ends and its error
/// at the end.
struct StandThenWalk {
  double share_standing;
  double share_walking;
  double error;
};

StandThenWalk standThenWalk(double stand_time) {
  ParticleFilter::Config config = standingConfig();
  config.particles = 1000;
  config.stand_time = stand_time;
  ParticleFilter filter(config);
  const Eigen::Vector3d modules[3] = {{0.3, 0, 1}, {-0.3, 0.2, 1}, {0, -0.3, 1}};
  std::mt19937 rng(3);
  std::normal_distribution<double> noise(0.0, 0.05);
  Eigen::Vector3d target(4.0, 1.0, 1.0);
  filter.initialize({target}, 0.5, 0.0);
  const auto run = [&](double from, double until, const Eigen::Vector2d& velocity) {
    for (double t = from; t < until; t += 0.1) {
      target.head<2>() += 0.1 * velocity;
      filter.predict(t);
      for (const Eigen::Vector3d& m : modules) {
        weighRange(filter, m, (target - m).norm() + noise(rng), RangeLikelihood{});
      }
      filter.resampleIfNeeded();
    }
  };
  StandThenWalk r{};
  run(0.1, 10.0, Eigen::Vector2d::Zero());
  r.share_standing = filter.walkingShare();
  run(10.0, 15.0, Eigen::Vector2d(0.0, 1.2));
  r.share_walking = filter.walkingShare();
  r.error = (filter.mean() - target).head<2>().norm();
  return r;
}

// The mode follows the data: ranges to a target that stands give the standing particles
// the weight; once it walks, the walkers take it back, and the track is as good as the
// walking model's.
TEST(ParticleFilter, TheWalkingShareFollowsWhatTheTargetDoes) {
  const StandThenWalk standing = standThenWalk(5.0);
  const StandThenWalk walking_model = standThenWalk(0.0);
  EXPECT_LT(standing.share_standing, 0.3);
  EXPECT_GT(standing.share_walking, 0.8);
  EXPECT_NEAR(walking_model.share_standing, 1.0, 1e-4);  // no standing mode: all walk
  RecordProperty("error_m", std::to_string(standing.error));
  RecordProperty("walking_model_error_m", std::to_string(walking_model.error));
  EXPECT_LT(standing.error, walking_model.error + 0.1);
}

/// Median error over the last 40 s of a minute in which the robot (Spot's three nearly
/// collinear modules, ranges only) drives a circle past a target standing 4.5 m away,
/// its modules' errors correlated over seconds as real ones are (a Gauss-Markov process
/// of tau 3 s and sigma 0.06 m each, plus 0.02 m white), ranges at 10 Hz.
double standingTargetError(double stand_time) {
  LocatorConfig config;
  config.stand_time = stand_time;
  Locator locator(test::uncalibratedLayout("spot_twr.yaml"), config);
  const Eigen::Vector3d target(4.0, 2.0, config.height);
  std::mt19937_64 rng(11);
  std::normal_distribution<double> unit(0.0, 1.0);
  std::vector<double> drift(locator.layout().twr_modules.size(), 0.0);
  const double keep = std::exp(-0.1 / 3.0);
  std::vector<double> errors;
  for (int k = 0; k < 600; ++k) {
    const double t = 0.1 * k;
    Pose2 pose;  // a circle of radius 1.5 m at 0.5 m/s about (0, 1.5), facing along it
    pose.x = 1.5 * std::sin(t / 3.0);
    pose.y = 1.5 - 1.5 * std::cos(t / 3.0);
    pose.yaw = t / 3.0;
    const Eigen::Vector3d local = pose.fromFixed(target);
    for (std::size_t i = 0; i < drift.size(); ++i) {
      drift[i] = keep * drift[i] + std::sqrt(1.0 - keep * keep) * 0.06 * unit(rng);
      const auto& m = locator.layout().twr_modules[i];
      locator.addRange(locator.layout().twrModuleIndex(m.id),
                       (local - m.position).norm() + drift[i] + 0.02 * unit(rng), t + 0.01 * i,
                       pose);
    }
    const LocatorEstimate e = locator.update(t + 0.05);
    if (t >= 20.0) {
      errors.push_back(hasPosition(e.status) ? (e.tracking_position - target).head<2>().norm()
                                             : 10.0);  // no position: as bad as it gets
    }
  }
  std::nth_element(errors.begin(), errors.begin() + errors.size() / 2, errors.end());
  return errors[errors.size() / 2];
}

// What the standing mode is for: the robot's path averages a standing target's position
// over the errors that the walking model follows around.
TEST(ParticleTracker, AStandingTargetIsAveragedOverTheRobotsPath) {
  const double walking_model = standingTargetError(0.0);
  const double standing_mode = standingTargetError(5.0);
  RecordProperty("walking_model_median_m", std::to_string(walking_model));
  RecordProperty("standing_mode_median_m", std::to_string(standing_mode));
  EXPECT_LT(standing_mode, 0.7 * walking_model);
  EXPECT_LT(standing_mode, 0.3);
}

/// The main cloud's position spread (sqrt of the covariance's trace) after 3 s of ranges
/// from the tracked robot's four modules to a standing target, `rate` per module.
double spreadAfter(double rate, double decorrelation_time) {
  LocatorConfig config;
  config.range_decorrelation_time = decorrelation_time;
  Locator locator(test::uncalibratedLayout("tracked.yaml"), config);
  const Eigen::Vector3d target(3.0, 1.0, config.height);
  std::mt19937_64 rng(5);
  std::normal_distribution<double> noise(0.0, config.range_sigma);
  const double dt = 1.0 / rate;
  for (int k = 0; k * dt < 3.0; ++k) {
    for (const auto& m : locator.layout().twr_modules) {
      locator.addRange(locator.layout().twrModuleIndex(m.id),
                       (target - m.position).norm() + noise(rng), k * dt);
    }
    locator.update(k * dt + 0.5 * dt);
  }
  return std::sqrt(locator.tracker().mainFilter().covariance().trace());
}

// A module ranging at 100 Hz says no more than one at 10 Hz: its errors are correlated
// over tenths of a second (real modules: 0.7 at 0.1 s). Counted as independent, ten
// times the ranges would shrink the cloud onto the current error.
TEST(ParticleTracker, AHundredHertzModuleCountsAsATenHertzOne) {
  const double ten_hertz = spreadAfter(10.0, 0.1);
  const double hundred_hertz = spreadAfter(100.0, 0.1);
  const double hundred_hertz_independent = spreadAfter(100.0, 0.0);
  EXPECT_GT(hundred_hertz, 0.7 * ten_hertz);
  EXPECT_LT(hundred_hertz, 1.4 * ten_hertz);
  EXPECT_LT(hundred_hertz_independent, 0.6 * ten_hertz);
}

}  // namespace
}  // namespace estimation
}  // namespace radio_follow
