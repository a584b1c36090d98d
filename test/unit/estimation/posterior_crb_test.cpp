// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/estimation/posterior_crb.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <optional>
#include <stdexcept>
#include <vector>

#include "radio_follow/estimation/fisher.hpp"
#include "radio_follow/estimation/kalman_filter.hpp"

namespace radio_follow {
namespace estimation {
namespace {

// A static target and no process noise: the information is the prior's plus the sum of
// every measurement's Fisher information, whatever the time steps (F = I, Q = 0).
TEST(PosteriorCrb, StaticTargetWithoutProcessNoiseSumsTheFisherInformation) {
  const Eigen::Vector3d target(3.0, 1.5, 1.0);
  std::vector<ObservationSet> epochs(3);
  for (int k = 0; k < 3; ++k) {
    RangeObservation range;
    range.module = Eigen::Vector3d(0.2 * k, -0.1 * k, 0.1);
    range.sigma = 0.02 + 0.01 * k;
    epochs[static_cast<std::size_t>(k)].ranges.push_back(range);
  }
  BearingObservation bearing;
  bearing.rotation = Eigen::AngleAxisd(0.4, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  bearing.sigma_azimuth = 0.05;
  bearing.sigma_elevation = 0.1;
  epochs[1].bearings.push_back(bearing);

  const Eigen::Matrix2d prior = 1e-3 * Eigen::Matrix2d::Identity();
  PosteriorCrb pcrb(prior);
  Eigen::Matrix2d sum = Eigen::Matrix2d::Zero();
  for (const ObservationSet& obs : epochs) {
    pcrb.predict(Eigen::Matrix2d::Identity(), Eigen::Matrix2d::Zero());
    const Eigen::Matrix2d info = fisherInformation(obs, target).topLeftCorner<2, 2>();
    pcrb.addInformation(info);
    sum += info;
  }
  EXPECT_LT((pcrb.information() - (prior + sum)).norm(), 1e-9 * sum.norm());
  ObservationSet all;
  for (const ObservationSet& obs : epochs) {
    all.ranges.insert(all.ranges.end(), obs.ranges.begin(), obs.ranges.end());
    all.bearings.insert(all.bearings.end(), obs.bearings.begin(), obs.bearings.end());
  }
  // With a negligible prior the bound is the static CRLB of all measurements together.
  PosteriorCrb weak(1e-12 * Eigen::Matrix2d::Identity());
  weak.addInformation(fisherInformation(all, target).topLeftCorner<2, 2>());
  const Eigen::Matrix3d crlb = *positionCrlb(fisherInformation(all, target), true);
  EXPECT_LT((weak.bound() - crlb.topLeftCorner<2, 2>()).norm(), 1e-9 * crlb.norm());
}

// A 1D random walk x' = x + w (Q = 0.5) measured directly (R = 2) from P0 = 1: the Kalman
// covariance by hand is P1 = 1 / (1 / 1.5 + 1 / 2) = 6/7, P2 = 1 / (1 / (6/7 + 0.5) + 1 / 2)
// = 38/47; linear and Gaussian, so the PCRB is exactly that.
TEST(PosteriorCrb, OneDimensionalRandomWalkIsTheKalmanCovariance) {
  PosteriorCrb pcrb(Eigen::MatrixXd::Constant(1, 1, 1.0));
  const Eigen::MatrixXd f = Eigen::MatrixXd::Constant(1, 1, 1.0);
  const Eigen::MatrixXd q = Eigen::MatrixXd::Constant(1, 1, 0.5);
  const Eigen::MatrixXd info = Eigen::MatrixXd::Constant(1, 1, 0.5);
  pcrb.predict(f, q);
  pcrb.addInformation(info);
  EXPECT_NEAR(pcrb.bound()(0, 0), 6.0 / 7.0, 1e-12);
  pcrb.predict(f, q);
  pcrb.addInformation(info);
  EXPECT_NEAR(pcrb.bound()(0, 0), 38.0 / 47.0, 1e-12);
}

// The locator's constant-velocity Kalman filter on position measurements is a linear
// Gaussian model: its covariance must equal the PCRB with the same Q, R and prior, at
// irregular stamps.
TEST(PosteriorCrb, ConstantVelocityEqualsTheKalmanFilterCovariance) {
  KalmanConfig config;
  config.model = MotionModel::kConstantVelocity;
  config.dims = 2;
  config.process_noise = 0.5;
  config.initial_velocity_variance = 2.0;
  config.gate_probability = 0.0;
  KalmanFilter filter(config);
  Eigen::Matrix2d r;
  r << 0.04, 0.01, 0.01, 0.09;
  const std::vector<double> stamps{0.0, 0.1, 0.13, 0.3, 0.31, 0.7, 1.0};
  std::optional<PosteriorCrb> pcrb;
  double last = 0.0;
  for (const double t : stamps) {
    filter.correct(Eigen::Vector2d(1.2 * t, 2.0 - 0.3 * t), r, t);
    if (!pcrb) {
      // The filter starts at the first measurement: position covariance R, velocity
      // variance initial_velocity_variance.
      Eigen::Matrix4d p0 = Eigen::Matrix4d::Zero();
      p0.topLeftCorner<2, 2>() = r;
      p0(2, 2) = p0(3, 3) = config.initial_velocity_variance;
      pcrb.emplace(p0.inverse());
    } else {
      Eigen::Matrix4d f, q;
      constantVelocityModel(t - last, config.process_noise, &f, &q);
      pcrb->predict(f, q);
      pcrb->addInformation(r.inverse());
    }
    last = t;
    EXPECT_LT((pcrb->bound() - filter.covariance()).norm(), 1e-10) << "at t = " << t;
  }
  EXPECT_LT(pcrb->bound()(0, 0), r(0, 0));  // seven measurements beat one
}

TEST(PosteriorCrb, PredictionLosesAndMeasurementsAddInformation) {
  PosteriorCrb pcrb(Eigen::Matrix4d::Identity());
  Eigen::Matrix4d f, q;
  constantVelocityModel(0.5, 0.5, &f, &q);
  const double before = pcrb.bound().trace();
  pcrb.predict(f, q);
  const double predicted = pcrb.bound().trace();
  EXPECT_GT(predicted, before);
  pcrb.addInformation(4.0 * Eigen::Matrix2d::Identity());
  EXPECT_LT(pcrb.bound().trace(), predicted);
}

TEST(PosteriorCrb, RejectsBadInputs) {
  EXPECT_THROW(PosteriorCrb(Eigen::Matrix2d::Zero()), std::invalid_argument);
  EXPECT_THROW(PosteriorCrb(Eigen::MatrixXd::Identity(2, 3)), std::invalid_argument);
  PosteriorCrb pcrb(Eigen::Matrix2d::Identity());
  EXPECT_THROW(pcrb.predict(Eigen::Matrix3d::Identity(), Eigen::Matrix3d::Zero()),
               std::invalid_argument);
  EXPECT_THROW(pcrb.addInformation(Eigen::Matrix3d::Identity()), std::invalid_argument);
  EXPECT_THROW(pcrb.predict(Eigen::Matrix2d::Zero(), Eigen::Matrix2d::Zero()),
               std::invalid_argument);  // a singular predicted covariance
}

}  // namespace
}  // namespace estimation
}  // namespace radio_follow
