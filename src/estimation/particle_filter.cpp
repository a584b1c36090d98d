// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/estimation/particle_filter.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <utility>

namespace radio_follow {
namespace estimation {
namespace {

/// Entries of the normal table: enough that the draws of one step never repeat.
constexpr std::size_t kNormalTable = 1u << 16;
/// Measurements closer in time than this share a prediction (one step is 4 normal draws
/// per particle, the most expensive part; a walking person moves 5 mm in it), s.
constexpr double kMinPredictStep = 0.005;
/// Spread added around the given positions at initialisation, m.
constexpr double kInitialSpread = 0.02;

}  // namespace

ParticleFilter::ParticleFilter(const Config& config) : config_(config), state_(config.seed) {
  std::mt19937_64 rng(config.seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  normals_.resize(kNormalTable);
  for (float& n : normals_) {
    n = static_cast<float>(normal(rng));
  }
  state_ = config.seed * 0x9E3779B97F4A7C15ull + 1;
}

void ParticleFilter::initialize(const std::vector<Eigen::Vector3d>& positions,
                                double velocity_sigma, double t) {
  std::vector<Eigen::Vector3d> spread(config_.particles);
  std::vector<Eigen::Vector2d> velocities(config_.particles);
  for (std::size_t i = 0; i < config_.particles; ++i) {
    const Eigen::Vector3d& p = positions[i % positions.size()];
    spread[i].x() = p.x() + kInitialSpread * normal();
    spread[i].y() = p.y() + kInitialSpread * normal();
    spread[i].z() = config_.planar ? config_.height : p.z() + kInitialSpread * normal();
    velocities[i].x() = velocity_sigma * normal();
    velocities[i].y() = velocity_sigma * normal();
    if (config_.stand_time > 0.0 && uniform() < standingShare()) {
      velocities[i].setZero();
    }
  }
  assign(spread, velocities, t);
}

void ParticleFilter::assign(const std::vector<Eigen::Vector3d>& positions,
                            const std::vector<Eigen::Vector2d>& velocities, double t) {
  const auto n = static_cast<Eigen::Index>(positions.size());
  origin_.setZero();
  for (const Eigen::Vector3d& p : positions) {
    origin_ += p;
  }
  if (n > 0) {
    origin_ /= static_cast<double>(n);
  }
  if (config_.planar) {
    origin_.z() = config_.height;
  }
  x_.resize(n);
  y_.resize(n);
  z_.resize(n);
  vx_.resize(n);
  vy_.resize(n);
  w_.setConstant(n, 1.0f / static_cast<float>(n));
  walking_.setOnes(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const auto k = static_cast<std::size_t>(i);
    const Eigen::Vector3f p = local(positions[k]);
    x_[i] = p.x();
    y_[i] = p.y();
    z_[i] = config_.planar ? 0.0f : p.z();
    vx_[i] = static_cast<float>(velocities[k].x());
    vy_[i] = static_cast<float>(velocities[k].y());
    if (config_.stand_time > 0.0 && velocities[k].isZero(0.0)) {
      walking_[i] = 0.0f;
    }
  }
  t_ = t;
  initialized_ = n > 0;
}

void ParticleFilter::predict(double t) {
  const double dt = t - t_;
  if (!initialized_ || !(dt >= kMinPredictStep)) {
    return;  // measurements closer than this share one prediction
  }
  // White acceleration q per axis over dt: velocity noise sqrt(q dt) n1, position noise
  // sqrt(q dt) dt / 2 n1 + sqrt(q dt^3 / 12) n2 (covariance q [dt^3/3, dt^2/2; dt^2/2, dt]).
  const double sv = std::sqrt(config_.process_noise * dt);
  const double sp = std::sqrt(config_.process_noise * dt * dt * dt / 12.0);
  const Eigen::Index n = w_.size();
  // The draws first (four per particle from the four 16-bit parts of one random word),
  // then the motion as whole-array expressions, which vectorise.
  noise_.resize(n, 4);
  for (Eigen::Index i = 0; i < n; ++i) {
    const std::uint64_t r = nextRandom();
    noise_(i, 0) = normals_[r & 0xFFFF];
    noise_(i, 1) = normals_[(r >> 16) & 0xFFFF];
    noise_(i, 2) = normals_[(r >> 32) & 0xFFFF];
    noise_(i, 3) = normals_[r >> 48];
  }
  const auto step = static_cast<float>(dt);
  const auto half = static_cast<float>(sv * dt * 0.5);
  const auto position = static_cast<float>(sp);
  const auto velocity = static_cast<float>(sv);
  if (config_.stand_time > 0.0) {
    // Switches first (a walking particle stops with probability 1 - exp(-dt / walk_time),
    // a standing one starts with 1 - exp(-dt / stand_time)), then each moves by its mode:
    // a walker as below, a stander by its sway; a particle that stops loses its velocity,
    // one that starts walks off from rest.
    const double stop = -std::expm1(-dt / config_.walk_time);
    const double start = -std::expm1(-dt / config_.stand_time);
    for (Eigen::Index i = 0; i < n; ++i) {
      const double u = uniform();
      walking_[i] = (walking_[i] > 0.5f ? u >= stop : u < start) ? 1.0f : 0.0f;
    }
    const auto sway = static_cast<float>(std::sqrt(config_.stand_noise * dt));
    const Eigen::ArrayXf standing = 1.0f - walking_;
    x_ += walking_ * (vx_ * step + half * noise_.col(0) + position * noise_.col(2)) +
          standing * sway * noise_.col(2);
    y_ += walking_ * (vy_ * step + half * noise_.col(1) + position * noise_.col(3)) +
          standing * sway * noise_.col(3);
    vx_ = walking_ * (vx_ + velocity * noise_.col(0));
    vy_ = walking_ * (vy_ + velocity * noise_.col(1));
  } else {
    x_ += vx_ * step + half * noise_.col(0) + position * noise_.col(2);
    y_ += vy_ * step + half * noise_.col(1) + position * noise_.col(3);
    vx_ += velocity * noise_.col(0);
    vy_ += velocity * noise_.col(1);
  }
  if (!config_.planar) {
    const double sz = std::sqrt(config_.vertical_noise * dt);
    for (Eigen::Index i = 0; i < n; ++i) {
      z_[i] += static_cast<float>(sz * normal());
    }
  }
  t_ = t;
}

MeasurementFit ParticleFilter::applyLikelihood(const Eigen::ArrayXf& inlier,
                                               const Eigen::ArrayXf& outlier) {
  const double inlier_mass = (w_ * inlier).sum();
  const double evidence = inlier_mass + (w_ * outlier).sum();
  if (!(evidence > 0.0) || !std::isfinite(evidence)) {
    return {};  // weights unchanged: a measurement nothing can explain says nothing
  }
  w_ *= (inlier + outlier) * static_cast<float>(1.0 / evidence);
  return {evidence, inlier_mass / evidence};
}

MeasurementFit ParticleFilter::applyLikelihood(const Eigen::ArrayXf& inlier, double outlier) {
  // The weights sum to one: the outlier part of the evidence is the constant itself.
  const double inlier_mass = (w_ * inlier).sum();
  const double evidence = inlier_mass + outlier;
  if (!(evidence > 0.0) || !std::isfinite(evidence)) {
    return {};
  }
  w_ *= (inlier + static_cast<float>(outlier)) * static_cast<float>(1.0 / evidence);
  return {evidence, inlier_mass / evidence};
}

double ParticleFilter::restrict(const std::function<bool(const Eigen::Vector3d&)>& keep) {
  scratch_ = w_.cast<double>();
  for (Eigen::Index i = 0; i < w_.size(); ++i) {
    if (!keep(position(static_cast<std::size_t>(i)))) {
      scratch_[i] = 0.0;
    }
  }
  const double kept = scratch_.sum();
  if (kept > 0.0) {
    w_ = (scratch_ / kept).cast<float>();
  }
  return kept;
}

double ParticleFilter::effectiveSampleSize() const {
  const double s = w_.square().sum();
  return s > 0.0 ? 1.0 / s : 0.0;
}

void ParticleFilter::drawIndices(std::size_t count) {
  indices_.clear();
  if (count == 0 || w_.size() == 0) {
    return;
  }
  // Systematic: one uniform offset, `count` evenly spaced pointers into the CDF.
  const double step = 1.0 / static_cast<double>(count);
  double pointer = step * uniform();
  double cumulative = w_[0];
  Eigen::Index i = 0;
  for (std::size_t k = 0; k < count; ++k) {
    while (pointer > cumulative && i + 1 < w_.size()) {
      cumulative += w_[++i];
    }
    indices_.push_back(i);
    pointer += step;
  }
}

void ParticleFilter::draw(std::size_t count, std::vector<Eigen::Vector3d>* positions,
                          std::vector<Eigen::Vector2d>* velocities) {
  drawIndices(count);
  positions->clear();
  velocities->clear();
  for (const Eigen::Index i : indices_) {
    positions->push_back(position(static_cast<std::size_t>(i)));
    velocities->emplace_back(vx_[i], vy_[i]);
  }
}

bool ParticleFilter::resampleIfNeeded() {
  if (!initialized_ ||
      effectiveSampleSize() >= config_.resample_threshold * static_cast<double>(w_.size())) {
    return false;
  }
  // In place: every state array gathered by the drawn indices, then re-centred on the
  // new cloud's mean (as assign() does), so the offsets stay small as the target moves.
  drawIndices(static_cast<std::size_t>(w_.size()));
  const auto gather = [this](Eigen::ArrayXf& a) {
    gathered_ = a(indices_);
    a.swap(gathered_);
  };
  gather(x_);
  gather(y_);
  gather(z_);
  gather(vx_);
  gather(vy_);
  gather(walking_);
  w_.setConstant(w_.size(), 1.0f / static_cast<float>(w_.size()));
  const Eigen::Vector3f shift = localMean().cast<float>();
  x_ -= shift.x();
  y_ -= shift.y();
  z_ -= shift.z();
  origin_ += shift.cast<double>();
  return true;
}

Eigen::Vector3d ParticleFilter::localMean() const {
  return {(w_ * x_).sum(), (w_ * y_).sum(), (w_ * z_).sum()};
}

Eigen::Vector3d ParticleFilter::mean() const {
  return origin_ + localMean();
}

Eigen::Vector2d ParticleFilter::meanVelocity() const {
  return {(w_ * vx_).sum(), (w_ * vy_).sum()};
}

Eigen::Matrix3d ParticleFilter::covariance() const {
  const Eigen::Vector3d m = localMean();
  const Eigen::ArrayXf ex = x_ - static_cast<float>(m.x());
  const Eigen::ArrayXf ey = y_ - static_cast<float>(m.y());
  const Eigen::ArrayXf ez = z_ - static_cast<float>(m.z());
  Eigen::Matrix3d c;
  c(0, 0) = (w_ * ex * ex).sum();
  c(1, 1) = (w_ * ey * ey).sum();
  c(2, 2) = config_.planar ? 0.0 : (w_ * ez * ez).sum();
  c(0, 1) = c(1, 0) = (w_ * ex * ey).sum();
  c(0, 2) = c(2, 0) = config_.planar ? 0.0 : (w_ * ex * ez).sum();
  c(1, 2) = c(2, 1) = config_.planar ? 0.0 : (w_ * ey * ez).sum();
  return c;
}

Eigen::Matrix4d ParticleFilter::planarCovariance() const {
  const Eigen::Vector3d m = localMean();
  const Eigen::Vector2d v = meanVelocity();
  const Eigen::ArrayXf e[4] = {x_ - static_cast<float>(m.x()), y_ - static_cast<float>(m.y()),
                               vx_ - static_cast<float>(v.x()), vy_ - static_cast<float>(v.y())};
  Eigen::Matrix4d c;
  for (int r = 0; r < 4; ++r) {
    for (int k = r; k < 4; ++k) {
      c(r, k) = c(k, r) = (w_ * e[r] * e[k]).sum();
    }
  }
  return c;
}

}  // namespace estimation
}  // namespace radio_follow
