// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/common/input_watch.hpp"

#include <gtest/gtest.h>

namespace radio_follow {
namespace {

using Indices = std::vector<std::size_t>;

TEST(InputWatch, NeverPublishedIsSilentAfterTheTimeoutFromTheStart) {
  InputWatch watch({"/uwb/5722/ranges", "/aoa/front/bearing"}, 3.0, 10.0, 100.0);
  EXPECT_TRUE(watch.silentInputs(102.9).empty());  // not yet: give the drivers time
  EXPECT_EQ(watch.silentInputs(103.1), (Indices{0, 1}));
  EXPECT_NEAR(watch.silenceSeconds(1, 103.1), 3.1, 1e-9);
}

TEST(InputWatch, ReportsTheFirstMessageOnceAndASilenceAfterIt) {
  InputWatch watch({"a", "b"}, 3.0, 10.0, 0.0);
  EXPECT_TRUE(watch.onMessage(0, 1.0));
  EXPECT_FALSE(watch.onMessage(0, 2.0));
  EXPECT_EQ(watch.silentInputs(4.0), (Indices{1}));  // a: 2 s ago; b: never
  EXPECT_EQ(watch.silentInputs(5.5), (Indices{0, 1}));
  EXPECT_EQ(watch.inputs()[0].messages, 2u);
  EXPECT_TRUE(watch.onMessage(1, 6.0));
  EXPECT_EQ(watch.silentInputs(6.0), (Indices{0}));
}

TEST(InputWatch, WarnsAtMostOncePerPeriodPerInput) {
  InputWatch watch({"a", "b"}, 1.0, 10.0, 0.0);
  watch.onMessage(1, 0.5);
  EXPECT_EQ(watch.dueWarnings(2.0), (Indices{0, 1}));
  EXPECT_TRUE(watch.dueWarnings(3.0).empty());
  EXPECT_TRUE(watch.dueWarnings(11.9).empty());
  EXPECT_EQ(watch.dueWarnings(12.0), (Indices{0, 1}));
  watch.onMessage(0, 12.5);
  EXPECT_EQ(watch.dueWarnings(30.0), (Indices{0, 1}));  // silent again, period passed
}

TEST(InputWatch, RestartForgetsEverything) {
  InputWatch watch({"a"}, 1.0, 10.0, 0.0);
  watch.onMessage(0, 0.5);
  watch.restart(50.0);
  EXPECT_FALSE(watch.silent(0, 50.5));
  EXPECT_TRUE(watch.silent(0, 51.5));
  EXPECT_TRUE(watch.onMessage(0, 52.0));  // a first message again
}

}  // namespace
}  // namespace radio_follow
