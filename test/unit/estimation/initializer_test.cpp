// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/estimation/initializer.hpp"

#include <gtest/gtest.h>

#include "../../support/shipped_layout.hpp"
#include "radio_follow/config/layout.hpp"
#include "radio_follow/estimation/synthetic_observations.hpp"

namespace radio_follow {
namespace estimation {
namespace {

class TrilaterationQuadrants : public ::testing::TestWithParam<double> {};

TEST_P(TrilaterationQuadrants, RecoversNoiseFreeTargetInEveryDirection) {
  for (const char* name : {"spot_twr.yaml", "tracked.yaml"}) {
    const Layout layout = test::shippedLayout(name);
    InitializerConfig config;
    config.height = 1.1;
    for (double distance : {1.0, 4.0, 10.0}) {
      const Eigen::Vector3d truth(distance * std::cos(GetParam()), distance * std::sin(GetParam()),
                                  config.height);
      const ObservationSet obs = idealObservations(layout, truth, SyntheticNoise{}, 0);
      const auto p = trilaterate(obs.ranges, config);
      ASSERT_TRUE(p.has_value()) << name;
      EXPECT_LT((*p - truth).norm(), 1e-6) << name << " at " << truth.transpose();
      const auto q = trilaterateQr(obs.ranges, config);
      ASSERT_TRUE(q.has_value()) << name;
      EXPECT_LT((*q - truth).norm(), 1e-6) << name << " at " << truth.transpose();
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Angles, TrilaterationQuadrants,
                         ::testing::Values(0.3, 1.9, -2.5, -0.7, 3.1));

TEST(Trilateration, ThreeDimensionsNeedsFourNonCoplanarModules) {
  std::vector<RangeObservation> ranges;
  const Eigen::Vector3d truth(2.0, -3.0, 1.5);
  for (const Eigen::Vector3d& m : {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(0.5, 0, 0),
                                   Eigen::Vector3d(0, 0.5, 0), Eigen::Vector3d(0, 0, 0.5)}) {
    RangeObservation z;
    z.module = m;
    z.range = (truth - m).norm();
    ranges.push_back(z);
  }
  InitializerConfig config;
  config.planar = false;
  const auto p = trilaterate(ranges, config);
  ASSERT_TRUE(p.has_value());
  EXPECT_LT((*p - truth).norm(), 1e-9);
  const auto q = trilaterateQr(ranges, config);
  ASSERT_TRUE(q.has_value());
  EXPECT_LT((*q - truth).norm(), 1e-9);
  ranges.pop_back();
  EXPECT_FALSE(trilaterate(ranges, config).has_value());
  EXPECT_FALSE(trilaterateQr(ranges, config).has_value());
}

/// Noise-free ranges of `truth` from modules at `modules` (2D, on the target's plane).
std::vector<RangeObservation> exactRanges(const std::vector<Eigen::Vector3d>& modules,
                                          const Eigen::Vector3d& truth) {
  std::vector<RangeObservation> ranges;
  for (const Eigen::Vector3d& m : modules) {
    RangeObservation z;
    z.module = m;
    z.range = (truth - m).norm();
    ranges.push_back(z);
  }
  return ranges;
}

TEST(TrilaterationQr, CollinearModulesAreRejectedLikeTheNormalEquations) {
  InitializerConfig config;
  config.height = 0.0;
  const Eigen::Vector3d truth(3.0, 2.0, 0.0);
  // Four modules on one line (consecutive differences all parallel), then one just off it.
  std::vector<Eigen::Vector3d> modules{{0, 0, 0}, {0.2, 0.1, 0}, {0.4, 0.2, 0}, {0.6, 0.3, 0}};
  EXPECT_FALSE(trilaterateQr(exactRanges(modules, truth), config).has_value());
  EXPECT_FALSE(trilaterate(exactRanges(modules, truth), config).has_value());
  modules.push_back({0.3, 0.5, 0});
  const auto q = trilaterateQr(exactRanges(modules, truth), config);
  ASSERT_TRUE(q.has_value());
  EXPECT_LT((*q - truth).norm(), 1e-9);
}

TEST(TrilaterationQr, TooFewRangesGiveNothing) {
  InitializerConfig config;
  const auto ranges = exactRanges({{0, 0, 1}, {1, 0, 1}}, {2, 2, 1});
  EXPECT_FALSE(trilaterateQr(ranges, config).has_value());
  EXPECT_FALSE(trilaterateQr({}, config).has_value());
}

TEST(TrilaterationQr, IllConditionedGeometryStillRecoversExactRanges) {
  // Modules 0.5 m apart along x, one 0.3 mm off that line, the target 30 m away. The
  // first differences' A has cond 7400, its normal matrix 5.4e7 (just inside the
  // degeneracy limit of 1e8); the consecutive differences' A has cond 2000. Both still
  // recover the target to 1e-9 m (measured: 3e-10 and 2e-10 m): the rounding of the
  // right-hand side's squared ranges, not the squared condition number, sets the error.
  InitializerConfig config;
  config.height = 0.0;
  const Eigen::Vector3d truth(21.0, 21.5, 0.0);
  std::vector<Eigen::Vector3d> modules{{0, 0, 0}, {0.5, 0.0, 0}, {1.0, 0.0003, 0}, {1.5, 0.0, 0}};
  const auto p = trilaterate(exactRanges(modules, truth), config);
  const auto q = trilaterateQr(exactRanges(modules, truth), config);
  ASSERT_TRUE(p.has_value());
  ASSERT_TRUE(q.has_value());
  EXPECT_LT((*p - truth).norm(), 1e-9);
  EXPECT_LT((*q - truth).norm(), 1e-9);
  // 0.2 mm off the line: the normal matrix's rcond (8e-9) is below the limit, the QR's
  // R-diagonal ratio (1/3000) is not. Each test judges its own matrix; they disagree here.
  modules[2].y() = 0.0002;
  EXPECT_FALSE(trilaterate(exactRanges(modules, truth), config).has_value());
  const auto q2 = trilaterateQr(exactRanges(modules, truth), config);
  ASSERT_TRUE(q2.has_value());
  EXPECT_LT((*q2 - truth).norm(), 1e-8);
}

TEST(Trilateration, CollinearModulesAreRejected) {
  std::vector<RangeObservation> ranges(3);
  for (int i = 0; i < 3; ++i) {
    ranges[static_cast<std::size_t>(i)].module = Eigen::Vector3d(0.2 * i, 0.0, 0.0);
    ranges[static_cast<std::size_t>(i)].range = 3.0;
  }
  EXPECT_FALSE(trilaterate(ranges, InitializerConfig{}).has_value());
}

TEST(MultiStart, BearingCandidateComesFirstAtTheRange) {
  const Layout layout = test::shippedLayout("cube.yaml");
  const Eigen::Vector3d truth(-3.0, 2.0, 1.0);
  const ObservationSet obs = idealObservations(layout, truth, SyntheticNoise{}, 1);
  ASSERT_EQ(obs.bearings.size(), 1u);
  InitializerConfig config;
  const auto starts = multiStartCandidates(obs, config);
  ASSERT_EQ(starts.size(), 1u + static_cast<std::size_t>(config.circle_points));
  EXPECT_LT((starts.front() - truth).norm(), 0.15);
  for (const auto& s : starts) {
    EXPECT_DOUBLE_EQ(s.z(), config.height);
  }
}

}  // namespace
}  // namespace estimation
}  // namespace radio_follow
