// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/estimation/particle_tracker.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "../../support/true_ranges.hpp"
#include "radio_follow/estimation/locator.hpp"
#include "radio_follow/estimation/measurement_models.hpp"

namespace radio_follow {
namespace estimation {
namespace {

/// Noisy ranges and bearings of a layout to a target, each sensor at its own phase.
class Feeder {
 public:
  Feeder(Locator& locator, double range_sigma, double azimuth_sigma, unsigned seed)
      : locator_(locator), range_sigma_(range_sigma), azimuth_sigma_(azimuth_sigma), rng_(seed) {}

  /// Every sensor once, between t and t + 0.1 (robot at `pose` in the odometry frame,
  /// target at `target` in that frame; no pose: both in the robot frame).
  void epoch(const Eigen::Vector3d& target, double t, const std::optional<Pose2>& pose,
             bool bearings = true) {
    const Pose2 p = pose.value_or(Pose2{});
    const double c = std::cos(p.yaw);
    const double s = std::sin(p.yaw);
    const Eigen::Vector3d d = target - Eigen::Vector3d(p.x, p.y, 0.0);
    const Eigen::Vector3d local(c * d.x() + s * d.y(), -s * d.x() + c * d.y(), d.z());
    const Layout& layout = locator_.layout();
    std::normal_distribution<double> range_noise(0.0, range_sigma_);
    std::normal_distribution<double> angle_noise(0.0, azimuth_sigma_);
    double at = t;
    for (const auto& m : layout.twr_modules) {
      locator_.addRange(m.id, (local - m.position).norm() + range_noise(rng_), at, pose);
      at += 0.1 / 8.0;
    }
    if (!bearings) {
      return;
    }
    for (const auto& b : layout.aoa_boards) {
      const Eigen::Vector3d v = b.orientation.conjugate() * (local - b.position);
      if (v.x() <= 0.0) {
        continue;  // behind the board: these tests give no mirrored bearings
      }
      const Eigen::Vector2d ae = predictBearing(local, b.position, b.orientation.toRotationMatrix());
      locator_.addBearing(b.id, ae(0) + angle_noise(rng_), ae(1) + angle_noise(rng_), -60.0, at,
                          pose);
      at += 0.1 / 8.0;
    }
  }

 private:
  Locator& locator_;
  double range_sigma_;
  double azimuth_sigma_;
  std::mt19937_64 rng_;
};

LocatorConfig particleConfig() {
  LocatorConfig config;
  config.estimator = Estimator::kParticle;
  config.range_sigma = 0.03;
  config.azimuth_sigma = 5.0 * M_PI / 180.0;
  config.elevation_sigma = 5.0 * M_PI / 180.0;
  return config;
}

TEST(ParticleTracker, StaticTargetSpotConverges) {
  const LocatorConfig config = particleConfig();
  Locator locator(test::uncalibratedLayout("spot.yaml"), config);
  Feeder feed(locator, 0.03, config.azimuth_sigma, 1);
  const Eigen::Vector3d truth(3.0, 1.0, config.height);
  LocatorEstimate e;
  for (int k = 0; k < 30; ++k) {
    feed.epoch(truth, 0.1 * k, std::nullopt);
    e = locator.update(0.1 * k + 0.1);
    std::printf("%d %s %.3f %.3f sig %.3f ev %.2f ess %.0f\n", k, toString(e.status), e.position.x(), e.position.y(), std::sqrt(e.covariance.trace()), locator.tracker().mirrorEvidence(), locator.tracker().mainFilter().effectiveSampleSize());
  }
  EXPECT_EQ(e.status, TargetStatus::kOk);
  EXPECT_LT((e.position - truth).head<2>().norm(), 0.15)
      << e.position.transpose() << " evidence " << locator.tracker().mirrorEvidence();
}

}  // namespace
}  // namespace estimation
}  // namespace radio_follow
