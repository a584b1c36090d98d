// SPDX-License-Identifier: BSD-3-Clause
// Live tuning of the locator core: Locator::setConfig and KalmanFilter::reconfigure.
#include <gtest/gtest.h>

#include "../../support/true_ranges.hpp"
#include "radio_follow/common/param_error.hpp"
#include "radio_follow/estimation/locator.hpp"

namespace radio_follow {
namespace estimation {
namespace {

using test::feedRanges;
/// These tests feed true ranges: the layout without its range calibration.
Layout spotTwr() {
  return test::uncalibratedLayout("spot_twr.yaml");
}

TEST(LocatorSetConfig, NoiseChangesKeepTheTrack) {
  LocatorConfig config = test::solverBackend();
  Locator locator(spotTwr(), config);
  const Eigen::Vector3d truth(-2.0, 3.0, config.height);
  feedRanges(locator, truth, 1.0);
  ASSERT_EQ(locator.update(1.0).status, TargetStatus::kOk);
  const Eigen::VectorXd state = locator.filter().state();
  const Eigen::MatrixXd covariance = locator.filter().covariance();

  config.process_noise = 4.0;
  config.range_sigma = 0.1;
  config.gate_probability = 0.99;
  config.max_age = 0.2;
  EXPECT_TRUE(locator.setConfig(config));
  EXPECT_TRUE(locator.filter().initialized());
  EXPECT_EQ(locator.filter().state(), state);
  EXPECT_EQ(locator.filter().covariance(), covariance);
  EXPECT_DOUBLE_EQ(locator.config().process_noise, 4.0);
  EXPECT_LT(locator.filter().gateThreshold(), KalmanFilter(KalmanConfig{}).gateThreshold());
  // The new max_age applies to the buffered ranges: 0.3 s later they are stale.
  EXPECT_EQ(locator.update(1.3).status, TargetStatus::kLost);
}

TEST(LocatorSetConfig, MotionModelChangeRestartsTheFilter) {
  LocatorConfig config = test::solverBackend();
  config.motion_model = MotionModel::kConstantPosition;  // the thesis's, to switch from
  Locator locator(spotTwr(), config);
  const Eigen::Vector3d truth(-2.0, 3.0, config.height);
  feedRanges(locator, truth, 1.0);
  ASSERT_EQ(locator.update(1.0).status, TargetStatus::kOk);
  config.motion_model = MotionModel::kConstantVelocity;
  EXPECT_FALSE(locator.setConfig(config));
  EXPECT_FALSE(locator.filter().initialized());
  EXPECT_EQ(locator.filter().state().size(), 4);
  feedRanges(locator, truth, 1.1);
  const LocatorEstimate e = locator.update(1.1);
  EXPECT_EQ(e.status, TargetStatus::kOk);
  EXPECT_LT((e.position - truth).norm(), 1e-3);
}

TEST(LocatorSetConfig, EstimatorSwitchRestartsTheTrack) {
  LocatorConfig config = test::solverBackend();
  Locator locator(spotTwr(), config);
  const Eigen::Vector3d truth(-2.0, 3.0, config.height);
  feedRanges(locator, truth, 1.0);
  ASSERT_EQ(locator.update(1.0).status, TargetStatus::kOk);
  config.estimator = Estimator::kParticle;
  config.gate_probability = 0.99;
  EXPECT_FALSE(locator.setConfig(config));
  EXPECT_FALSE(locator.filter().initialized());
  // The idle solver estimator takes new tuning too: a switch back finds it.
  EXPECT_LT(locator.filter().gateThreshold(), KalmanFilter(KalmanConfig{}).gateThreshold());
  config.estimator = Estimator::kSolver;
  EXPECT_FALSE(locator.setConfig(config));
  feedRanges(locator, truth, 1.1);
  const LocatorEstimate e = locator.update(1.1);
  EXPECT_EQ(e.status, TargetStatus::kOk);
  EXPECT_LT((e.position - truth).norm(), 1e-3);
}

TEST(LocatorSetConfig, InvalidOrModeChangingConfigIsRefusedAndTheOldOneKept) {
  LocatorConfig config = test::solverBackend();
  config.motion_model = MotionModel::kConstantPosition;  // state size 2 in the plane
  Locator locator(spotTwr(), config);
  LocatorConfig bad = config;
  bad.range_sigma = -0.1;
  try {
    locator.setConfig(bad);
    FAIL() << "a negative sigma was accepted";
  } catch (const ParamError& e) {
    EXPECT_EQ(e.name(), "~range_sigma");
  }
  EXPECT_DOUBLE_EQ(locator.config().range_sigma, config.range_sigma);
  LocatorConfig three_d = config;
  three_d.planar = false;
  EXPECT_THROW(locator.setConfig(three_d), ParamError);
  EXPECT_TRUE(locator.config().planar);
  EXPECT_EQ(locator.filter().state().size(), 2);
}

TEST(KalmanFilterReconfigure, KeepsCountersWhenTheStateSizeChanges) {
  KalmanConfig config;
  config.max_consecutive_rejections = 100;
  KalmanFilter filter(config);
  const Eigen::Matrix2d r = 0.01 * Eigen::Matrix2d::Identity();
  ASSERT_EQ(filter.correct(Eigen::Vector2d(0, 0), r, 0.0), CorrectionResult::kInitialized);
  ASSERT_EQ(filter.correct(Eigen::Vector2d(50, 0), r, 0.1), CorrectionResult::kGated);
  config.model = MotionModel::kConstantVelocity;
  EXPECT_FALSE(filter.reconfigure(config));
  EXPECT_FALSE(filter.initialized());
  EXPECT_EQ(filter.gatedCount(), 1u);
  EXPECT_EQ(filter.state().size(), 4);
}

}  // namespace
}  // namespace estimation
}  // namespace radio_follow
