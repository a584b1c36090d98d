// SPDX-License-Identifier: BSD-3-Clause
#include <ceres/ceres.h>
#include <gtest/gtest.h>

#include <random>

#include "radio_follow/estimation/fisher.hpp"
#include "radio_follow/estimation/measurement_models.hpp"

namespace radio_follow {
namespace estimation {
namespace {

template <int R>
void expectSameCost(const ceres::CostFunction& analytic, const ceres::CostFunction& autodiff,
                    const Eigen::Vector3d& p) {
  const double* params[] = {p.data()};
  double ra[R];
  double rb[R];
  double ja[R * 3];
  double jb[R * 3];
  double* jacs_a[] = {ja};
  double* jacs_b[] = {jb};
  ASSERT_TRUE(analytic.Evaluate(params, ra, jacs_a));
  ASSERT_TRUE(autodiff.Evaluate(params, rb, jacs_b));
  for (int i = 0; i < R; ++i) {
    EXPECT_NEAR(ra[i], rb[i], 1e-9) << "residual " << i << " at " << p.transpose();
  }
  for (int i = 0; i < R * 3; ++i) {
    EXPECT_NEAR(ja[i], jb[i], 1e-7 * (1.0 + std::abs(jb[i])))
        << "jacobian entry " << i << " at " << p.transpose();
  }
}

Eigen::Vector3d randomPoint(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-8.0, 8.0);
  return {u(rng), u(rng), 0.3 * u(rng)};
}

TEST(CostFunctors, RangeAnalyticMatchesAutodiff) {
  std::mt19937_64 rng(1);
  for (int i = 0; i < 50; ++i) {
    RangeObservation z;
    z.module = 0.2 * randomPoint(rng);
    z.range = 3.0;
    z.sigma = 0.03;
    RangeCost analytic(z);
    ceres::AutoDiffCostFunction<RangeFunctor, 1, 3> autodiff(new RangeFunctor(z));
    expectSameCost<1>(analytic, autodiff, randomPoint(rng));
  }
}

TEST(CostFunctors, TdoaAnalyticMatchesAutodiff) {
  std::mt19937_64 rng(2);
  for (int i = 0; i < 50; ++i) {
    TdoaObservation z;
    z.anchor_a = 0.2 * randomPoint(rng);
    z.anchor_b = 0.2 * randomPoint(rng);
    z.difference = 0.1;
    z.sigma = 0.05;
    TdoaCost analytic(z);
    ceres::AutoDiffCostFunction<TdoaFunctor, 1, 3> autodiff(new TdoaFunctor(z));
    expectSameCost<1>(analytic, autodiff, randomPoint(rng));
  }
}

TEST(CostFunctors, BearingAnalyticMatchesAutodiffForRotatedBoards) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> angle(-kPi, kPi);
  for (int i = 0; i < 50; ++i) {
    BearingObservation z;
    z.board = 0.1 * randomPoint(rng);
    z.rotation = (Eigen::AngleAxisd(angle(rng), Eigen::Vector3d::UnitZ()) *
                  Eigen::AngleAxisd(0.3 * angle(rng), Eigen::Vector3d::UnitY()))
                     .toRotationMatrix();
    z.azimuth = angle(rng);
    z.elevation = 0.2 * angle(rng);
    z.use_elevation = (i % 2) == 0;
    BearingCost analytic(z);
    ceres::AutoDiffCostFunction<BearingFunctor, 2, 3> autodiff(new BearingFunctor(z));
    expectSameCost<2>(analytic, autodiff, randomPoint(rng));
  }
}

TEST(CostFunctors, BearingResidualIsWrapped) {
  BearingObservation z;
  z.azimuth = kPi - 0.01;  // measured just short of +pi
  z.sigma_azimuth = 0.01;
  z.use_elevation = false;
  // Target just past -pi: the true error is 0.02 rad, not 2 pi - 0.02.
  const Eigen::Vector3d p(-5.0, -5.0 * std::tan(0.01), 0.0);
  const Eigen::Vector2d r = bearingResidual(z, p, nullptr);
  EXPECT_NEAR(r(0), 2.0, 1e-6);
  EXPECT_EQ(r(1), 0.0);
}

TEST(CostFunctors, ZeroRangeHasFiniteJacobian) {
  RangeObservation z;
  z.module = Eigen::Vector3d(1.0, 2.0, 3.0);
  z.range = 0.5;
  Eigen::RowVector3d j;
  const double r = rangeResidual(z, z.module, &j);
  EXPECT_NEAR(r, -0.5 / z.sigma, 1e-12);
  EXPECT_TRUE(j.allFinite());
  EXPECT_EQ(j.norm(), 0.0);
  BearingObservation b;
  Eigen::Matrix<double, 2, 3> jb;
  bearingResidual(b, Eigen::Vector3d(0.0, 0.0, 2.0), &jb);  // straight above the board
  EXPECT_TRUE(jb.allFinite());
}

TEST(Fisher, TwoOrthogonalRangesGiveDiagonalInformation) {
  ObservationSet obs;
  RangeObservation a;
  a.module = Eigen::Vector3d(-10.0, 0.0, 0.0);
  a.sigma = 0.1;
  RangeObservation b;
  b.module = Eigen::Vector3d(0.0, -10.0, 0.0);
  b.sigma = 0.2;
  obs.ranges = {a, b};
  const Eigen::Matrix3d info = fisherInformation(obs, Eigen::Vector3d::Zero());
  EXPECT_NEAR(info(0, 0), 100.0, 1e-9);
  EXPECT_NEAR(info(1, 1), 25.0, 1e-9);
  EXPECT_NEAR(info(0, 1), 0.0, 1e-9);
  const auto crlb = positionCrlb(info, true);
  ASSERT_TRUE(crlb.has_value());
  EXPECT_NEAR((*crlb)(0, 0), 0.01, 1e-12);
  EXPECT_NEAR((*crlb)(1, 1), 0.04, 1e-12);
  EXPECT_EQ((*crlb)(2, 2), 0.0);
  // In 3D the z direction has no information: unobservable, no bound.
  EXPECT_FALSE(positionCrlb(info, false).has_value());
}

TEST(Fisher, BearingInformationIsTangential) {
  ObservationSet obs;
  BearingObservation z;
  z.sigma_azimuth = 0.01;
  z.use_elevation = false;
  obs.bearings.push_back(z);
  const Eigen::Matrix3d info = fisherInformation(obs, Eigen::Vector3d(5.0, 0.0, 0.0));
  // Azimuth information about y is 1 / (range * sigma)^2, none along the bearing.
  EXPECT_NEAR(info(1, 1), 1.0 / (0.05 * 0.05), 1e-6);
  EXPECT_NEAR(info(0, 0), 0.0, 1e-12);
}

}  // namespace
}  // namespace estimation
}  // namespace radio_follow
