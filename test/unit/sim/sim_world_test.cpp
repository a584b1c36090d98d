// SPDX-License-Identifier: BSD-3-Clause
#include <gtest/gtest.h>

#include <cmath>

#include "radio_follow/common/angles.hpp"
#include "radio_follow/common/param_error.hpp"
#include "radio_follow/common/yaml_params.hpp"
#include "radio_follow/sim/world.hpp"

namespace radio_follow {
namespace sim {
namespace {

Layout spot() {
  return loadLayoutFile(std::string(RF_CONFIG_DIR) + "/layouts/spot.yaml");
}

Scenario standing(double x, double y) {
  Scenario s;
  s.target = TargetPath(Pose2{x, y, 0.0});
  s.duration = 100.0;
  return s;
}

TEST(World, EverySensorReportsAtItsRate) {
  WorldConfig config;
  config.profile = SensorProfile::kIdeal;  // the realistic one drops a few % of the epochs
  config.rates.twr_hz = 10.0;
  config.rates.aoa_hz = 20.0;
  World world(spot(), standing(4.0, 0.0), config);
  std::vector<int> twr(3, 0), aoa(4, 0);
  for (int i = 0; i < 1000; ++i) {  // 10 s in 10 ms steps
    const StepEvents e = world.step(0.0, 0.0, 0.01);
    for (const auto& ev : e.twr) {
      ++twr[ev.module];
      EXPECT_LE(ev.t, world.time());
      EXPECT_GT(ev.t, world.time() - 0.01 - 1e-12);
    }
    for (const auto& ev : e.aoa)
      ++aoa[ev.board];
  }
  for (int n : twr)
    EXPECT_NEAR(n, 100, 1);
  for (int n : aoa)
    EXPECT_NEAR(n, 200, 1);
}

// The anchors hear the person's device and, as often, every one of the robot's own modules
// (at its layout position): those blinks are what the locator calibrates the anchors from.
TEST(World, TdoaAnchorsHearThePersonAndTheRobotsOwnModules) {
  const Layout layout = loadLayoutFile(std::string(RF_CONFIG_DIR) + "/layouts/spot_tdoa.yaml");
  ASSERT_EQ(layout.tdoa_anchors.size(), 3u);
  WorldConfig config;
  config.profile = SensorProfile::kIdeal;
  config.tdoa_sigma = 0.0;  // exact differences
  World world(layout, standing(3.0, 2.0), config);
  const auto difference = [&](const Eigen::Vector3d& p, std::size_t a) {
    return (p - layout.tdoa_anchors[a].position).norm() -
           (p - layout.tdoa_anchors[0].position).norm();
  };
  int person = 0;
  int module = 0;
  for (int i = 0; i < 1000; ++i) {  // 10 s
    const StepEvents e = world.step(0.0, 0.0, 0.01);
    for (const auto& ev : e.tdoa) {
      ASSERT_EQ(ev.differences.size(), 2u);
      const Eigen::Vector3d from =
          ev.module ? layout.twr_modules[*ev.module].position : world.targetInRobot();
      person += !ev.module;
      module += ev.module.has_value();
      EXPECT_NEAR(ev.differences[0], difference(from, 1), 1e-9);
      EXPECT_NEAR(ev.differences[1], difference(from, 2), 1e-9);
    }
  }
  EXPECT_NEAR(person, 100, 1);  // tdoa_rate 10 Hz
  EXPECT_NEAR(module, 100, 1);  // one module, as often
}

TEST(World, TargetIsSeenInTheRobotFrame) {
  Scenario s = standing(3.0, 4.0);
  s.robot_start = Pose2{3.0, 0.0, kPi / 2.0};  // robot faces +y, target 4 m ahead
  s.target_height = 1.2;
  World world(spot(), s, WorldConfig{});
  const Eigen::Vector3d p = world.targetInRobot();
  EXPECT_NEAR(p.x(), 4.0, 1e-9);
  EXPECT_NEAR(p.y(), 0.0, 1e-9);
  EXPECT_NEAR(p.z(), 1.2, 1e-12);
}

TEST(World, RangesMatchTheGeometry) {
  WorldConfig config;
  config.profile = SensorProfile::kIdeal;  // no hardware errors
  config.twr.use_table_bias = false;
  config.twr.sigma_scale = 0.0;
  const Layout layout = spot();
  World world(layout, standing(5.0, 2.0), config);
  int seen = 0;
  for (int i = 0; i < 50; ++i) {
    for (const auto& ev : world.step(0.0, 0.0, 0.02).twr) {
      const double truth = (world.targetInRobot() - layout.twr_modules[ev.module].position).norm();
      EXPECT_NEAR(ev.range, truth, 1e-9);
      ++seen;
    }
  }
  EXPECT_GT(seen, 0);
}

TEST(World, SameSeedSameEventsOtherSeedOtherNoise) {
  auto run = [](std::uint64_t seed) {
    WorldConfig config;
    config.seed = seed;
    World world(spot(), standing(4.0, 1.0), config);
    double sum = 0.0;
    for (int i = 0; i < 200; ++i) {
      for (const auto& ev : world.step(0.3, 0.1, 0.02).twr)
        sum += ev.range;
    }
    return sum;
  };
  EXPECT_DOUBLE_EQ(run(5), run(5));
  EXPECT_NE(run(5), run(6));
}

TEST(World, RejectsBadConfigNamingTheParameter) {
  WorldConfig config;
  config.rates.aoa_hz = 0.0;
  try {
    World world(spot(), standing(1, 1), config);
    FAIL();
  } catch (const ParamError& e) {
    EXPECT_EQ(e.name(), "~aoa_rate");
  }
}

TEST(WorldConfigLoad, ReadsTheSensorProfileAndRefusesBadValuesNamingThem) {
  WorldConfig config;
  config.load(YamlParams(YAML::Load("sensor_profile: ideal\nhardware_seed: 7")));
  EXPECT_EQ(config.profile, SensorProfile::kIdeal);
  EXPECT_EQ(config.hardware_seed, 7u);
  EXPECT_EQ(WorldConfig{}.profile, SensorProfile::kRealistic) << "the default";
  const auto rejected = [](const std::string& yaml) {
    try {
      WorldConfig c;
      c.load(YamlParams(YAML::Load(yaml)));
    } catch (const ParamError& e) {
      return e.name();
    }
    return std::string("(accepted)");
  };
  EXPECT_EQ(rejected("sensor_profile: rough"), "~sensor_profile");
  EXPECT_EQ(rejected("hardware_seed: -1"), "~hardware_seed");
}

}  // namespace
}  // namespace sim
}  // namespace radio_follow
