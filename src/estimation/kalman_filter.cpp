// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/estimation/kalman_filter.hpp"

#include <Eigen/Cholesky>
#include <boost/math/distributions/chi_squared.hpp>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "radio_follow/common/param_error.hpp"

namespace radio_follow {
namespace estimation {

MotionModel parseMotionModel(const std::string& text, const std::string& parameter) {
  require(text == "constant_position" || text == "constant_velocity", parameter, text,
          "constant_position or constant_velocity");
  return text == "constant_velocity" ? MotionModel::kConstantVelocity
                                     : MotionModel::kConstantPosition;
}

std::string toString(MotionModel model) {
  return model == MotionModel::kConstantVelocity ? "constant_velocity" : "constant_position";
}
namespace {

bool positiveDefinite(const Eigen::MatrixXd& m) {
  if (!m.allFinite() || !m.isApprox(m.transpose(), 1e-9)) {
    return false;
  }
  const Eigen::LLT<Eigen::MatrixXd> llt(m);
  return llt.info() == Eigen::Success;
}

}  // namespace

double chiSquareQuantile(double probability, int dof) {
  if (!(probability > 0.0 && probability < 1.0)) {
    throw std::invalid_argument("chi-square quantile needs a probability in (0, 1)");
  }
  if (dof < 1) {
    throw std::invalid_argument("chi-square quantile needs at least 1 degree of freedom");
  }
  return boost::math::quantile(boost::math::chi_squared(dof), probability);
}

KalmanFilter::KalmanFilter(const KalmanConfig& config)
    : config_(config),
      n_(config.model == MotionModel::kConstantVelocity ? 2 * config.dims : config.dims),
      gate_(config.gate_probability > 0.0 ? chiSquareQuantile(config.gate_probability, config.dims)
                                          : std::numeric_limits<double>::infinity()),
      x_(Eigen::VectorXd::Zero(n_)),
      p_(Eigen::MatrixXd::Zero(n_, n_)) {}

void KalmanFilter::reset() {
  initialized_ = false;
  consecutive_gated_ = 0;
  x_.setZero();
  p_.setZero();
}

bool KalmanFilter::reconfigure(const KalmanConfig& config) {
  if (config.model == config_.model && config.dims == config_.dims) {
    config_ = config;
    gate_ = KalmanFilter(config).gate_;
    return true;
  }
  const std::size_t gated = gated_;
  const std::size_t invalid = invalid_;
  const std::size_t resets = resets_;
  *this = KalmanFilter(config);
  gated_ = gated;
  invalid_ = invalid;
  resets_ = resets;
  return false;
}

Eigen::VectorXd KalmanFilter::velocity() const {
  if (config_.model == MotionModel::kConstantVelocity) {
    return x_.tail(config_.dims);
  }
  return Eigen::VectorXd::Zero(config_.dims);
}

void KalmanFilter::initialize(const Eigen::VectorXd& z, const Eigen::MatrixXd& r, double t) {
  const int d = config_.dims;
  x_.setZero();
  x_.head(d) = z;
  p_.setZero();
  p_.topLeftCorner(d, d) = r;
  if (config_.model == MotionModel::kConstantVelocity) {
    p_.bottomRightCorner(d, d) =
        config_.initial_velocity_variance * Eigen::MatrixXd::Identity(d, d);
  }
  t_ = t;
  initialized_ = true;
  consecutive_gated_ = 0;
}

void KalmanFilter::predict(double t) {
  if (!initialized_) {
    return;
  }
  const int d = config_.dims;
  if (!(t > t_)) {
    return;  // predicting twice to the same time must not add process noise twice
  }
  const double dt = t - t_;
  t_ = t;
  const Eigen::MatrixXd eye = Eigen::MatrixXd::Identity(d, d);
  if (config_.model == MotionModel::kConstantPosition) {
    p_ += config_.process_noise * eye;
    return;
  }
  Eigen::MatrixXd f = Eigen::MatrixXd::Identity(n_, n_);
  f.topRightCorner(d, d) = dt * eye;
  Eigen::MatrixXd q(n_, n_);
  const double qa = config_.process_noise;
  q.topLeftCorner(d, d) = qa * dt * dt * dt / 3.0 * eye;
  q.topRightCorner(d, d) = qa * dt * dt / 2.0 * eye;
  q.bottomLeftCorner(d, d) = qa * dt * dt / 2.0 * eye;
  q.bottomRightCorner(d, d) = qa * dt * eye;
  x_ = f * x_;
  p_ = f * p_ * f.transpose() + q;
}

CorrectionResult KalmanFilter::correct(const Eigen::VectorXd& z, const Eigen::MatrixXd& r,
                                       double t) {
  const int d = config_.dims;
  if (z.size() != d || r.rows() != d || r.cols() != d || !z.allFinite() || !positiveDefinite(r)) {
    ++invalid_;
    return CorrectionResult::kInvalid;
  }
  if (!initialized_) {
    initialize(z, r, t);
    return CorrectionResult::kInitialized;
  }
  predict(t);
  const Eigen::VectorXd y = z - x_.head(d);
  const Eigen::MatrixXd s = p_.topLeftCorner(d, d) + r;
  const Eigen::LDLT<Eigen::MatrixXd> ldlt(s);
  const double mahalanobis2 = y.dot(ldlt.solve(y));
  if (!(mahalanobis2 <= gate_)) {
    ++gated_;
    if (++consecutive_gated_ >= config_.max_consecutive_rejections) {
      ++resets_;
      initialize(z, r, t);
      return CorrectionResult::kReset;
    }
    return CorrectionResult::kGated;
  }
  consecutive_gated_ = 0;
  // K = P H^T S^-1 with H = [I 0]: P H^T is the first d columns of P.
  const Eigen::MatrixXd pht = p_.leftCols(d);
  const Eigen::MatrixXd k = ldlt.solve(pht.transpose()).transpose();
  x_ += k * y;
  // Joseph form keeps P symmetric positive semi-definite whatever the rounding.
  Eigen::MatrixXd ikh = Eigen::MatrixXd::Identity(n_, n_);
  ikh.leftCols(d) -= k;
  p_ = ikh * p_ * ikh.transpose() + k * r * k.transpose();
  p_ = 0.5 * (p_ + p_.transpose());
  return CorrectionResult::kAccepted;
}

}  // namespace estimation
}  // namespace radio_follow
