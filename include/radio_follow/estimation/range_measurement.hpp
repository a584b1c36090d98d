// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <ceres/sized_cost_function.h>

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <optional>

#include "radio_follow/common/target_status.hpp"
#include "radio_follow/config/layout.hpp"
#include "radio_follow/estimation/correlated_error.hpp"
#include "radio_follow/estimation/particle_filter.hpp"
#include "radio_follow/estimation/robust_loss.hpp"
#include "radio_follow/estimation/tracked_reading.hpp"

namespace radio_follow {
namespace estimation {

// A two-way range (TWR) from a module on the robot to the tag: the observation, its
// model, its Ceres cost (the solver), its autodiff reference (the cost's test), its
// particle likelihood and its answers to the particle tracker (tracked_reading.hpp), in
// one place. The TDoA difference reuses the model and the likelihood
// (tdoa_measurement.hpp).

class RangeCost;

/// A two-way range from a module on the robot to the target, already calibrated. Its
/// answers to the solver (measurement_models.hpp): its cost, its loss unless tuned
/// (range_loss), the source bit of an estimate it helped.
struct RangeObservation {
  using Cost = RangeCost;
  static constexpr LossConfig kDefaultLoss{LossType::kCauchy, 2.0};
  static constexpr std::uint8_t kSource = kSourceTwr;

  Eigen::Vector3d module = Eigen::Vector3d::Zero();  ///< module position, fixed frame, m
  double range = 0.0;                                ///< measured range, m
  double sigma = 0.03;                               ///< standard deviation, m
};

// The analytic models are shared by the Ceres cost functions (residual and Jacobian), the
// Fisher information (Jacobian only) and the simulators (prediction). Residuals are
// whitened; Jacobians are with respect to the target position p.

/// Predicted range and its unit gradient; a zero-length difference gets a zero gradient
/// (the range has no derivative there, and any unit vector would bias the step).
inline double predictRange(const Eigen::Vector3d& p, const Eigen::Vector3d& module,
                           Eigen::RowVector3d* gradient) {
  const Eigen::Vector3d d = p - module;
  const double r = d.norm();
  if (gradient != nullptr) {
    *gradient = r > 1e-12 ? Eigen::RowVector3d(d.transpose() / r) : Eigen::RowVector3d::Zero();
  }
  return r;
}

inline double rangeResidual(const RangeObservation& z, const Eigen::Vector3d& p,
                            Eigen::RowVector3d* jacobian) {
  const double r = predictRange(p, z.module, jacobian);
  if (jacobian != nullptr) {
    *jacobian /= z.sigma;
  }
  return (r - z.range) / z.sigma;
}

/// The whitened residual's Jacobian (the Fisher information's part of a range).
inline Eigen::RowVector3d residualJacobian(const RangeObservation& z, const Eigen::Vector3d& p) {
  Eigen::RowVector3d j;
  rangeResidual(z, p, &j);
  return j;
}

/// Analytic (||p - m|| - r) / sigma, one parameter block: the target position [x, y, z]
/// in the fixed frame. About three times cheaper to evaluate than RangeFunctor.
class RangeCost final : public ceres::SizedCostFunction<1, 3> {
 public:
  explicit RangeCost(const RangeObservation& z) : z_(z) {}
  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override {
    const Eigen::Map<const Eigen::Vector3d> p(parameters[0]);
    Eigen::RowVector3d j;
    residuals[0] = rangeResidual(z_, p, jacobians != nullptr ? &j : nullptr);
    if (jacobians != nullptr && jacobians[0] != nullptr) {
      Eigen::Map<Eigen::RowVector3d> out(jacobians[0]);
      out = j;
    }
    return true;
  }

