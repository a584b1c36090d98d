// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/estimation/fast_exp.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

namespace rf = radio_follow::estimation;

namespace {

// Every float in [lo, hi] at a fine step, an odd count (Eigen takes the last one alone).
Eigen::ArrayXf grid(float lo, float hi, int count) {
  return Eigen::ArrayXf::LinSpaced(count, lo, hi);
}

}  // namespace

TEST(FastExp, IsWithinTenMillionthsOfExpOverTheWholeRange) {
  // The polynomial's error (3.2e-6 at most) plus, for large |x|, the rounding of
  // x log2(e) to a float (6e-8 relative, i.e. 7e-6 of the result near |x| = 86).
  const auto worst = [](float lo, float hi) {
    const Eigen::ArrayXf x = grid(lo, hi, 1'000'001);
    const Eigen::ArrayXf fast = rf::fastExp(x);
    double w = 0.0;
    for (Eigen::Index i = 0; i < x.size(); ++i) {
      const double exact = std::exp(static_cast<double>(x[i]));
      w = std::max(w, std::abs(fast[i] - exact) / exact);
    }
    return w;
  };
  EXPECT_LT(worst(-86.0f, 88.0f), 1e-5);
  EXPECT_LT(worst(-10.0f, 10.0f), 4e-6);
  EXPECT_FLOAT_EQ(rf::fastExp(Eigen::ArrayXf::Zero(5))(4), 1.0f);
}

TEST(FastExp, ClampsToNormalFloats) {
  Eigen::ArrayXf x(5);
  x << -1e30f, -1000.0f, -86.0f, 1000.0f, 1e30f;
  const Eigen::ArrayXf e = rf::fastExp(x);
  for (Eigen::Index i = 0; i < x.size(); ++i) {
    EXPECT_TRUE(std::isnormal(e[i])) << x[i];
    EXPECT_GT(e[i], 0.0f);
  }
  EXPECT_NEAR(e[0] / std::exp(-86.0f), 1.0f, 3e-6f);
  EXPECT_NEAR(e[4] / std::exp(88.0f), 1.0f, 3e-6f);
}

TEST(FastExp, ScalarAndVectorPathsAgreeBitForBit) {
  const Eigen::ArrayXf x = grid(-40.0f, 5.0f, 100'003);
  const Eigen::ArrayXf vector = rf::fastExp(x);
  const rf::FastExp scalar;
  for (Eigen::Index i = 0; i < x.size(); ++i) {
    const float s = scalar(x[i]);
    ASSERT_EQ(std::memcmp(&s, &vector[i], sizeof s), 0) << "x = " << x[i];
  }
}
