// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/estimation/posterior_crb.hpp"

#include <Eigen/Cholesky>
#include <stdexcept>
#include <string>

namespace radio_follow {
namespace estimation {
namespace {

/// The inverse of a symmetric positive definite matrix by LLT; throws when it is not.
Eigen::MatrixXd inverseSpd(const Eigen::MatrixXd& m, const char* what) {
  const Eigen::LLT<Eigen::MatrixXd> llt(m);
  if (llt.info() != Eigen::Success || !m.allFinite()) {
    throw std::invalid_argument(std::string("PosteriorCrb: ") + what +
                                " is not symmetric positive definite");
  }
  const Eigen::MatrixXd inverse = llt.solve(Eigen::MatrixXd::Identity(m.rows(), m.cols()));
  return 0.5 * (inverse + inverse.transpose());  // keep it exactly symmetric
}

}  // namespace

PosteriorCrb::PosteriorCrb(const Eigen::MatrixXd& prior_information) : j_(prior_information) {
  if (j_.rows() != j_.cols() || j_.rows() == 0) {
    throw std::invalid_argument("PosteriorCrb: the prior information must be square");
  }
  inverseSpd(j_, "the prior information");
}

void PosteriorCrb::predict(const Eigen::MatrixXd& f, const Eigen::MatrixXd& q) {
  const Eigen::Index n = j_.rows();
  if (f.rows() != n || f.cols() != n || q.rows() != n || q.cols() != n) {
    throw std::invalid_argument("PosteriorCrb::predict: F and Q must match the state's size");
  }
  const Eigen::MatrixXd p = f * inverseSpd(j_, "the information") * f.transpose() + q;
  j_ = inverseSpd(p, "the predicted covariance");
}

void PosteriorCrb::addInformation(const Eigen::MatrixXd& information) {
  if (information.rows() != information.cols() || information.rows() > j_.rows()) {
    throw std::invalid_argument(
        "PosteriorCrb::addInformation: a square block no larger than the state");
  }
  j_.topLeftCorner(information.rows(), information.cols()) += information;
}

Eigen::MatrixXd PosteriorCrb::bound() const {
  return inverseSpd(j_, "the information");
}

void constantVelocityModel(double dt, double acceleration_psd, Eigen::Matrix4d* f,
                           Eigen::Matrix4d* q) {
  f->setIdentity();
  (*f)(0, 2) = (*f)(1, 3) = dt;
  const double a = acceleration_psd;
  q->setZero();
  (*q)(0, 0) = (*q)(1, 1) = a * dt * dt * dt / 3.0;
  (*q)(0, 2) = (*q)(2, 0) = (*q)(1, 3) = (*q)(3, 1) = a * dt * dt / 2.0;
  (*q)(2, 2) = (*q)(3, 3) = a * dt;
}

}  // namespace estimation
}  // namespace radio_follow
