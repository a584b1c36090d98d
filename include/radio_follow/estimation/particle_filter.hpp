// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "radio_follow/config/layout.hpp"
#include "radio_follow/estimation/kalman_filter.hpp"

namespace radio_follow {
namespace estimation {

/// What one measurement told a filter: its marginal likelihood sum_i w_i l_i (the
/// evidence the hypothesis bank compares) and the posterior probability that it was not
/// an outlier (a filter whose particles no longer explain its inputs sees this drop).
struct MeasurementFit {
  double likelihood = 0.0;
  double inlier = 0.0;
};

/// Constant-velocity particle filter of a point target (x, y, z, vx, vy) in a fixed
/// tracking frame; z is a state only in 3D mode (a random walk). With `stand_time` > 0
/// the motion is a jump-Markov model of a person who walks and stands by turns: each
/// particle is either walking (constant velocity, white acceleration) or standing (no
/// velocity, a slow sway), and switches with the rates 1 / walk_time and 1 / stand_time.
/// A standing target seen from a moving robot is then averaged over the robot's path
/// (the range errors of real modules are correlated over seconds, which a walking model
/// cannot average), and a walking one loses nothing but the particles that stopped.
/// Weights are kept normalised; a measurement kind's `weigh*` function (weighRange(), ...)
/// multiplies them by the measurement's likelihood and returns its marginal likelihood
/// sum_i w_i l_i (the evidence the hypothesis bank compares). Deterministic for a seed.
class ParticleFilter {
 public:
  struct Config {
    std::size_t particles = 500;
    bool planar = true;
    double height = kDefaultTargetHeight;         ///< z of every particle in planar mode, m
    double process_noise = kDefaultProcessNoise;  ///< white-acceleration PSD per axis, m^2/s^3
    double vertical_noise = 0.1;  ///< 3D mode: z random-walk PSD, m^2/s
    /// Mean length of a standing spell, s; 0: no standing mode (every particle walks).
    double stand_time = 0.0;
    double walk_time = 10.0;     ///< mean length of a walking spell, s (with stand_time > 0)
    double stand_noise = 0.003;  ///< a standing target's sway: random-walk PSD per axis, m^2/s
    /// Resample (systematic) when the effective sample size falls below this share of N.
    double resample_threshold = 0.5;
    std::uint64_t seed = 1;
  };

  explicit ParticleFilter(const Config& config);

  /// Particles at `positions` (cycled when fewer than N; a small spread is added) with
  /// velocities ~ N(0, velocity_sigma^2) per axis, equal weights, clock at `t`. With the
  /// standing mode, the stationary share stand_time / (stand_time + walk_time) of them
  /// stand (velocity zero).
  void initialize(const std::vector<Eigen::Vector3d>& positions, double velocity_sigma, double t);
  bool initialized() const { return initialized_; }
  void reset() { initialized_ = false; }

  /// Moves every particle to time t (constant velocity plus the exact discretisation of
  /// white acceleration noise). Times before the filter's are ignored (see time()).
  void predict(double t);
  double time() const { return t_; }

  // What a measurement kind's likelihood reads and writes (range_measurement.hpp,
  // tdoa_measurement.hpp, bearing_measurement.hpp, rss_direction.hpp): it computes one
  // likelihood per particle from the positions below into the workspace, then
  // applyLikelihood() multiplies the weights by it.

  /// Particle positions relative to origin(), single precision (see the members).
  const Eigen::ArrayXf& localX() const { return x_; }
  const Eigen::ArrayXf& localY() const { return y_; }
  const Eigen::ArrayXf& localZ() const { return z_; }
  const Eigen::Vector3d& origin() const { return origin_; }
  /// `p` (tracking frame) relative to origin(), single precision.
  Eigen::Vector3f local(const Eigen::Vector3d& p) const { return (p - origin_).cast<float>(); }
  /// Per-particle work arrays of the likelihoods, kept so that none allocates per
  /// measurement. Their contents are the caller's between calls.
  struct Workspace {
    Eigen::ArrayXf inlier, outlier, lx, ly, lz, rho2, inv_rho, pick;
  };
  Workspace& workspace() { return work_; }
  /// Multiplies the weights by each particle's inlier + outlier likelihood and
  /// renormalises; returns the measurement's evidence and inlier probability. A
  /// measurement nothing explains (zero or non-finite evidence) leaves them unchanged.
  MeasurementFit applyLikelihood(const Eigen::ArrayXf& inlier, const Eigen::ArrayXf& outlier);
  /// The same with an outlier likelihood that is the same for every particle.
  MeasurementFit applyLikelihood(const Eigen::ArrayXf& inlier, double outlier);

