// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/drivers/tdoa_grouper.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace radio_follow {
namespace drivers {
namespace {

TEST(TdoaBlinkGrouper, EmitsWhenEveryAnchorReported) {
  TdoaBlinkGrouper grouper(3, 0.05);
  std::vector<TdoaBlinkGroup> out;
  grouper.add(0x5A84, 7, {0, 100}, 1.000, &out);
  grouper.add(0x5A84, 7, {2, 300}, 1.001, &out);
  EXPECT_TRUE(out.empty());
  grouper.add(0x5A84, 7, {1, 200}, 1.002, &out);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_TRUE(out[0].complete);
  EXPECT_EQ(out[0].tag, 0x5A84);
  EXPECT_EQ(out[0].sequence, 7);
  EXPECT_DOUBLE_EQ(out[0].first_arrival, 1.000);
  ASSERT_EQ(out[0].receptions.size(), 3u);
  EXPECT_EQ(out[0].receptions[1].anchor, 2u);
  EXPECT_EQ(out[0].receptions[1].rx_ticks, 300u);
  EXPECT_EQ(grouper.openGroups(), 0u);
}

TEST(TdoaBlinkGrouper, KeepsTagsAndSequenceNumbersApart) {
  TdoaBlinkGrouper grouper(2, 0.05);
  std::vector<TdoaBlinkGroup> out;
  grouper.add(0x0001, 7, {0, 1}, 1.0, &out);
  grouper.add(0x0002, 7, {1, 2}, 1.0, &out);
  grouper.add(0x0001, 8, {1, 3}, 1.0, &out);
  EXPECT_TRUE(out.empty());
  EXPECT_EQ(grouper.openGroups(), 3u);
  grouper.add(0x0001, 7, {1, 4}, 1.01, &out);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0].tag, 0x0001);
  EXPECT_EQ(out[0].sequence, 7);
}

TEST(TdoaBlinkGrouper, DropsDuplicateAnchorReport) {
  TdoaBlinkGrouper grouper(2, 0.05);
  std::vector<TdoaBlinkGroup> out;
  EXPECT_EQ(grouper.add(1, 1, {0, 10}, 1.0, &out), TdoaBlinkGrouper::AddResult::kFiled);
  EXPECT_EQ(grouper.add(1, 1, {0, 11}, 1.0, &out), TdoaBlinkGrouper::AddResult::kDuplicate);
  EXPECT_TRUE(out.empty());
  grouper.add(1, 1, {1, 12}, 1.0, &out);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0].receptions[0].rx_ticks, 10u);  // the first report wins
}

TEST(TdoaBlinkGrouper, EmitsIncompleteGroupAfterTheWindow) {
  TdoaBlinkGrouper grouper(3, 0.05);
  std::vector<TdoaBlinkGroup> out;
  grouper.add(1, 1, {0, 10}, 1.0, &out);
  grouper.add(1, 1, {1, 10}, 1.01, &out);
  grouper.expire(1.049, &out);
  EXPECT_TRUE(out.empty());
  grouper.expire(1.05, &out);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_FALSE(out[0].complete);
  EXPECT_EQ(out[0].receptions.size(), 2u);
}

TEST(TdoaBlinkGrouper, SequenceWraparoundStartsANewBlink) {
  // 256 blinks later the same (tag, sequence) returns; the stale group must not absorb it.
  TdoaBlinkGrouper grouper(2, 0.05);
  std::vector<TdoaBlinkGroup> out;
  grouper.add(1, 255, {0, 10}, 1.0, &out);
  grouper.add(1, 0, {0, 20}, 1.01, &out);
  grouper.add(1, 255, {1, 99}, 26.6, &out);  // a later blink with the same number
  ASSERT_EQ(out.size(), 2u);                 // both stale groups expired, incomplete
  EXPECT_FALSE(out[0].complete);
  EXPECT_EQ(out[0].sequence, 255);
  EXPECT_EQ(out[1].sequence, 0);
  EXPECT_EQ(grouper.openGroups(), 1u);
  grouper.add(1, 255, {0, 100}, 26.61, &out);
  ASSERT_EQ(out.size(), 3u);
  EXPECT_TRUE(out[2].complete);
  EXPECT_EQ(out[2].receptions[0].rx_ticks, 99u);
}

TEST(TdoaBlinkGrouper, BoundsOpenGroups) {
  TdoaBlinkGrouper grouper(2, 10.0, 4);
  std::vector<TdoaBlinkGroup> out;
  for (int seq = 0; seq < 6; ++seq) {
    grouper.add(1, static_cast<std::uint8_t>(seq), {0, 1}, 1.0, &out);
  }
  EXPECT_EQ(grouper.openGroups(), 4u);
  EXPECT_EQ(grouper.overflows(), 2u);
  ASSERT_EQ(out.size(), 2u);
  EXPECT_EQ(out[0].sequence, 0);  // oldest first
  EXPECT_EQ(out[1].sequence, 1);
}

}  // namespace
}  // namespace drivers
}  // namespace radio_follow
