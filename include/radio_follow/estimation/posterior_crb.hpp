// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <Eigen/Core>

namespace radio_follow {
namespace estimation {

/// The posterior Cramer-Rao bound (PCRB) of a tracked state: the covariance no estimator
/// of the state from the measurements so far can beat, for a linear-Gaussian motion model
/// x_{k+1} = F x_k + w, w ~ N(0, Q), and measurements of known information. Tichavsky,
/// Muravchik and Nehorai's recursion (IEEE TSP 46(5), 1998) on the information J:
///   J_{k+1} = (Q + F J_k^{-1} F^T)^{-1} + E[H^T R^{-1} H],
/// one prediction per time step and one information term per measurement at its own stamp
/// (doc/locator_accuracy.md, "Walking person against the posterior CRB"). For a linear
/// model with Gaussian noise the bound is the Kalman filter's covariance.
class PosteriorCrb {
 public:
  /// Starts from the prior's information (the inverse of its covariance; positive
  /// definite). Throws std::invalid_argument when it is not square or not positive definite.
  explicit PosteriorCrb(const Eigen::MatrixXd& prior_information);

  /// One motion step: J <- (Q + F J^{-1} F^T)^{-1}. Q may be zero (F must then be
  /// invertible). Throws std::invalid_argument on a size mismatch or when the predicted
  /// covariance is not positive definite.
  void predict(const Eigen::MatrixXd& f, const Eigen::MatrixXd& q);

  /// Adds a measurement's information about the leading block of the state (e.g. the
  /// position of a (position, velocity) state): J.topLeft += information.
  void addInformation(const Eigen::MatrixXd& information);

  const Eigen::MatrixXd& information() const { return j_; }
  /// The bound: J^{-1}.
  Eigen::MatrixXd bound() const;

 private:
  Eigen::MatrixXd j_;
};

/// The transition F and process noise Q over dt of the planar constant-velocity model
/// (x, y, vx, vy) with white acceleration noise of spectral density `acceleration_psd` per
/// axis (m^2/s^3): Q = q [dt^3/3, dt^2/2; dt^2/2, dt] per axis, the exact discretisation the
/// locator's Kalman and particle filters use (`process_noise`).
void constantVelocityModel(double dt, double acceleration_psd, Eigen::Matrix4d* f,
                           Eigen::Matrix4d* q);

}  // namespace estimation
}  // namespace radio_follow