  /// Systematic resampling when the effective sample size is below the threshold.
  /// Returns true when it resampled.
  bool resampleIfNeeded();
  double effectiveSampleSize() const;

  Eigen::Vector3d mean() const;
  Eigen::Vector2d meanVelocity() const;
  /// Position covariance (planar mode: zero z row and column), m^2.
  Eigen::Matrix3d covariance() const;
  /// Position-velocity covariance of the planar state (x, y, vx, vy).
  Eigen::Matrix4d planarCovariance() const;

  std::size_t size() const { return static_cast<std::size_t>(w_.size()); }
  Eigen::Vector3d position(std::size_t i) const {
    return origin_ + Eigen::Vector3d(x_[i], y_[i], z_[i]);
  }
  Eigen::Vector2d velocity(std::size_t i) const { return {vx_[i], vy_[i]}; }
  /// Whether particle i walks (always, without the standing mode).
  bool walking(std::size_t i) const { return walking_[static_cast<Eigen::Index>(i)] > 0.5f; }
  /// The weight of the walking particles (1 without the standing mode).
  double walkingShare() const { return (w_ * walking_).sum(); }
  double weight(std::size_t i) const { return w_[i]; }
  /// N particles drawn (systematically) from this cloud: (position, velocity) pairs.
  void draw(std::size_t count, std::vector<Eigen::Vector3d>* positions,
            std::vector<Eigen::Vector2d>* velocities);
  /// Zeroes the weight of every particle `keep` refuses and renormalises; returns the
  /// share of the weight kept (0: nothing changed, no particle was kept).
  double restrict(const std::function<bool(const Eigen::Vector3d&)>& keep);
  /// Replaces the cloud by the given particles with equal weights, clock at t. With the
  /// standing mode, a particle with velocity exactly zero stands (as draw() gives a
  /// standing particle's copies), every other one walks.
  void assign(const std::vector<Eigen::Vector3d>& positions,
              const std::vector<Eigen::Vector2d>& velocities, double t);

  const Config& config() const { return config_; }

 private:
  /// `count` systematic draws of particle indices by weight, into indices_.
  void drawIndices(std::size_t count);
  /// splitmix64: fast, plenty for indexing a table and systematic resampling, and its
  /// draws depend on each other only through one addition, so a loop of draws pipelines.
  std::uint64_t nextRandom() {
    std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  /// A uniform draw in [0, 1).
  double uniform() { return static_cast<double>(nextRandom() >> 11) * 0x1.0p-53; }
  /// The share of time a target of the standing mode stands.
  double standingShare() const {
    return config_.stand_time / (config_.stand_time + config_.walk_time);
  }
  /// A standard normal draw (table lookup: the filter draws millions per second).
  double normal() { return normals_[nextRandom() >> 48]; }
  /// The cloud's weighted mean relative to the origin.
  Eigen::Vector3d localMean() const;

  Config config_;
  bool initialized_ = false;
  double t_ = 0.0;
  /// Particle states in single precision, positions relative to `origin_` (the cloud's
  /// mean, set by assign() and moved at every resampling): a cloud spans metres, so its
  /// offsets keep micrometres wherever the tracking frame's origin is, and every
  /// per-particle loop takes four particles per vector instruction instead of two.
  Eigen::Vector3d origin_ = Eigen::Vector3d::Zero();
  Eigen::ArrayXf x_, y_, z_, vx_, vy_, w_;
  /// 1: the particle walks, 0: it stands (a 0/1 mask, so the motion stays arithmetic).
  Eigen::ArrayXf walking_;
  std::vector<float> normals_;
  std::uint64_t state_;
  Eigen::ArrayXd scratch_;
  /// The prediction's standard normal draws, four per particle (a column each).
  Eigen::ArrayXXf noise_;
  std::vector<Eigen::Index> indices_;  ///< drawIndices()'s result
  Eigen::ArrayXf gathered_;
  Workspace work_;
};

}  // namespace estimation
}  // namespace radio_follow
