// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <ceres/sized_cost_function.h>

#include <Eigen/Core>

#include "radio_follow/estimation/particle_filter.hpp"
#include "radio_follow/estimation/range_measurement.hpp"

namespace radio_follow {
namespace estimation {

// A TDoA distance difference between two anchors on the robot: the observation, its
// model, its Ceres cost, its autodiff reference, its particle likelihood (the range's
// heavy-tailed one, symmetric: either anchor's path may be long) and its answers to the
// particle tracker (tracked_reading.hpp).

class TdoaCost;

/// A TDoA distance difference |p - a| - |p - b|. Its loss unless tuned: tdoa_loss.
struct TdoaObservation {
  using Cost = TdoaCost;
  static constexpr LossConfig kDefaultLoss{LossType::kCauchy, 2.0};
  static constexpr std::uint8_t kSource = kSourceTdoa;

  Eigen::Vector3d anchor_a = Eigen::Vector3d::Zero();  ///< fixed frame, m
  Eigen::Vector3d anchor_b = Eigen::Vector3d::Zero();  ///< fixed frame, m
  double difference = 0.0;                             ///< m
  double sigma = 0.1;                                  ///< m
};

/// Whitened residual and its Jacobian with respect to the target position p.
inline double tdoaResidual(const TdoaObservation& z, const Eigen::Vector3d& p,
                           Eigen::RowVector3d* jacobian) {
  Eigen::RowVector3d ga;
  Eigen::RowVector3d gb;
  const double ra = predictRange(p, z.anchor_a, jacobian != nullptr ? &ga : nullptr);
  const double rb = predictRange(p, z.anchor_b, jacobian != nullptr ? &gb : nullptr);
  if (jacobian != nullptr) {
    *jacobian = (ga - gb) / z.sigma;
  }
  return (ra - rb - z.difference) / z.sigma;
}

inline Eigen::RowVector3d residualJacobian(const TdoaObservation& z, const Eigen::Vector3d& p) {
  Eigen::RowVector3d j;
  tdoaResidual(z, p, &j);
  return j;
}

/// Analytic (||p - a|| - ||p - b|| - d) / sigma.
class TdoaCost final : public ceres::SizedCostFunction<1, 3> {
 public:
  explicit TdoaCost(const TdoaObservation& z) : z_(z) {}
  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override {
    const Eigen::Map<const Eigen::Vector3d> p(parameters[0]);
    Eigen::RowVector3d j;
    residuals[0] = tdoaResidual(z_, p, jacobians != nullptr ? &j : nullptr);
    if (jacobians != nullptr && jacobians[0] != nullptr) {
      Eigen::Map<Eigen::RowVector3d> out(jacobians[0]);
      out = j;
    }
    return true;
  }

 private:
  TdoaObservation z_;
};

/// Autodiff reference for TdoaCost.
struct TdoaFunctor {
  explicit TdoaFunctor(const TdoaObservation& z) : z_(z) {}
  template <typename T>
  bool operator()(const T* p, T* residual) const {
    using std::sqrt;
    T sa = T(0.0);
    T sb = T(0.0);
    for (int i = 0; i < 3; ++i) {
      const T da = p[i] - T(z_.anchor_a[i]);
      const T db = p[i] - T(z_.anchor_b[i]);
      sa += da * da;
      sb += db * db;
    }
    residual[0] = (sqrt(sa) - sqrt(sb) - T(z_.difference)) / T(z_.sigma);
    return true;
  }
  TdoaObservation z_;
};

/// Weighs `filter`'s particles by the difference |p - a| - |p - b| of anchors `a` and `b`
/// (tracking frame); `model` should be symmetric (one_sided false).
MeasurementFit weighTdoa(ParticleFilter& filter, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                         double difference, const RangeLikelihood& model);

/// A distance difference |p - a| - |p - b| of TDoA anchors `anchor_a` and `anchor_b`
/// (layout indices), offset-corrected, as the particle tracker takes it: it fixes the
/// distance once several pairs cross, and a cold start samples a disc around the robot
/// (one pair's hyperbola gives a direction only). All pairs count as one sensor heard.
struct TdoaReading {
  static constexpr std::uint8_t kSource = TdoaObservation::kSource;
  static constexpr bool kFixesDistance = true;
  static constexpr ColdSeed kColdSeed = ColdSeed::kDisc;
  static constexpr const char* kTopicsParam = "tdoa_topics";
  struct Tuning {
    /// The range's, symmetric: either anchor's path may be the long one.
    RangeLikelihood likelihood = [] {
      RangeLikelihood l;
      l.one_sided = false;
      return l;
    }();
    double bias_sigma = 0.05;  ///< m, the slowly varying error (correlated_error.hpp)
  };
  static std::size_t expectedSensors(const Layout& layout) {
    return layout.tdoa_anchors.empty() ? 0 : 1;
  }
  SensorPair sensors() const { return {anchor_a, anchor_b}; }
  std::optional<SensorPair> heardAs() const { return SensorPair{0, 0}; }

  std::size_t anchor_a = 0;
  std::size_t anchor_b = 0;
  double difference = 0.0;  ///< m
  double sigma = 0.0;       ///< m, the message's or tdoa_sigma
};

/// The symmetric heavy-tailed likelihood with the reading's own sigma.
MeasurementFit weigh(const TdoaReading& r, ParticleFilter& filter, const TrackerContext& c);
std::optional<InformingSensor> informing(const TdoaReading& r, const Eigen::Vector3d& position,
                                         const TrackerContext& c);
/// None: a blink's differences come from different anchor pairs.
inline Decorrelation decorrelation(const TdoaReading& /*r*/, const TrackerContext& /*c*/) {
  return {};
}
inline bool usable(const TdoaReading& /*r*/, const TrackerContext& /*c*/) {
  return true;
}

/// Two distinct known anchors and a plausible difference; the pair's learnt offset
/// removed while TDoA auto-calibration is active (held, counted in
/// LocatorStats::tdoa_uncalibrated, until the pair has one); a sigma that is not positive
/// and finite becomes tdoa_sigma.
Intake accept(TdoaReading& r, const LocatorIntake& c);
/// A TdoaObservation with the reading's sigma.
void observe(const TdoaReading& r, double t, const LocatorIntake& c, FreshMeasurements& fresh,
             LocatorEstimate& out);

}  // namespace estimation
}  // namespace radio_follow
