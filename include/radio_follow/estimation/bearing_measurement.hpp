// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <ceres/sized_cost_function.h>

#include <Eigen/Core>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>

#include "radio_follow/common/angles.hpp"
#include "radio_follow/common/target_status.hpp"
#include "radio_follow/config/layout.hpp"
#include "radio_follow/estimation/correlated_error.hpp"
#include "radio_follow/estimation/particle_filter.hpp"
#include "radio_follow/estimation/robust_loss.hpp"
#include "radio_follow/estimation/tracked_reading.hpp"

namespace radio_follow {
namespace estimation {

// An angle-of-arrival bearing (azimuth and elevation) measured by an AoA board: the
// observation, its model, its Ceres cost, its autodiff reference, its particle likelihood
// and its answers to the particle tracker (tracked_reading.hpp), in one place.

class BearingCost;

/// An angle-of-arrival bearing measured by one board, in that board's frame. Its loss
/// unless tuned: bearing_loss.
struct BearingObservation {
  using Cost = BearingCost;
  static constexpr LossConfig kDefaultLoss{LossType::kHuber, 2.0};
  static constexpr std::uint8_t kSource = kSourceAoa;

  Eigen::Vector3d board = Eigen::Vector3d::Zero();  ///< board position, fixed frame, m
  /// Rotation board -> fixed frame (columns are the board axes in the fixed frame).
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  double azimuth = 0.0;    ///< rad, CCW about board z, 0 = boresight
  double elevation = 0.0;  ///< rad, towards board +z
  double sigma_azimuth = 0.035;
  double sigma_elevation = 0.087;
  bool use_elevation = true;  ///< false: the elevation residual is always zero
};

/// Azimuth and elevation of p as seen from a board (board frame), radians.
inline Eigen::Vector2d predictBearing(const Eigen::Vector3d& p, const Eigen::Vector3d& board,
                                      const Eigen::Matrix3d& rotation) {
  const Eigen::Vector3d v = rotation.transpose() * (p - board);
  return {std::atan2(v.y(), v.x()), std::atan2(v.z(), std::hypot(v.x(), v.y()))};
}

/// Whitened, wrapped (azimuth, elevation) residual. Straight above or below the board the
/// azimuth is undefined: its Jacobian row is zero there rather than infinite.
inline Eigen::Vector2d bearingResidual(const BearingObservation& z, const Eigen::Vector3d& p,
                                       Eigen::Matrix<double, 2, 3>* jacobian) {
  const Eigen::Vector3d v = z.rotation.transpose() * (p - z.board);
  const double rho2 = v.x() * v.x() + v.y() * v.y();
  const double rho = std::sqrt(rho2);
  const double n2 = rho2 + v.z() * v.z();
  Eigen::Vector2d residual;
  residual(0) = wrapAngleFast(std::atan2(v.y(), v.x()) - z.azimuth) / z.sigma_azimuth;
  residual(1) = z.use_elevation
                    ? wrapAngleFast(std::atan2(v.z(), rho) - z.elevation) / z.sigma_elevation
                    : 0.0;
  if (jacobian != nullptr) {
    Eigen::Matrix<double, 2, 3> dv = Eigen::Matrix<double, 2, 3>::Zero();
    if (rho2 > 1e-18) {
      dv.row(0) << -v.y() / rho2, v.x() / rho2, 0.0;
      if (z.use_elevation) {
        dv.row(1) << -v.x() * v.z() / (rho * n2), -v.y() * v.z() / (rho * n2), rho / n2;
      }
    }
    dv.row(0) /= z.sigma_azimuth;
    dv.row(1) /= z.sigma_elevation;
    *jacobian = dv * z.rotation.transpose();
  }
  return residual;
}

inline Eigen::Matrix<double, 2, 3> residualJacobian(const BearingObservation& z,
                                                    const Eigen::Vector3d& p) {
  Eigen::Matrix<double, 2, 3> j;
  bearingResidual(z, p, &j);
  return j;
}

/// Analytic wrapped (azimuth, elevation) residual in the board frame.
class BearingCost final : public ceres::SizedCostFunction<2, 3> {
 public:
  explicit BearingCost(const BearingObservation& z) : z_(z) {}
  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override {
    const Eigen::Map<const Eigen::Vector3d> p(parameters[0]);
    Eigen::Matrix<double, 2, 3> j;
    Eigen::Map<Eigen::Vector2d> r(residuals);
    r = bearingResidual(z_, p, jacobians != nullptr ? &j : nullptr);
    if (jacobians != nullptr && jacobians[0] != nullptr) {
      Eigen::Map<Eigen::Matrix<double, 2, 3, Eigen::RowMajor>> out(jacobians[0]);
      out = j;
    }
    return true;
  }

