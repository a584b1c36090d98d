// SPDX-License-Identifier: BSD-3-Clause
// Which estimates the followers' track takes (TrackGate).
#include "radio_follow/evaluation/follow_inputs.hpp"

#include <gtest/gtest.h>

namespace radio_follow {
namespace evaluation {
namespace {

using estimation::TargetStatus;

TEST(TrackGate, ADegradedEstimateCountsOnlyInATrackThatWasOk) {
  TrackGate gate;
  EXPECT_FALSE(gate.accept(TargetStatus::kDegraded)) << "a young track's wide cloud";
  EXPECT_FALSE(gate.accept(TargetStatus::kDegraded));
  EXPECT_TRUE(gate.accept(TargetStatus::kOk));
  EXPECT_TRUE(gate.accept(TargetStatus::kDegraded)) << "the confirmed track gone wide";
  EXPECT_TRUE(gate.accept(TargetStatus::kDegraded));
  EXPECT_TRUE(gate.accept(TargetStatus::kOk));
}

TEST(TrackGate, AnEstimateWithoutAPositionEndsTheTrack) {
  for (const TargetStatus gap : {TargetStatus::kLost, TargetStatus::kAmbiguous,
                                 TargetStatus::kHeadingOnly, TargetStatus::kUnset}) {
    TrackGate gate;
    ASSERT_TRUE(gate.accept(TargetStatus::kOk));
    EXPECT_FALSE(gate.accept(gap)) << toString(gap);
    EXPECT_FALSE(gate.accept(TargetStatus::kDegraded))
        << "after " << toString(gap) << " the track is young again";
    EXPECT_TRUE(gate.accept(TargetStatus::kOk));
  }
}

}  // namespace
}  // namespace evaluation
}  // namespace radio_follow
