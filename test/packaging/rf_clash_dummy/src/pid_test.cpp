// SPDX-License-Identifier: BSD-3-Clause
#include <gtest/gtest.h>

TEST(ClashDummy, Runs) {
  EXPECT_EQ(1 + 1, 2);
}

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
