// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/control/follower_state.hpp"

#include <gtest/gtest.h>

#include "radio_follow/control/announcement_queue.hpp"

namespace radio_follow {
namespace control {
namespace {

TEST(FollowerState, StopReasonsMapToStates) {
  EXPECT_EQ(stateFor(StopReason::kTooClose), FollowerState::kTooClose);
  EXPECT_EQ(stateFor(StopReason::kEstimateStale), FollowerState::kTargetLost);
  EXPECT_EQ(stateFor(StopReason::kRangesSilent), FollowerState::kTargetLost);
  EXPECT_EQ(stateFor(StopReason::kDisabled), FollowerState::kDisabled);
  EXPECT_EQ(stopText(StopReason::kTooClose), "Too close, stopping.");
}

TEST(FollowerState, NamesAreTheMessageConstantsInLowerCase) {
  // FollowerStatus.STATE_<NAME> without the prefix; diagnostics show these, not numbers.
  EXPECT_STREQ(toString(FollowerState::kDisabled), "disabled");
  EXPECT_STREQ(toString(FollowerState::kWaitingForTarget), "waiting_for_target");
  EXPECT_STREQ(toString(FollowerState::kFollowing), "following");
  EXPECT_STREQ(toString(FollowerState::kTooClose), "too_close");
  EXPECT_STREQ(toString(FollowerState::kTargetLost), "target_lost");
  EXPECT_STREQ(toString(FollowerState::kArrived), "arrived");
  EXPECT_STREQ(toString(FollowerState::kTargetAmbiguous), "target_ambiguous");
  EXPECT_STREQ(toString(static_cast<FollowerState>(200)), "unknown");
}

TEST(StatusTracker, ReportsOnlyChanges) {
  StatusTracker tracker;
  EXPECT_TRUE(tracker.update(FollowerState::kDisabled, "a"));
  EXPECT_FALSE(tracker.update(FollowerState::kDisabled, "a"));
  EXPECT_TRUE(tracker.update(FollowerState::kDisabled, "b"));
  EXPECT_TRUE(tracker.update(FollowerState::kFollowing, "b"));
}

TEST(AnnouncementQueue, OneAtATimeInOrder) {
  AnnouncementQueue queue(10.0, 8);
  EXPECT_TRUE(queue.push("one", 0.0));
  EXPECT_TRUE(queue.push("two", 0.0));
  EXPECT_EQ(queue.pop(0.0).value(), "one");
  EXPECT_EQ(queue.pop(0.0).value(), "two");
  EXPECT_FALSE(queue.pop(0.0));
}

TEST(AnnouncementQueue, IdenticalMessagesRateLimited) {
  AnnouncementQueue queue(10.0, 8);
  EXPECT_TRUE(queue.push("Too close, stopping.", 0.0));
  EXPECT_FALSE(queue.push("Too close, stopping.", 0.5));  // already queued
  queue.pop(1.0);
  EXPECT_FALSE(queue.push("Too close, stopping.", 5.0));  // spoken 4 s ago
  EXPECT_TRUE(queue.push("Too close, stopping.", 11.5));
}

TEST(AnnouncementQueue, BoundedLength) {
  AnnouncementQueue queue(0.0, 2);
  EXPECT_TRUE(queue.push("a", 0.0));
  EXPECT_TRUE(queue.push("b", 0.0));
  EXPECT_FALSE(queue.push("c", 0.0));
}

}  // namespace
}  // namespace control
}  // namespace radio_follow
