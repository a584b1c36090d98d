// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/common/time_policy.hpp"

#include <gtest/gtest.h>

#include <limits>

namespace radio_follow {
namespace {

TEST(TimePolicy, FutureBeyondToleranceIsRefusedAndCounted) {
  TimePolicy policy;
  EXPECT_EQ(policy.check(10.0, 10.0), TimePolicy::Verdict::kFresh);
  EXPECT_EQ(policy.check(9.0, 10.0), TimePolicy::Verdict::kFresh);  // old: the consumer's call
  EXPECT_EQ(policy.check(10.0 + kFutureStampTolerance * 0.5, 10.0), TimePolicy::Verdict::kFresh);
  EXPECT_EQ(policy.check(10.0 + kFutureStampTolerance * 2.0, 10.0), TimePolicy::Verdict::kFuture);
  EXPECT_EQ(policy.check(std::numeric_limits<double>::quiet_NaN(), 10.0),
            TimePolicy::Verdict::kFuture);
  EXPECT_EQ(policy.futureRefused(), 2u);
}

// Issue 33: on simulated time a busy receiver's clock trails its sender's; the tolerance
// comes from the clock, and a tolerated stamp never counts as newer than its receipt.
TEST(TimePolicy, TheToleranceIsTheClocksAndALeadNeverExtendsFreshness) {
  EXPECT_EQ(futureStampTolerance(false), kFutureStampTolerance);
  EXPECT_EQ(futureStampTolerance(true), kSimFutureStampTolerance);
  TimePolicy simulated(futureStampTolerance(true));
  EXPECT_EQ(simulated.check(10.3, 10.0), TimePolicy::Verdict::kFresh);   // 0.3 s behind
  EXPECT_EQ(simulated.check(10.6, 10.0), TimePolicy::Verdict::kFuture);  // truly ahead
  EXPECT_EQ(simulated.check(40.0, 10.0), TimePolicy::Verdict::kFuture);
  EXPECT_EQ(TimePolicy::received(10.3, 10.0), 10.0);
  EXPECT_EQ(TimePolicy::received(9.7, 10.0), 9.7);
  TimePolicy wall;
  EXPECT_EQ(wall.check(10.3, 10.0), TimePolicy::Verdict::kFuture);
}

TEST(TimePolicy, ClockJumpBackIsReportedOnce) {
  TimePolicy policy;
  EXPECT_FALSE(policy.jumpedBack(100.0));
  EXPECT_FALSE(policy.jumpedBack(100.5));
  EXPECT_FALSE(policy.jumpedBack(100.45));  // jitter between callbacks
  EXPECT_TRUE(policy.jumpedBack(3.0));      // bag loop
  EXPECT_FALSE(policy.jumpedBack(3.1));     // the new clock runs on
  EXPECT_EQ(policy.clockJumps(), 1u);
}

}  // namespace
}  // namespace radio_follow
