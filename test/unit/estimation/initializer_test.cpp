// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/estimation/initializer.hpp"

#include <gtest/gtest.h>

#include "radio_follow/config/layout.hpp"
#include "radio_follow/estimation/synthetic_observations.hpp"

namespace radio_follow {
namespace estimation {
namespace {

Layout layoutFile(const std::string& name) {
  return loadLayoutFile(std::string(RF_CONFIG_DIR) + "/layouts/" + name);
}

class TrilaterationQuadrants : public ::testing::TestWithParam<double> {};

TEST_P(TrilaterationQuadrants, RecoversNoiseFreeTargetInEveryDirection) {
  for (const char* name : {"spot_twr.yaml", "tracked.yaml"}) {
    const Layout layout = layoutFile(name);
    InitializerConfig config;
    config.height = 1.1;
    for (double distance : {1.0, 4.0, 10.0}) {
      const Eigen::Vector3d truth(distance * std::cos(GetParam()), distance * std::sin(GetParam()),
                                  config.height);
      const ObservationSet obs = idealObservations(layout, truth, SyntheticNoise{}, 0);
      const auto p = trilaterate(obs.ranges, config);
      ASSERT_TRUE(p.has_value()) << name;
      EXPECT_LT((*p - truth).norm(), 1e-6) << name << " at " << truth.transpose();
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
  ranges.pop_back();
  EXPECT_FALSE(trilaterate(ranges, config).has_value());
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
  const Layout layout = layoutFile("cube.yaml");
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