 private:
  RangeObservation z_;
};

/// Autodiff reference for RangeCost (ceres::AutoDiffCostFunction): what the analytic
/// Jacobian is tested against.
struct RangeFunctor {
  explicit RangeFunctor(const RangeObservation& z) : z_(z) {}
  template <typename T>
  bool operator()(const T* p, T* residual) const {
    using std::sqrt;
    T sq = T(0.0);
    for (int i = 0; i < 3; ++i) {
      const T d = p[i] - T(z_.module[i]);
      sq += d * d;
    }
    residual[0] = (sqrt(sq) - T(z_.range)) / T(z_.sigma);
    return true;
  }
  RangeObservation z_;
};

/// A range or distance-difference likelihood with heavy tails (seed 001's robust
/// measurement model; real UWB: doc/nodes/locator.md, "Particle estimator"):
///   l(e) = (1 - eps) N(e; 0, sigma^2) + eps [0.9 (e > 0) exp(-e / L) / L + 0.1 / (2 W)],
/// e = measured - predicted. A reflection only ever makes a range longer, so most of the
/// outlier mass is on the long side; the small two-sided floor keeps every particle
/// alive under any measurement (no zero weights, no underflow).
struct RangeLikelihood {
  double sigma = 0.07;          ///< m
  double outlier_share = 0.02;  ///< eps
  double outlier_length = 1.0;  ///< L, mean excess of a long outlier, m
  bool one_sided = true;        ///< false (TDoA: either anchor's path may be long): symmetric
  double floor_width = 20.0;    ///< W, m

  /// l(e), not normalised over the outlier floor's support.
  double operator()(double error) const;
  /// The inlier (Gaussian) and outlier (tail and floor) parts of l(e) of every error in
  /// `error`, in single precision, into the two buffers (`inlier` may alias `error`).
  void evaluate(const Eigen::ArrayXf& error, Eigen::ArrayXf* inlier, Eigen::ArrayXf* outlier) const;
};

/// Weighs `filter`'s particles by a range from `module` (tracking frame).
MeasurementFit weighRange(ParticleFilter& filter, const Eigen::Vector3d& module, double range,
                          const RangeLikelihood& model);

/// A calibrated range of TWR module `module` (layout index), as the particle tracker
/// takes it: it fixes the distance, and a cold start samples a ring around the module.
struct RangeReading {
  static constexpr std::uint8_t kSource = RangeObservation::kSource;
  static constexpr bool kFixesDistance = true;
  static constexpr ColdSeed kColdSeed = ColdSeed::kRing;
  static constexpr const char* kTopicsParam = "uwb_topics";
  /// Its tuning in the tracker (ParticleTrackerConfig::of(), from LocatorConfig).
  struct Tuning {
    RangeLikelihood likelihood;  ///< range_sigma, range_outlier_share, range_outlier_length
    /// A module's ranges closer in time than this are not independent (real errors stay
    /// correlated over tenths of a second and longer): one arriving dt < this after the
    /// module's previous one counts as dt / this of a measurement (its sigma grows by
    /// sqrt(this / dt)), so a 100 Hz module carries the information of a 10 Hz one and the
    /// cloud does not collapse onto the current error. s; 0: every range counts fully.
    double decorrelation_time = 0.1;
    /// The slowly varying part of the error (correlated_error.hpp): the floor of the
    /// reported covariance, m.
    double bias_sigma = 0.05;
  };
  static std::size_t expectedSensors(const Layout& layout) { return layout.twr_modules.size(); }
  SensorPair sensors() const { return {module, 0}; }
  std::optional<SensorPair> heardAs() const { return sensors(); }

  std::size_t module = 0;
  double range = 0.0;  ///< m
};

/// The range likelihood (range_sigma, grown by the context's decorrelation factor).
MeasurementFit weigh(const RangeReading& r, ParticleFilter& filter, const TrackerContext& c);
/// The range's gradient at `position` with its white and slowly varying sigmas.
std::optional<InformingSensor> informing(const RangeReading& r, const Eigen::Vector3d& position,
                                         const TrackerContext& c);
/// range_decorrelation_time.
Decorrelation decorrelation(const RangeReading& r, const TrackerContext& c);
inline bool usable(const RangeReading& /*r*/, const TrackerContext& /*c*/) {
  return true;
}
/// The module's position and the range.
SeedRing seedRing(const RangeReading& r, const TrackerContext& c);

/// A known module and a plausible positive raw range, then the module's calibration.
Intake accept(RangeReading& r, const LocatorIntake& c);
/// A RangeObservation with range_sigma; the estimate's ranges_used and ranges_m.
void observe(const RangeReading& r, double t, const LocatorIntake& c, FreshMeasurements& fresh,
             LocatorEstimate& out);

}  // namespace estimation
}  // namespace radio_follow
