// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/control/target_motion.hpp"

#include <gtest/gtest.h>

#include <random>

namespace radio_follow {
namespace control {
namespace {

TEST(TargetMotion, RecoversAConstantVelocityFromNoisyPositions) {
  TargetMotion motion;
  std::mt19937 rng(7);
  std::normal_distribution<double> noise(0.0, 0.05);
  double t = 0.0;
  for (; t < 3.0; t += 0.1) {
    motion.add(t, Eigen::Vector2d(1.0 + 0.8 * t + noise(rng), -0.6 * t + noise(rng)));
  }
  const auto v = motion.velocity(t);
  ASSERT_TRUE(v.has_value());
  // Slope sigma with 10 samples over 0.9 s and 0.05 m noise is ~0.055 m/s.
  EXPECT_NEAR(v->x(), 0.8, 0.2);
  EXPECT_NEAR(v->y(), -0.6, 0.2);
}

TEST(TargetMotion, ExactOnNoiselessData) {
  TargetMotion motion;
  for (int i = 0; i < 20; ++i) {
    motion.add(0.1 * i, Eigen::Vector2d(0.5 * 0.1 * i, 2.0));
  }
  const auto v = motion.velocity(1.9);
  ASSERT_TRUE(v.has_value());
  EXPECT_NEAR(v->x(), 0.5, 1e-9);
  EXPECT_NEAR(v->y(), 0.0, 1e-9);
}

TEST(TargetMotion, NoVelocityFromTooFewOrTooOldSamples) {
  TargetMotion motion;
  EXPECT_FALSE(motion.velocity(0.0).has_value());
  for (int i = 0; i < 4; ++i) {
    motion.add(0.1 * i, Eigen::Vector2d(0.1 * i, 0.0));
  }
  EXPECT_FALSE(motion.velocity(0.3).has_value()) << "4 samples < min_samples";
  motion.add(0.4, Eigen::Vector2d(0.4, 0.0));
  motion.add(0.5, Eigen::Vector2d(0.5, 0.0));
  EXPECT_TRUE(motion.velocity(0.5).has_value());
  // Two seconds later the samples are outside the window: the target may have stopped.
  EXPECT_FALSE(motion.velocity(2.5).has_value());
}

TEST(TargetMotion, SamplesBunchedInTimeAreRejected) {
  TargetMotion motion;
  for (int i = 0; i < 10; ++i) {
    motion.add(1.0 + 0.01 * i, Eigen::Vector2d(0.0, 0.0));  // 0.09 s span < 0.5 s
  }
  EXPECT_FALSE(motion.velocity(1.1).has_value());
}

TEST(TargetMotion, OutOfOrderAndNonFiniteSamplesAreIgnored) {
  TargetMotion motion;
  for (int i = 0; i < 10; ++i) {
    motion.add(0.1 * i, Eigen::Vector2d(0.1 * i, 0.0));
  }
  motion.add(0.5, Eigen::Vector2d(100.0, 0.0));  // older than the newest
  motion.add(1.0, Eigen::Vector2d(std::nan(""), 0.0));
  const auto v = motion.velocity(0.9);
  ASSERT_TRUE(v.has_value());
  EXPECT_NEAR(v->x(), 1.0, 1e-9);
}

}  // namespace
}  // namespace control
}  // namespace radio_follow
