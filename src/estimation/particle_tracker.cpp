// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/estimation/particle_tracker.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <set>
#include <tuple>
#include <utility>
#include <variant>

#include "radio_follow/common/angles.hpp"
#include "radio_follow/common/time_policy.hpp"
#include "radio_follow/estimation/correlated_error.hpp"

namespace radio_follow {
namespace estimation {
namespace {

/// |log Bayes factor| cap, nats: a numerical guard only (the fading memory bounds it).
constexpr double kMaxEvidence = 50.0;
/// Modules whose scatter's small/large eigenvalue ratio is below this are "nearly
/// collinear": their ranges allow a mirror solution, which a second filter follows.
constexpr double kCollinearRatio = 0.15;
/// Mirror and main closer than this (or 3 sigma) are one hypothesis, m.
constexpr double kMinMirrorSeparation = 0.5;
/// The main hypothesis moving farther than this (or 3 sigma) between two updates has
/// jumped to another place: its mirror image is drawn again, m.
constexpr double kMainJump = 1.0;
/// A mirror hypothesis with less probability than this is not reported.
constexpr double kReportedShare = 0.01;
/// Weight of each measurement in the running inlier probability (about the last 50).
constexpr double kFitRate = 0.02;
/// Below this running inlier probability the track has diverged and restarts (a
/// consistent track sits near 1 - the outlier shares, about 0.95).
constexpr double kDivergedFit = 0.6;
/// Boards within this of one another's heading face "the same way" (one mirror plane), rad.
constexpr double kParallelBoards = 0.2;
/// A hypothesis with more of its weight than this across the boards' plane is folded back.
constexpr double kAstrayShare = 0.01;
/// The robot moved between two measurements when its pose changed by more than this (m or
/// rad): below it, a board's bearings cannot tell front from back.
constexpr double kStill = 1e-4;

double worstSigma(const Eigen::Matrix3d& covariance) {
  return std::sqrt(std::max(
      0.0, Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(covariance).eigenvalues().maxCoeff()));
}

ParticleFilter::Config mirrorConfig(ParticleFilter::Config c) {
  c.particles = std::max<std::size_t>(50, c.particles / 4);
  c.seed = c.seed * 31 + 7;
  return c;
}

}  // namespace

ParticleTracker::ParticleTracker(const Layout& layout, const ParticleTrackerConfig& config)
    : layout_(layout),
      config_(config),
      main_(config.filter),
      mirror_(mirrorConfig(config.filter)),
      rss_pairs_(opposedBoardPairs(layout.aoa_boards)) {
  accumulates_ = layout.twr_modules.size() <= 1 && layout.aoa_boards.empty();
  for (const auto& b : layout.aoa_boards) {
    bearing_origin_ += b.position.head<2>() / static_cast<double>(layout.aoa_boards.size());
  }
  std::vector<Eigen::Vector3d> modules;
  for (const auto& m : layout.twr_modules) {
    modules.push_back(m.position);
  }
  const auto facing = [](const AoaBoard& b) {
    const Eigen::Vector3d x = b.orientation * Eigen::Vector3d::UnitX();
    return std::atan2(x.y(), x.x());
  };
  const double yaw = layout.aoa_boards.empty() ? 0.0 : facing(layout.aoa_boards.front());
  boards_one_way_ =
      !layout.aoa_boards.empty() &&
      std::all_of(layout.aoa_boards.begin(), layout.aoa_boards.end(), [&](const AoaBoard& b) {
        return std::abs(std::remainder(facing(b) - yaw, 2.0 * kPi)) < kParallelBoards;
      });
  const std::optional<MirrorAxis> axis = mirrorAxis(modules);
  if (config.filter.planar && axis && axis->flatness < kCollinearRatio) {
    axis_ = axis;
  } else if (config.filter.planar && modules.size() <= 1 && boards_one_way_) {
    // The boards' plane: a direction along it and the first board's position on it.
    MirrorAxis plane;
    plane.centroid = layout.aoa_boards.front().position.head<2>();
    plane.direction = Eigen::Vector2d(-std::sin(yaw), std::cos(yaw));
    axis_ = plane;
    board_axis_ = true;
  }
}

void ParticleTracker::reset() {
  fit_ = 1.0;
  main_.reset();
  mirror_.reset();
  mirror_active_ = false;
  evidence_ = 0.0;
  last_main_mean_.reset();
  last_position_fix_ = -1.0;
  last_source_.clear();
  last_reading_.clear();
}

void ParticleTracker::setConfig(const ParticleTrackerConfig& config) {
  const bool restart = config.filter.particles != config_.filter.particles ||
                       config.filter.planar != config_.filter.planar;
  config_ = config;
  // An optional input switched off: what is queued or kept for cold starts must not count
  // any more.
  const auto off = [this](const TrackedMeasurement& m) { return !usable(m); };
  queue_.erase(std::remove_if(queue_.begin(), queue_.end(), off), queue_.end());
  recent_.erase(std::remove_if(recent_.begin(), recent_.end(), off), recent_.end());
  if (restart) {
    main_ = ParticleFilter(config.filter);
    mirror_ = ParticleFilter(mirrorConfig(config.filter));
    reset();
  }
}

void ParticleTracker::add(const TrackedMeasurement& measurement) {
  if (usable(measurement)) {
    queue_.push_back(measurement);
  }
}

TrackerContext ParticleTracker::context(const Pose2& pose, double t) const {
  return {layout_, config_, rss_pairs_, boards_one_way_, pose, rangedAt(t)};
}

bool ParticleTracker::usable(const TrackedMeasurement& m) const {
  const TrackerContext c = context(Pose2{}, m.t);
  return std::visit([&c](const auto& r) { return estimation::usable(r, c); }, m.reading);
}

Eigen::Vector3d ParticleTracker::mirrored(const Eigen::Vector3d& p, const Pose2& pose) const {
  return pose.toFixed(axis_->reflect(pose.fromFixed(p)));
}

Eigen::Vector2d ParticleTracker::mirroredVelocity(const Eigen::Vector2d& v,
                                                  const Pose2& pose) const {
  const Eigen::Rotation2Dd rotation(pose.yaw);
  return rotation * axis_->reflectVector(rotation.inverse() * v);
}

bool ParticleTracker::onMainSide(const Eigen::Vector3d& p, const Pose2& pose) const {
  return axis_->leftOf(pose.fromFixed(p));
}

MeasurementFit ParticleTracker::weigh(ParticleFilter& filter, const TrackedMeasurement& m,
                                      const Pose2& pose, bool cold_start,
                                      double sigma_scale) const {
  TrackerContext c = context(pose, m.t);
  c.cold_start = cold_start;
  c.sigma_scale = sigma_scale;
  return std::visit([&](const auto& r) { return estimation::weigh(r, filter, c); }, m.reading);
}

bool ParticleTracker::rangedAt(double t) const {
  return last_position_fix_ >= 0.0 && t - last_position_fix_ <= config_.max_age;
}

double ParticleTracker::sigmaScale(const TrackedMeasurement& m) {
  const TrackerContext c = context(Pose2{}, m.t);
  const Decorrelation d =
      std::visit([&c](const auto& r) { return estimation::decorrelation(r, c); }, m.reading);
  double& last = last_reading_.try_emplace(sensorKey(m), -1e300).first->second;
  const double dt = m.t - last;
  last = std::max(last, m.t);
  if (!(d.time > 0.0) || !(dt < d.time)) {
    return 1.0;
  }
  // dt / time of a reading; a repeated stamp (dt 0) counts as a hundredth.
  const double scale = std::sqrt(d.time / std::max(dt, 0.01 * d.time));
  return std::min(scale, d.max_scale);
}

void ParticleTracker::apply(const TrackedMeasurement& m) {
  const Pose2 pose = m.pose.value_or(Pose2{});
  if (m.t < main_.time()) {
    ++stats_.late;  // applied at the filter's time: the filters do not run backwards
  }
  const double sigma_scale = sigmaScale(m);
  main_.predict(m.t);
  const MeasurementFit main_fit = weigh(main_, m, pose, /*cold_start=*/false, sigma_scale);
  // A track whose particles are all in the wrong place explains every input as an
  // outlier, and the outlier floor then moves nothing: watch the inlier probability.
  fit_ += kFitRate * (main_fit.inlier - fit_);
  if (mirror_active_) {
    mirror_.predict(m.t);
    const MeasurementFit mirror_fit = weigh(mirror_, m, pose, /*cold_start=*/false, sigma_scale);
    if (main_fit.likelihood > 0.0 && mirror_fit.likelihood > 0.0) {
      // Fading memory: the side is decided by about the last `mirror_memory` seconds of
      // data. It bounds the evidence by the rate at which the sensors deliver it, so one
      // reflection cannot overturn a second of consistent bearings, and errors that stay
      // correlated for seconds stop adding up after a while; a wrong side is left within
      // about that time once the data disambiguate.
      const double faded =
          evidence_ * std::exp(-std::max(0.0, m.t - evidence_time_) / config_.mirror_memory);
      double change = std::log(mirror_fit.likelihood) - std::log(main_fit.likelihood);
      if (board_axis_ && !moved(pose)) {
        // A board hears a tag behind it as its mirror image in front: while the robot
        // stands still, whatever the two clouds' fits say about the side is their own
        // difference, not the data's. Only the field of view's prior counts.
        const double prior = std::log(config_.of<BearingReading>().likelihood.behind_weight);
        change = inFront(main_.mean(), pose) ? prior : -prior;
      }
      evidence_ = std::clamp(faded + change, -kMaxEvidence, kMaxEvidence);
      evidence_time_ = std::max(evidence_time_, m.t);
    }
    mirror_.resampleIfNeeded();
  }
  stats_.resamples += main_.resampleIfNeeded();
  if (m.t >= main_.time()) {
    pose_ = pose;
  }
  double& source = last_source_.try_emplace(sourceOf(m), -1.0).first->second;
  source = std::max(source, m.t);
  if (fixesDistance(m)) {
    last_position_fix_ = std::max(last_position_fix_, m.t);
  }
  ++stats_.processed;
}

Eigen::Matrix3d ParticleTracker::correlatedFloor(const Eigen::Vector3d& position) const {
  std::vector<InformingSensor> sensors;
  std::set<SensorKey> seen;
  const TrackerContext c = context(pose_, main_.time());
  for (const TrackedMeasurement& m : recent_) {
    if (!seen.insert(sensorKey(m)).second) {
      continue;
    }
    const std::optional<InformingSensor> s =
        std::visit([&](const auto& r) { return estimation::informing(r, position, c); }, m.reading);
    if (s) {
      sensors.push_back(*s);
    }
  }
  return correlatedErrorCovariance(sensors);
}

void ParticleTracker::seedMirror() {
  std::vector<Eigen::Vector3d> positions;
  std::vector<Eigen::Vector2d> velocities;
  main_.draw(mirror_.config().particles, &positions, &velocities);
  for (std::size_t i = 0; i < positions.size(); ++i) {
    positions[i] = mirrored(positions[i], pose_);
    velocities[i] = mirroredVelocity(velocities[i], pose_);
  }
  mirror_.assign(positions, velocities, main_.time());
  mirror_active_ = true;
}

bool ParticleTracker::mirrorDistinct() const {
  if (board_axis_) {
    return true;  // the boards' plane keeps the two apart (keepSide)
  }
  const double separation = (mirror_.mean() - main_.mean()).head<2>().norm();
  return separation > std::max(kMinMirrorSeparation, 3.0 * worstSigma(main_.covariance()));
}

void ParticleTracker::maintainMirror() {
  if (!axis_ || !main_.initialized()) {
    return;
  }
  if (mirror_active_ && mirrorDistinct() && evidence_ > config_.ambiguity_margin) {
    // The data prefer the mirror: it becomes the main hypothesis.
    std::vector<Eigen::Vector3d> positions;
    std::vector<Eigen::Vector2d> velocities;
    mirror_.draw(main_.config().particles, &positions, &velocities);
    main_.assign(positions, velocities, main_.time());
    evidence_ = -evidence_;
    ++stats_.mirror_swaps;
    last_main_mean_ = main_.mean();  // a swap is not a jump
  }
  // A main hypothesis that jumped (a young cloud settling on one of the places its first
  // epoch allowed) has left the mirror filter behind, an image of where it was: that
  // filter would then have to walk to the new mirror image on process noise alone, and
  // until it does nothing weighs the new place against its own image. It is drawn again
  // as the image of the new place; the evidence is kept (the data that built it still
  // weigh the two sides).
  const Eigen::Vector3d main_mean = main_.mean();
  const bool jumped =
      last_main_mean_ && (main_mean - *last_main_mean_).head<2>().norm() >
                             std::max(kMainJump, 3.0 * worstSigma(main_.covariance()));
  last_main_mean_ = main_mean;
  if (jumped) {
    ++stats_.mirror_redraws_after_jump;
  }
  // The mirror hypothesis follows its own data, so that it settles in the mirror's own
  // minimum (a few centimetres off the geometric mirror image when the modules are not
  // exactly collinear) and its evidence is fair. When the data reject it, its particles
  // drift onto the main one's: then it is drawn again as the main one's mirror image,
  // keeping the evidence (near the modules' axis the two coincide and the evidence stops
  // changing: the side the data chose before is kept until data say otherwise).
  if (!mirror_active_ || !mirrorDistinct() || jumped) {
    seedMirror();
  }
  if (board_axis_) {
    // The boards' plane splits the two hypotheses for good: a cloud whose distance
    // nothing fixes (no range) can drift through the board, and once wholly behind it
    // nothing pulls it back. The side changes only by the evidence (a swap above).
    const bool main_left = onMainSide(main_.mean(), pose_);
    keepSide(main_, main_left);
    keepSide(mirror_, !main_left);
  }
}

bool ParticleTracker::moved(const Pose2& pose) const {
  return std::abs(std::remainder(pose.yaw - pose_.yaw, 2.0 * kPi)) > kStill ||
         std::hypot(pose.x - pose_.x, pose.y - pose_.y) > kStill;
}

bool ParticleTracker::inFront(const Eigen::Vector3d& p, const Pose2& pose) const {
  const AoaBoard& board = layout_.aoa_boards.front();
  const Eigen::Vector3d local = board.orientation.conjugate() * (pose.fromFixed(p) - board.position);
  return local.x() >= 0.0;
}

void ParticleTracker::keepSide(ParticleFilter& filter, bool left) const {
  double astray = 0.0;
  for (std::size_t i = 0; i < filter.size(); ++i) {
    astray += onMainSide(filter.position(i), pose_) != left ? filter.weight(i) : 0.0;
  }
  if (astray < kAstrayShare) {
    return;
  }
  std::vector<Eigen::Vector3d> positions;
  std::vector<Eigen::Vector2d> velocities;
  filter.draw(filter.size(), &positions, &velocities);
  for (std::size_t i = 0; i < positions.size(); ++i) {
    if (onMainSide(positions[i], pose_) != left) {
      positions[i] = mirrored(positions[i], pose_);
      velocities[i] = mirroredVelocity(velocities[i], pose_);
    }
  }
  filter.assign(positions, velocities, filter.time());
}

TrackerOutput ParticleTracker::update(double now) {
  std::stable_sort(
      queue_.begin(), queue_.end(),
      [](const TrackedMeasurement& a, const TrackedMeasurement& b) { return a.t < b.t; });
  for (const TrackedMeasurement& m : queue_) {
    if (m.t > now + kFutureStampTolerance) {
      ++stats_.future_dropped;
      continue;
    }
    if (now - m.t > config_.max_age) {
      ++stats_.stale_dropped;
      continue;
    }
    const bool odom = m.pose.has_value();
    if (odom != in_odom_) {
      // Odometry appeared or vanished: positions in the old frame mean nothing now.
      if (main_.initialized()) {
        ++stats_.frame_switches;
      }
      reset();
      recent_.clear();
      in_odom_ = odom;
    }
    if (main_.initialized()) {
      apply(m);
    }
    recent_.push_back(m);
  }
  queue_.clear();
  while (!recent_.empty() && now - recent_.front().t > config_.max_age) {
    recent_.pop_front();
  }

  TrackerOutput out;
  out.in_odom = in_odom_;
  if (main_.initialized() && fit_ < kDivergedFit) {
    ++stats_.divergences;
    reset();  // and start again from what the sensors say now
  }
  if (!main_.initialized() && !coldStart(now)) {
    return out;
  }
  maintainMirror();
  out.stamp = main_.time();
  out.pose = pose_;
  const bool fresh = now - main_.time() <= config_.max_age;
  const Eigen::Matrix3d covariance = main_.covariance();
  const Eigen::Vector3d position = main_.mean();
  const bool ranged = rangedAt(now);
  const double sigma = worstSigma(covariance);
  const double distance = pose_.fromFixed(position).head<2>().norm();
  // A cloud wider than lost_sigma (or, far away, than twice the relative limit: a
  // bearing's sideways spread) is no position: a cold start's ring around one module,
  // whose mean is near the robot, or a track that fell apart.
  const double lost_limit =
      std::max(config_.lost_sigma, 2.0 * config_.max_relative_sigma * distance);
  if (!fresh || !position.allFinite() || !covariance.allFinite()) {
    reset();
    return out;
  }
  if (ranged && sigma > lost_limit) {
    if (!accumulates_) {
      reset();
    }
    return out;
  }
  for (const auto& [bit, stamp] : last_source_) {
    if (stamp >= 0.0 && now - stamp <= config_.max_age) {
      out.sources |= bit;
    }
  }
  out.position = position;
  out.velocity = main_.meanVelocity();
  out.covariance = covariance;
  out.hypotheses = 1;
  out.hypothesis_weight = 1.0;
  if (!ranged) {
    // Direction only, along the ray from where the bearings are taken (a board ahead of
    // base_link would otherwise turn it by the parallax of a distance nobody measured);
    // where along it is the prior's guess.
    const Eigen::Vector3d relative = pose_.fromFixed(position);
    const Eigen::Vector2d ray = relative.head<2>() - bearing_origin_;
    const Eigen::Vector2d along = bearing_origin_ + config_.default_range * ray.normalized();
    out.position = pose_.toFixed({along.x(), along.y(), position.z()});
    out.status = TargetStatus::kHeadingOnly;
    return out;
  }
  const double allowed =
      std::max(config_.max_position_sigma, config_.max_relative_sigma * distance);
  Eigen::Vector3d mixture_position = position;
  Eigen::Vector2d mixture_velocity = out.velocity;
  Eigen::Matrix3d mixture_covariance = covariance;
  if (mirror_active_ && mirrorDistinct()) {
    const double mirror_share = 1.0 / (1.0 + std::exp(-evidence_));
    out.hypothesis_weight = 1.0 - mirror_share;
    out.alternative = mirror_.mean();
    if (mirror_share >= kReportedShare) {
      out.hypotheses = 2;
      // The law of total covariance over the two hypotheses.
      const Eigen::Vector3d apart = out.alternative - position;
      mixture_position = position + mirror_share * apart;
      mixture_velocity = out.velocity + mirror_share * (mirror_.meanVelocity() - out.velocity);
      mixture_covariance = (1.0 - mirror_share) * covariance + mirror_share * mirror_.covariance() +
                           mirror_share * (1.0 - mirror_share) * apart * apart.transpose();
    }
  }
  const Eigen::Matrix3d reported = mixture_covariance + correlatedFloor(mixture_position);
  out.covariance = reported;
  if (worstSigma(reported) <= allowed) {
    // One estimate, even with a mirror close by: the mixture is where the target is.
    out.status = TargetStatus::kOk;
    out.position = mixture_position;
    out.velocity = mixture_velocity;
    return out;
  }
  // Too wide to act on: the leading hypothesis, DEGRADED, or AMBIGUOUS while the data do
  // not prefer one side of a distinct mirror.
  out.status = out.hypotheses == 2 && evidence_ > -config_.ambiguity_margin
                   ? TargetStatus::kAmbiguous
                   : TargetStatus::kDegraded;
  return out;
}

}  // namespace estimation
}  // namespace radio_follow
