// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/estimation/correlated_error.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <random>
#include <vector>

namespace radio_follow {
namespace estimation {
namespace {

InformingSensor range(const Eigen::Vector3d& sensor, const Eigen::Vector3d& target, double white,
                      double bias) {
  return {rangeGradient(sensor, target, true), white, bias};
}

TEST(CorrelatedError, OneRangeBoundsOnlyItsOwnDirection) {
  const Eigen::Vector3d target(3.0, 0.0, 1.0);
  const Eigen::Matrix3d p =
      correlatedErrorCovariance({range(Eigen::Vector3d(0.0, 0.0, 1.0), target, 0.07, 0.05)});
  // Along the line of sight: the bias itself; across it the range says nothing, and this
  // floor adds nothing there (the estimate's prior owns that direction).
  EXPECT_NEAR(p(0, 0), 0.05 * 0.05, 1e-12);
  EXPECT_NEAR(p(1, 1), 0.0, 1e-12);
  EXPECT_NEAR(p(2, 2), 0.0, 1e-12);
  EXPECT_TRUE(p.allFinite());
}

TEST(CorrelatedError, NoSensorsNoFloor) {
  EXPECT_EQ(correlatedErrorCovariance({}), Eigen::Matrix3d::Zero());
  // A target on top of its sensor has no direction: nothing, not NaN.
  const Eigen::Vector3d at(1.0, 1.0, 1.0);
  EXPECT_EQ(correlatedErrorCovariance({range(at, at, 0.07, 0.05)}), Eigen::Matrix3d::Zero());
}

// The formula is the covariance of a weighted least-squares fit whose measurements carry
// constant errors: draw the errors, solve, compare.
TEST(CorrelatedError, MatchesTheSpreadOfFitsToBiasedMeasurements) {
  const Eigen::Vector3d target(2.0, 1.5, 1.0);
  std::vector<InformingSensor> sensors = {
      range(Eigen::Vector3d(0.3, 0.2, 0.1), target, 0.07, 0.05),
      range(Eigen::Vector3d(-0.3, 0.2, 0.1), target, 0.07, 0.05),
      range(Eigen::Vector3d(0.0, -0.3, 0.1), target, 0.07, 0.05),
      {azimuthGradient(Eigen::Vector3d(0.0, 0.0, 0.2), target), 0.087, 0.035},
  };
  const Eigen::Matrix3d expected = correlatedErrorCovariance(sensors);
  Eigen::MatrixXd h(sensors.size(), 2);
  Eigen::VectorXd w(sensors.size());
  for (std::size_t i = 0; i < sensors.size(); ++i) {
    h.row(i) = sensors[i].gradient.head<2>().transpose();
    w(i) = 1.0 / (sensors[i].white_sigma * sensors[i].white_sigma);
  }
  const Eigen::MatrixXd normal = h.transpose() * w.asDiagonal() * h;
  std::mt19937_64 rng(7);
  std::normal_distribution<double> unit(0.0, 1.0);
  Eigen::Matrix2d sample = Eigen::Matrix2d::Zero();
  const int trials = 20000;
  for (int t = 0; t < trials; ++t) {
    Eigen::VectorXd bias(sensors.size());
    for (std::size_t i = 0; i < sensors.size(); ++i) {
      bias(i) = sensors[i].bias_sigma * unit(rng);
    }
    const Eigen::Vector2d shift = normal.ldlt().solve(h.transpose() * w.asDiagonal() * bias);
    sample += shift * shift.transpose() / trials;
  }
  const double tolerance = 0.03 * expected.topLeftCorner<2, 2>().norm();
  EXPECT_LT((sample - expected.topLeftCorner<2, 2>()).cwiseAbs().maxCoeff(), tolerance)
      << "sampled\n"
      << sample << "\nformula\n"
      << expected.topLeftCorner<2, 2>();
  EXPECT_GT(expected(0, 0), 0.0);
}

TEST(CorrelatedError, AzimuthGradientIsAcrossTheLineOfSightOverTheDistance) {
  const Eigen::Vector3d g =
      azimuthGradient(Eigen::Vector3d::Zero(), Eigen::Vector3d(0.0, 4.0, 1.0));
  EXPECT_NEAR(g.x(), -0.25, 1e-12);
  EXPECT_NEAR(g.y(), 0.0, 1e-12);
  EXPECT_NEAR(g.z(), 0.0, 1e-12);
}

}  // namespace
}  // namespace estimation
}  // namespace radio_follow
