// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/estimation/kalman_filter.hpp"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <limits>
#include <random>
#include <stdexcept>

namespace radio_follow {
namespace estimation {
namespace {

TEST(ChiSquare, QuantilesMatchTables) {
  EXPECT_NEAR(chiSquareQuantile(0.95, 1), 3.841459, 1e-5);
  EXPECT_NEAR(chiSquareQuantile(0.99, 2), 9.210340, 1e-5);
  EXPECT_NEAR(chiSquareQuantile(0.999, 3), 16.266236, 1e-5);
  EXPECT_NEAR(chiSquareQuantile(0.95, 4), 9.487729, 1e-5);
  EXPECT_THROW(chiSquareQuantile(0.9, 0), std::invalid_argument);
  EXPECT_THROW(chiSquareQuantile(1.0, 2), std::invalid_argument);
}

TEST(KalmanFilter, ConstantPositionAveragesNoise) {
  KalmanConfig config;
  config.process_noise = 1e-6;
  KalmanFilter filter(config);
  std::mt19937_64 rng(4);
  std::normal_distribution<double> noise(0.0, 0.1);
  const Eigen::Vector2d truth(2.0, -1.0);
  const Eigen::MatrixXd r = 0.01 * Eigen::MatrixXd::Identity(2, 2);
  EXPECT_EQ(filter.correct(truth + Eigen::Vector2d(noise(rng), noise(rng)), r, 0.0),
            CorrectionResult::kInitialized);
  for (int k = 1; k <= 400; ++k) {
    filter.correct(truth + Eigen::Vector2d(noise(rng), noise(rng)), r, 0.05 * k);
  }
  EXPECT_LT((filter.position() - truth).norm(), 0.03);
  // Close to the averaged variance 0.01 / 401, and symmetric PSD (Joseph form).
  const Eigen::MatrixXd p = filter.covariance();
  EXPECT_NEAR(p(0, 0), 0.01 / 401.0, 1e-4);
  EXPECT_DOUBLE_EQ(p(0, 1), p(1, 0));
  EXPECT_GE(Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(p).eigenvalues().minCoeff(), 0.0);
  EXPECT_EQ(filter.velocity().norm(), 0.0);
}

TEST(KalmanFilter, ConstantVelocityTracksAMovingTarget) {
  KalmanConfig config;
  config.model = MotionModel::kConstantVelocity;
  config.dims = 3;
  config.process_noise = 0.1;
  KalmanFilter filter(config);
  const Eigen::Vector3d v(1.0, -0.5, 0.0);
  const Eigen::MatrixXd r = 1e-4 * Eigen::MatrixXd::Identity(3, 3);
  for (int k = 0; k <= 100; ++k) {
    const double t = 0.05 * k;
    filter.correct(Eigen::Vector3d(v * t), r, t);
  }
  EXPECT_LT((filter.velocity() - v).norm(), 0.02);
  EXPECT_LT((filter.position() - v * 5.0).norm(), 0.01);
}

TEST(KalmanFilter, GatesOutliersThenResetsAfterRepeatedRejections) {
  KalmanConfig config;
  config.process_noise = 1e-4;
  config.gate_probability = 0.99;
  config.max_consecutive_rejections = 3;
  KalmanFilter filter(config);
  const Eigen::MatrixXd r = 0.01 * Eigen::MatrixXd::Identity(2, 2);
  for (int k = 0; k < 10; ++k) {
    filter.correct(Eigen::Vector2d(1.0, 1.0), r, 0.1 * k);
  }
  // A 2 m jump is > 9 sigma: gated, state unchanged.
  EXPECT_EQ(filter.correct(Eigen::Vector2d(3.0, 1.0), r, 1.0), CorrectionResult::kGated);
  EXPECT_NEAR(filter.position()(0), 1.0, 1e-6);
  EXPECT_EQ(filter.correct(Eigen::Vector2d(3.0, 1.0), r, 1.1), CorrectionResult::kGated);
  // Third in a row: the target really moved; re-initialise there.
  EXPECT_EQ(filter.correct(Eigen::Vector2d(3.0, 1.0), r, 1.2), CorrectionResult::kReset);
  EXPECT_NEAR(filter.position()(0), 3.0, 1e-12);
  EXPECT_EQ(filter.gatedCount(), 3u);
  EXPECT_EQ(filter.resetCount(), 1u);
}

TEST(KalmanFilter, RejectsInvalidMeasurementsAndCountsThem) {
  KalmanFilter filter(KalmanConfig{});
  Eigen::MatrixXd r = Eigen::MatrixXd::Identity(2, 2);
  EXPECT_EQ(filter.correct(Eigen::Vector2d(std::nan(""), 0.0), r, 0.0), CorrectionResult::kInvalid);
  r(0, 0) = -1.0;
  EXPECT_EQ(filter.correct(Eigen::Vector2d(0.0, 0.0), r, 0.0), CorrectionResult::kInvalid);
  EXPECT_EQ(filter.invalidCount(), 2u);
  EXPECT_FALSE(filter.initialized());
}

TEST(KalmanFilter, ConstantPositionAddsProcessNoiseOncePerEpoch) {
  KalmanConfig config;
  config.process_noise = 1.0;  // thesis Q = I
  KalmanFilter filter(config);
  filter.correct(Eigen::Vector2d(0.0, 0.0), 50.0 * Eigen::MatrixXd::Identity(2, 2), 0.0);
  filter.predict(0.05);
  filter.predict(0.05);
  EXPECT_DOUBLE_EQ(filter.covariance()(0, 0), 51.0);
}

}  // namespace
}  // namespace estimation
}  // namespace radio_follow