 private:
  BearingObservation z_;
};

/// Autodiff reference for BearingCost.
struct BearingFunctor {
  explicit BearingFunctor(const BearingObservation& z) : z_(z) {}
  template <typename T>
  bool operator()(const T* p, T* residual) const {
    using std::atan2;
    using std::sqrt;
    T v[3];
    for (int k = 0; k < 3; ++k) {
      v[k] = T(0.0);
      for (int i = 0; i < 3; ++i) {
        v[k] += T(z_.rotation(i, k)) * (p[i] - T(z_.board[i]));
      }
    }
    residual[0] = wrapAngle(atan2(v[1], v[0]) - T(z_.azimuth)) / T(z_.sigma_azimuth);
    residual[1] = z_.use_elevation
                      ? wrapAngle(atan2(v[2], sqrt(v[0] * v[0] + v[1] * v[1])) - T(z_.elevation)) /
                            T(z_.sigma_elevation)
                      : T(0.0);
    return true;
  }
  BearingObservation z_;
};

/// A bearing likelihood for real boards (issue 35; doc/nodes/locator.md, "Bearings"): von
/// Mises in azimuth (and elevation), concentration 1 / sigma^2, mixed with a uniform share
/// for reflections, so an error of any size costs at most the floor (real boards: median
/// 8 deg, p95 30 deg). A board cannot tell a tag in front from one behind its plane: a
/// particle behind the board predicts the mirrored direction with the same likelihood,
/// times `behind_weight` (the field of view's prior: the board faces where the tag is
/// expected, and its ground plane hears less from behind). So the size of an error never
/// decides the side; only a change of geometry does (the robot turning or driving), or
/// that prior.
struct BearingLikelihood {
  /// Which angle decides whether the board sees the target (its sigma then grows by
  /// `edge_sigma_factor`).
  enum class FieldOfViewTest {
    /// The cloud's mean, mirrored to the board's front, for every particle alike: a
    /// tracked cloud's estimate.
    kCloudMean,
    /// Each particle's own angle, mirrored to the front: a cold start's cloud spread
    /// around the robot, whose mean (near the robot) says nothing about where the
    /// target is.
    kEachParticle,
  };
  double azimuth_sigma = deg2rad(5.0);     ///< rad
  double elevation_sigma = deg2rad(10.0);  ///< rad
  bool use_elevation = true;
  double outlier_share = 0.05;  ///< reflections, from any direction
  /// Elevations alone off (shadowed: the wearer's body between tag and board), uniform.
  double elevation_outlier_share = 0.1;
  double field_of_view = 1.22;     ///< rad; beyond it the sigma grows
  double edge_sigma_factor = 6.0;  ///< sigma factor of a bearing measured outside it
  double behind_weight = 0.5;      ///< likelihood factor of a particle behind the board
  FieldOfViewTest field_of_view_test = FieldOfViewTest::kCloudMean;
};

/// Weighs `filter`'s particles by a bearing of the board at `board` whose axes
/// `rotation` turns into the tracking frame; azimuth and elevation in the board frame.
MeasurementFit weighBearing(ParticleFilter& filter, const Eigen::Vector3d& board,
                            const Eigen::Matrix3d& rotation, double azimuth, double elevation,
                            const BearingLikelihood& model);

/// A bearing of AoA board `board` (layout index) in the board's frame, elevation offset
/// removed, as the particle tracker takes it: a direction only, and a cold start samples
/// rays along it when nothing fixes the distance.
struct BearingReading {
  static constexpr std::uint8_t kSource = BearingObservation::kSource;
  static constexpr bool kFixesDistance = false;
  static constexpr ColdSeed kColdSeed = ColdSeed::kRay;
  static constexpr const char* kTopicsParam = "aoa_topics";
  struct Tuning {
    BearingLikelihood likelihood;
    /// The range's decorrelation for a board's bearings while ranges fix the distance
    /// (real boards report about 30 a second, whose errors share the geometry's multipath
    /// and stay correlated for seconds while the person walks); without a range, at most
    /// one advertising interval (0.1 s), s; 0: all fully.
    double decorrelation_time = 0.5;
    double bias_sigma = deg2rad(2.0);  ///< rad, the azimuth's slowly varying error
  };
  static std::size_t expectedSensors(const Layout& layout) { return layout.aoa_boards.size(); }
  SensorPair sensors() const { return {board, 0}; }
  std::optional<SensorPair> heardAs() const { return sensors(); }

  std::size_t board = 0;
  double azimuth = 0.0;    ///< rad
  double elevation = 0.0;  ///< rad
  double rssi = 0.0;       ///< dBm (the solver's board selection, the RSS direction)
};

/// The bearing likelihood with the board's field of view (tested on the cloud's mean, or
/// on each particle during a cold start), the field of view's prior only when every board
/// faces the same way, the decorrelation factor, and a wider elevation when no range
/// fixes the distance.
MeasurementFit weigh(const BearingReading& r, ParticleFilter& filter, const TrackerContext& c);
/// The azimuth's gradient at `position`; nothing when the board does not see it there (the
/// filter all but ignores such a board).
std::optional<InformingSensor> informing(const BearingReading& r, const Eigen::Vector3d& position,
                                         const TrackerContext& c);
/// bearing_decorrelation_time while a range fixes the distance; without one, at most one
/// advertising interval (the bearings are then all the direction there is).
Decorrelation decorrelation(const BearingReading& r, const TrackerContext& c);
inline bool usable(const BearingReading& /*r*/, const TrackerContext& /*c*/) {
  return true;
}
/// The board's position and orientation and the angles.
SeedRay seedRay(const BearingReading& r, const TrackerContext& c);

/// A known board and plausible angles, then the board's elevation offset removed (a real
/// board reads low): both estimators, and the published bearing, see the corrected one.
Intake accept(BearingReading& r, const LocatorIntake& c);
/// The board as a candidate for the solver's selection (which boards may speak is the
/// estimator's choice); the estimate's bearings_fresh and bearing_angles.
void observe(const BearingReading& r, double t, const LocatorIntake& c, FreshMeasurements& fresh,
             LocatorEstimate& out);

}  // namespace estimation
}  // namespace radio_follow
