// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/estimation/position_solver.hpp"

#include <gtest/gtest.h>

#include <random>

#include "../../support/shipped_layout.hpp"
#include "radio_follow/common/param_error.hpp"
#include "radio_follow/estimation/fisher.hpp"
#include "radio_follow/estimation/initializer.hpp"
#include "radio_follow/estimation/synthetic_observations.hpp"

namespace radio_follow {
namespace estimation {
namespace {

TEST(PositionSolver, RecoversTruthAndCovarianceFromNoiseFreeRanges) {
  const Layout layout = test::shippedLayout("tracked.yaml");
  SolverConfig config;
  PositionSolver solver(config);
  const Eigen::Vector3d truth(3.0, -2.0, config.height);
  const ObservationSet obs = idealObservations(layout, truth, SyntheticNoise{}, 0);
  const SolveResult r = solver.solve(obs, Eigen::Vector3d(2.0, -1.0, 0.0));
  ASSERT_TRUE(r.success);
  EXPECT_LT((r.position - truth).norm(), 1e-6);
  EXPECT_DOUBLE_EQ(r.position.z(), config.height);
  EXPECT_NEAR(r.cost, 0.0, 1e-12);
  ASSERT_TRUE(r.covariance_valid);
  const auto crlb = positionCrlb(fisherInformation(obs, truth), true);
  ASSERT_TRUE(crlb.has_value());
  EXPECT_TRUE(r.covariance.isApprox(*crlb, 1e-6));
}

TEST(PositionSolver, CeresCovarianceAgreesWithFisherWithoutLoss) {
  const Layout layout = test::shippedLayout("spot.yaml");
  SolverConfig config;
  config.loss<RangeObservation>().type = config.loss<BearingObservation>().type = LossType::kNone;
  config.ceres_covariance = true;
  PositionSolver solver(config);
  const Eigen::Vector3d truth(4.0, 1.0, config.height);
  const ObservationSet obs = idealObservations(layout, truth, SyntheticNoise{}, 1);
  const SolveResult r = solver.solve(obs, truth + Eigen::Vector3d(0.3, -0.2, 0.0));
  ASSERT_TRUE(r.success && r.covariance_valid);
  const auto crlb = positionCrlb(fisherInformation(obs, truth), true);
  ASSERT_TRUE(crlb.has_value());
  const Eigen::Matrix2d ceres_xy = r.covariance.topLeftCorner<2, 2>();
  const Eigen::Matrix2d crlb_xy = crlb->topLeftCorner<2, 2>();
  EXPECT_TRUE(ceres_xy.isApprox(crlb_xy, 1e-4)) << ceres_xy << "\nvs\n" << crlb_xy;
}

TEST(PositionSolver, MultiStartFindsTheCubeTargetInEveryQuadrant) {
  const Layout layout = test::shippedLayout("cube.yaml");
  SolverConfig config;
  PositionSolver solver(config);
  InitializerConfig init;
  for (double angle : {0.5, 2.0, -2.2, -0.9}) {
    const Eigen::Vector3d truth(5.0 * std::cos(angle), 5.0 * std::sin(angle), config.height);
    const ObservationSet obs = idealObservations(layout, truth, SyntheticNoise{}, 1);
    const SolveResult r = solver.solveMultiStart(obs, multiStartCandidates(obs, init));
    ASSERT_TRUE(r.success);
    EXPECT_LT((r.position - truth).norm(), 1e-4) << "angle " << angle;
  }
}

TEST(PositionSolver, RobustLossResistsANonLineOfSightRange) {
  const Layout layout = test::shippedLayout("tracked.yaml");
  const Eigen::Vector3d truth(4.0, 3.0, 1.0);
  ObservationSet obs = idealObservations(layout, truth, SyntheticNoise{}, 0);
  obs.ranges[0].range += 2.0;  // NLOS: the direct path is blocked, the echo is longer
  SolverConfig plain;
  plain.loss<RangeObservation>().type = LossType::kNone;
  SolverConfig robust;
  robust.loss<RangeObservation>() = {LossType::kCauchy, 1.0};
  const SolveResult a = PositionSolver(plain).solve(obs, truth);
  const SolveResult b = PositionSolver(robust).solve(obs, truth);
  ASSERT_TRUE(a.success && b.success);
  EXPECT_LT((b.position - truth).norm(), 0.5 * (a.position - truth).norm());
}

TEST(PositionSolver, BearingOnlyKeepsTheDirection) {
  const Layout layout = test::shippedLayout("cube.yaml");
  SolverConfig config;
  PositionSolver solver(config);
  const Eigen::Vector3d truth(-2.0, 6.0, config.height);
  ObservationSet obs = idealObservations(layout, truth, SyntheticNoise{}, 1);
  obs.ranges.clear();
  const SolveResult r = solver.solve(obs, Eigen::Vector3d(1.0, 0.0, 0.0));
  ASSERT_TRUE(r.success);
  const double bearing = std::atan2(r.position.y() - obs.bearings[0].board.y(),
                                    r.position.x() - obs.bearings[0].board.x());
  const double truth_bearing =
      std::atan2(truth.y() - obs.bearings[0].board.y(), truth.x() - obs.bearings[0].board.x());
  EXPECT_NEAR(bearing, truth_bearing, 1e-3);
}

TEST(PositionSolver, ParsesLossNames) {
  EXPECT_EQ(parseLossType("soft_l1", "x"), LossType::kSoftL1);
  EXPECT_EQ(parseLossType("none", "x"), LossType::kNone);
  EXPECT_THROW(parseLossType("tukey", "range_loss"), ParamError);
}

}  // namespace
}  // namespace estimation
}  // namespace radio_follow
