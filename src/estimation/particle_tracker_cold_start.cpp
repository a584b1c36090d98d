// SPDX-License-Identifier: BSD-3-Clause
// ParticleTracker's cold start (particle_tracker.hpp): a cloud sampled from the newest
// measurement of every sensor, weighed by all of them, split by side of the modules' axis.
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <set>
#include <tuple>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include "radio_follow/estimation/particle_tracker.hpp"

namespace radio_follow {
namespace estimation {
namespace {

/// |log Bayes factor| of a cold start's two sides at most, nats: one epoch's data, some of
/// which may be reflections, never make a side certain.
constexpr double kColdStartEvidence = 10.0;
/// Cold starts sample this many times the particle count, then keep the best N.
constexpr std::size_t kColdStartFactor = 4;
/// A cold start waits for every sensor's first input, at most this long after the first
/// input, s (two periods of a 10 Hz sensor: a dropped reading or a dead sensor delays the
/// start by no more).
constexpr double kColdStartWait = 0.2;
/// Velocity spread of a cold start, m/s per axis (a walking person).
constexpr double kColdVelocitySigma = 0.7;
/// Bearing-only cold starts spread particles over this distance interval, m.
constexpr double kRayMin = 0.3;
constexpr double kRayMax = 12.0;
/// Disc cold starts (distance differences only) spread particles over this radius, m.
constexpr double kDiscRadius = 15.0;

}  // namespace

bool ParticleTracker::coldStart(double now) {
  // The newest reading of every sensor (the deque is in processing order).
  std::map<SensorKey, const TrackedMeasurement*> newest;
  for (const auto& m : recent_) {
    const SensorKey key = sensorKey(m);
    const auto it = newest.find(key);
    if (it == newest.end() || it->second->t <= m.t) {
      newest[key] = &m;
    }
  }
  const std::size_t sensors = expectedSensors(layout_);
  if (newest.size() < std::min<std::size_t>(2, sensors) || newest.empty()) {
    return false;
  }
  // The tightest shape the readings allow (tracked_reading.hpp's ColdSeed): the smallest
  // ring, else a disc, else rays.
  const TrackedMeasurement* ring = nullptr;
  SeedRing ring_seed;
  const TrackedMeasurement* latest = nullptr;
  bool any_disc = false;
  bool any_fix = false;
  std::set<SensorKey> heard;
  for (const auto& [key, m] : newest) {
    const std::optional<SeedRing> r = std::visit(
        [this, m = m](const auto& reading) -> std::optional<SeedRing> {
          if constexpr (std::decay_t<decltype(reading)>::kColdSeed == ColdSeed::kRing) {
            return seedRing(reading, context(Pose2{}, m->t));
          }
          return std::nullopt;
        },
        m->reading);
    if (r && (ring == nullptr || r->radius < ring_seed.radius)) {
      ring = m;
      ring_seed = *r;
    }
    any_disc = any_disc || coldSeedOf(*m) == ColdSeed::kDisc;
    any_fix = any_fix || fixesDistance(*m);
    if (latest == nullptr || m->t > latest->t) {
      latest = m;
    }
    if (const std::optional<SensorKey> h = heardKey(*m)) {
      heard.insert(*h);
    }
  }
  // Bearings alone place the target only along rays, some of them from a board's edge;
  // a layout that ranges waits for a range (for max_age, then starts heading-only).
  if (!any_fix && rangingLayout(layout_) &&
      (recent_.empty() || now - recent_.front().t < config_.max_age)) {
    return false;
  }
  // One epoch of every sensor first: a start from the first two or three inputs takes a
  // board's reflection, or the edge-biased reading of a board that cannot see the target,
  // as the direction whenever the board that sees it has not spoken yet
  // (doc/locator_accuracy.md, "What the locks are").
  if (heard.size() < sensors && !recent_.empty() && now - recent_.front().t < kColdStartWait) {
    return false;
  }
  const Pose2 pose = latest->pose.value_or(Pose2{});

  ParticleFilter::Config sampler_config = config_.filter;
  sampler_config.particles = kColdStartFactor * config_.filter.particles;
  sampler_config.seed = config_.filter.seed + 1000 * (stats_.cold_starts + 1);
  ParticleFilter sampler(sampler_config);
  std::vector<Eigen::Vector3d> positions;
  const std::size_t count = sampler_config.particles;
  const double height = config_.filter.height;
  const double golden = 2.39996322972865332;  // rad: evenly spread angles, no RNG needed
  if (ring != nullptr) {
    const Eigen::Vector3d module = ring->pose.value_or(Pose2{}).toFixed(ring_seed.centre);
    const double dz = config_.filter.planar ? height - module.z() : 0.0;
    const double radius = std::sqrt(std::max(0.01, ring_seed.radius * ring_seed.radius - dz * dz));
    for (std::size_t k = 0; k < count; ++k) {
      const double angle = golden * static_cast<double>(k);
      positions.emplace_back(module.x() + radius * std::cos(angle),
                             module.y() + radius * std::sin(angle), height);
    }
  } else if (any_disc) {
    for (std::size_t k = 0; k < count; ++k) {
      const double r = kDiscRadius * std::sqrt((static_cast<double>(k) + 0.5) / count);
      const double angle = golden * static_cast<double>(k);
      positions.push_back(pose.toFixed({r * std::cos(angle), r * std::sin(angle), height}));
    }
  } else {
    std::vector<std::pair<const TrackedMeasurement*, SeedRay>> rays;
    for (const auto& [key, m] : newest) {
      std::visit(
          [&, m = m](const auto& reading) {
            if constexpr (std::decay_t<decltype(reading)>::kColdSeed == ColdSeed::kRay) {
              rays.emplace_back(m, seedRay(reading, context(Pose2{}, m->t)));
            }
          },
          m->reading);
    }
    if (rays.empty()) {
      return false;
    }
    for (std::size_t k = 0; k < count; ++k) {
      const auto& [b, ray] = rays[k % rays.size()];
      const Pose2 at = b->pose.value_or(Pose2{});
      Eigen::Vector3d direction(std::cos(ray.elevation) * std::cos(ray.azimuth),
                                std::cos(ray.elevation) * std::sin(ray.azimuth),
                                std::sin(ray.elevation));
      if ((k / rays.size()) % 2 == 1) {
        direction.x() = -direction.x();  // the array's other side
      }
      const double fraction = static_cast<double>((k * 7919) % count) / static_cast<double>(count);
      const double distance = kRayMin + (kRayMax - kRayMin) * fraction;
      Eigen::Vector3d p = at.toFixed(ray.origin + ray.orientation * (distance * direction));
      if (config_.filter.planar) {
        p.z() = height;
      }
      positions.push_back(p);
    }
  }
  sampler.initialize(positions, kColdVelocitySigma, latest->t);
  for (const auto& [key, m] : newest) {
    // The cloud's mean is a point near the robot here: whether a board sees the target
    // is each particle's own question.
    weigh(sampler, *m, m->pose.value_or(Pose2{}), /*cold_start=*/true);
  }
  evidence_ = 0.0;
  evidence_time_ = latest->t;
  if (axis_ && (ring != nullptr || board_axis_)) {
    // Keep the side with more weight; the other is what the mirror filter starts from.
    const auto side = [this, &pose](const Eigen::Vector3d& p) { return onMainSide(p, pose); };
    ParticleFilter other = sampler;
    const double first = sampler.restrict(side);
    const double second = 1.0 - first;
    if (first < second) {
      other.restrict([&side](const Eigen::Vector3d& p) { return !side(p); });
      sampler = other;
    }
    evidence_ = std::clamp(std::log(std::max(std::min(first, second), 1e-12) /
                                    std::max(std::max(first, second), 1e-12)),
                           -kColdStartEvidence, kColdStartEvidence);
  }
  std::vector<Eigen::Vector3d> kept;
  std::vector<Eigen::Vector2d> velocities;
  sampler.draw(config_.filter.particles, &kept, &velocities);
  main_.assign(kept, velocities, latest->t);
  pose_ = pose;
  for (const auto& [key, m] : newest) {
    double& source = last_source_.try_emplace(sourceOf(*m), -1.0).first->second;
    source = std::max(source, m->t);
    if (fixesDistance(*m)) {
      last_position_fix_ = std::max(last_position_fix_, m->t);
    }
  }
  mirror_active_ = false;
  if (axis_) {
    seedMirror();
  }
  ++stats_.cold_starts;
  (void)now;
  return true;
}

}  // namespace estimation
}  // namespace radio_follow
