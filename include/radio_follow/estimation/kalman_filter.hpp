// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <string>

namespace radio_follow {
namespace estimation {

/// The locator's `process_noise` unless configured: the Kalman filter's and the particle
/// filter's white-acceleration PSD per axis, m^2/s^3.
constexpr double kDefaultProcessNoise = 0.5;

enum class MotionModel {
  /// The thesis's model: x_k = x_{k-1} + w, Q = process_noise * I per epoch (m^2).
  kConstantPosition,
  /// Position and velocity with white acceleration noise of spectral density
  /// process_noise (m^2/s^3), discretised over the actual time step.
  kConstantVelocity,
};

/// "constant_position" / "constant_velocity" (the locator's `motion_model` parameter);
/// parse throws ParamError naming `parameter` for any other text.
MotionModel parseMotionModel(const std::string& text, const std::string& parameter);
std::string toString(MotionModel model);

struct KalmanConfig {
  MotionModel model = MotionModel::kConstantPosition;
  /// 2 (2D mode: x, y) or 3 (x, y, z) position dimensions.
  int dims = 2;
  double process_noise = kDefaultProcessNoise;
  /// Initial velocity variance of the constant-velocity model, (m/s)^2.
  double initial_velocity_variance = 1.0;
  /// Probability mass of the chi-square gate (dimension = dims); <= 0 disables gating.
  double gate_probability = 0.999;
  /// After this many consecutive gated measurements the filter re-initialises from the
  /// next one: the target has moved away from the prediction for good.
  int max_consecutive_rejections = 5;
};

/// Outcome of one correction.
enum class CorrectionResult { kInitialized, kAccepted, kGated, kInvalid, kReset };

/// Linear Kalman filter on the solver's position output (position measurement, H = [I 0]).
class KalmanFilter {
 public:
  explicit KalmanFilter(const KalmanConfig& config);

  /// Moves the state to time t (seconds); no-op before the first measurement and when t
  /// is not later than the state's time (the constant-position model adds its Q once per
  /// epoch, as the thesis did).
  void predict(double t);
  /// Predicts to t, then fuses a position measurement z (dims) with covariance r
  /// (dims x dims). NaN/Inf or a non-positive-definite r is rejected and counted, never repaired.
  CorrectionResult correct(const Eigen::VectorXd& z, const Eigen::MatrixXd& r, double t);
  void reset();
  /// Applies new tuning at runtime. With the same motion model and dimension the state,
  /// covariance and counters are kept and only Q, the gate and the rejection limit
  /// change (returns true); otherwise the state has another size and the filter starts
  /// again uninitialised, keeping its counters (returns false).
  bool reconfigure(const KalmanConfig& config);

  bool initialized() const { return initialized_; }
  /// Position part of the state and its covariance.
  Eigen::VectorXd position() const { return x_.head(config_.dims); }
  Eigen::MatrixXd positionCovariance() const {
    return p_.topLeftCorner(config_.dims, config_.dims);
  }
  /// Zero for the constant-position model.
  Eigen::VectorXd velocity() const;
  const Eigen::VectorXd& state() const { return x_; }
  const Eigen::MatrixXd& covariance() const { return p_; }

  std::size_t gatedCount() const { return gated_; }
  std::size_t invalidCount() const { return invalid_; }
  std::size_t resetCount() const { return resets_; }
  /// Mahalanobis gate threshold (squared distance) in use.
  double gateThreshold() const { return gate_; }

 private:
  void initialize(const Eigen::VectorXd& z, const Eigen::MatrixXd& r, double t);

  KalmanConfig config_;
  int n_;
  double gate_;
  bool initialized_ = false;
  double t_ = 0.0;
  Eigen::VectorXd x_;
  Eigen::MatrixXd p_;
  int consecutive_gated_ = 0;
  std::size_t gated_ = 0;
  std::size_t invalid_ = 0;
  std::size_t resets_ = 0;
};

/// Quantile of the chi-square distribution with `dof` degrees of freedom (boost::math);
/// throws std::invalid_argument for dof < 1 or p outside (0, 1).
double chiSquareQuantile(double probability, int dof);

}  // namespace estimation
}  // namespace radio_follow
