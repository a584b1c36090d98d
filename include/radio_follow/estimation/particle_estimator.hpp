// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstddef>
#include <vector>

#include "radio_follow/config/layout.hpp"
#include "radio_follow/estimation/particle_tracker.hpp"
#include "radio_follow/estimation/position_estimator.hpp"
#include "radio_follow/estimation/rss_direction.hpp"

namespace radio_follow {
namespace estimation {

/// Estimator::kParticle: every measurement at its stamp into a ParticleTracker (odometry
/// frame when the measurements carry poses), with the opposed boards' RSSI differences
/// when rss_direction is on.
class ParticleEstimator : public PositionEstimator {
 public:
  ParticleEstimator(const Layout& layout, const ParticleTrackerConfig& config);

  void add(const TrackedMeasurement& m) override;
  /// The fresh lists only feed the diagnostics (which bearings were "used").
  LocatorEstimate estimate(double now, const FreshMeasurements& fresh, LocatorEstimate partial,
                           LocatorStats& stats) override;
  void reset() override;
  /// New validated tuning of the same mode; keeps the track unless the particle count or
  /// the motion model changes (ParticleTracker::setConfig, which does not report it).
  void setConfig(const ParticleTrackerConfig& config);

  const ParticleTracker& tracker() const { return tracker_; }

 private:
  std::vector<AoaBoard> boards_;
  ParticleTrackerConfig config_;
  ParticleTracker tracker_;
  RssDifferencer rss_;  ///< opposed boards' RSSI differences (rss_direction only)
};

}  // namespace estimation
}  // namespace radio_follow
