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

TEST(StatusTracker, AnnouncesTheFirstAndDisabledAtOnceOthersOnceSettled) {
  StatusTracker tracker;
  EXPECT_TRUE(tracker.update(FollowerState::kDisabled, "a", 0.0));
  EXPECT_FALSE(tracker.update(FollowerState::kDisabled, "a", 0.1));
  EXPECT_TRUE(tracker.update(FollowerState::kDisabled, "b", 0.2));  // an operator's command
  EXPECT_FALSE(tracker.update(FollowerState::kFollowing, "f", 1.0));
  EXPECT_FALSE(tracker.update(FollowerState::kFollowing, "f", 1.0 + kStatusSettleTime / 2));
  EXPECT_TRUE(tracker.update(FollowerState::kFollowing, "f", 1.0 + kStatusSettleTime));
  EXPECT_FALSE(tracker.update(FollowerState::kFollowing, "f", 3.0));
}

// A state held for less than kStatusSettleTime is never announced.
TEST(StatusTracker, ShortStatesAreNotAnnounced) {
  StatusTracker tracker;
  EXPECT_TRUE(tracker.update(FollowerState::kFollowing, "f", 0.0));
  EXPECT_FALSE(tracker.update(FollowerState::kTooClose, "close", 1.0));
  EXPECT_FALSE(tracker.update(FollowerState::kFollowing, "f", 1.0 + kStatusSettleTime / 2));
  EXPECT_FALSE(tracker.update(FollowerState::kFollowing, "f", 5.0));
}

// Issue 34: steady future-stamped ranges flipped the text between two stop reasons of one
// state at 20 Hz and the announcer spoke both in turn. Now: the state once, when it has
// held, and no text that never holds.
TEST(StatusTracker, FlappingTextsOfOneStateAreAnnouncedOnce) {
  StatusTracker tracker;
  EXPECT_TRUE(tracker.update(FollowerState::kFollowing, "Following.", 0.0));
  int announced = 0;
  for (int tick = 0; tick < 40; ++tick) {  // 2 s at 20 Hz
    const bool clock = tick % 2 == 0;
    announced += tracker.update(FollowerState::kTargetLost, clock ? "Clock mismatch" : "No range",
                                1.0 + 0.05 * tick);
  }
  EXPECT_EQ(announced, 1);
}

// States that flap faster than the settle time are still told: the one current when the
// announced state has not been current for kStatusSettleTime, and then it stays.
TEST(StatusTracker, FlappingStatesAreToldNotHidden) {
  StatusTracker tracker;
  EXPECT_TRUE(tracker.update(FollowerState::kFollowing, "Following.", 0.0));
  int announced = 0;
  for (int tick = 0; tick < 40; ++tick) {
    const bool close = tick % 2 == 0;
    announced += tracker.update(close ? FollowerState::kTooClose : FollowerState::kTargetLost,
                                close ? "Too close" : "Lost", 1.0 + 0.05 * tick);
  }
  EXPECT_EQ(announced, 1);
}

TEST(StatusTracker, ClockJumpBackRestartsTheSpans) {
  StatusTracker tracker;
  EXPECT_TRUE(tracker.update(FollowerState::kFollowing, "f", 100.0));
  EXPECT_FALSE(tracker.update(FollowerState::kTargetLost, "lost", 101.0));
  EXPECT_FALSE(tracker.update(FollowerState::kTargetLost, "lost", 1.0));  // jumped back
  EXPECT_TRUE(tracker.update(FollowerState::kTargetLost, "lost", 1.0 + kStatusSettleTime));
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
