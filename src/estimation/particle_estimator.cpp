// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/estimation/particle_estimator.hpp"

#include <Eigen/Geometry>
#include <chrono>
#include <cmath>
#include <optional>
#include <variant>

namespace radio_follow {
namespace estimation {

ParticleEstimator::ParticleEstimator(const Layout& layout, const ParticleTrackerConfig& config)
    : boards_(layout.aoa_boards), config_(config), tracker_(layout, config), rss_(boards_) {}

void ParticleEstimator::add(const TrackedMeasurement& m) {
  tracker_.add(m);
  const auto* bearing = std::get_if<BearingReading>(&m.reading);
  if (bearing == nullptr || !config_.of<RssDirectionReading>().enabled) {
    return;
  }
  if (const std::optional<RssDifference> d = rss_.add(bearing->board, bearing->rssi, m.t)) {
    // The pair's readings are within 0.1 s of this one: its pose.
    tracker_.add({d->t, m.pose, RssDirectionReading{d->pair, d->difference}});
  }
}

void ParticleEstimator::reset() {
  tracker_.reset();
}

void ParticleEstimator::setConfig(const ParticleTrackerConfig& config) {
  config_ = config;
  tracker_.setConfig(config_);
}

LocatorEstimate ParticleEstimator::estimate(double now, const FreshMeasurements& /*fresh*/,
                                            LocatorEstimate out, LocatorStats& stats) {
  const auto start = std::chrono::steady_clock::now();
  const TrackerOutput track = tracker_.update(now);
  stats.last_solve_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ++stats.solves;
  // The filter weighs every bearing; those of boards whose field of view does not contain
  // the estimate count at a sixth of their weight (bearing_measurement.hpp): "not used" for the
  // markers and diagnostics, as the solver's selection would say.
  out.bearings_used.clear();
  out.sources = track.sources;
  out.in_odom = track.in_odom;
  if (track.status == TargetStatus::kLost) {
    out.status = TargetStatus::kLost;
    ++stats.lost;
    return out;
  }
  out.stamp = track.stamp;
  out.robot_pose = track.pose;
  out.tracking_position = track.position;
  out.tracking_velocity.head<2>() = track.velocity;
  out.tracking_covariance = track.covariance;
  const Eigen::Matrix3d rotation =
      Eigen::AngleAxisd(track.pose.yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  out.position = track.pose.fromFixed(track.position);
  out.velocity = rotation.transpose() * out.tracking_velocity;
  out.covariance = rotation.transpose() * track.covariance * rotation;
  out.alternative = track.pose.fromFixed(track.alternative);
  out.hypotheses = track.hypotheses;
  out.hypothesis_weight = track.hypothesis_weight;
  out.status = track.status;
  for (const std::size_t i : out.bearings_fresh) {
    const AoaBoard& board = boards_[i];
    const Eigen::Vector3d local = board.orientation.conjugate() * (out.position - board.position);
    if (local.x() > std::cos(board.field_of_view) * local.head<2>().norm()) {
      out.bearings_used.push_back(i);
    }
  }
  stats.bearings_rejected_fov += out.bearings_fresh.size() - out.bearings_used.size();
  if (config_.filter.planar) {
    out.position.z() = config_.filter.height;
    out.alternative.z() = config_.filter.height;
  }
  if (!out.position.allFinite() || !out.velocity.allFinite() || !out.covariance.allFinite()) {
    ++stats.non_finite;
    tracker_.reset();
    out.status = TargetStatus::kLost;
    ++stats.lost;
    return out;
  }
  if (out.status == TargetStatus::kAmbiguous) {
    ++stats.ambiguous;
  }
  return out;
}

}  // namespace estimation
}  // namespace radio_follow
