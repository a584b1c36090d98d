// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/drivers/backoff.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <stdexcept>

namespace radio_follow::drivers {
namespace {

using namespace std::chrono_literals;

TEST(Backoff, DoublesFromInitialUpToMax) {
  Backoff backoff(100ms, 1s);
  EXPECT_EQ(backoff.next(), 100ms);
  EXPECT_EQ(backoff.next(), 200ms);
  EXPECT_EQ(backoff.next(), 400ms);
  EXPECT_EQ(backoff.next(), 800ms);
  EXPECT_EQ(backoff.next(), 1s);
  EXPECT_EQ(backoff.next(), 1s);
  EXPECT_EQ(backoff.peek(), 1s);
}

TEST(Backoff, ResetStartsAgainFromInitial) {
  Backoff backoff(500ms, 10s);
  backoff.next();
  backoff.next();
  EXPECT_EQ(backoff.peek(), 2s);
  backoff.reset();
  EXPECT_EQ(backoff.next(), 500ms);
  EXPECT_EQ(backoff.next(), 1s);
}

TEST(Backoff, MaxCapsTheFirstWaitToo) {
  Backoff backoff(100ms, 50ms);
  EXPECT_EQ(backoff.next(), 50ms);
  EXPECT_EQ(backoff.next(), 50ms);
  backoff.reset();
  EXPECT_EQ(backoff.next(), 50ms);
}

TEST(Backoff, NoOverflowNearTheLargestDuration) {
  const Backoff::Duration huge = Backoff::Duration::max();
  Backoff backoff(huge / 2 + 1ns, huge);
  backoff.next();
  EXPECT_EQ(backoff.next(), huge);
  EXPECT_EQ(backoff.next(), huge);
}

TEST(Backoff, RefusesWaitsThatWouldSpin) {
  EXPECT_THROW(Backoff(0ms, 1s), std::invalid_argument);
  EXPECT_THROW(Backoff(-1ms, 1s), std::invalid_argument);
  EXPECT_THROW(Backoff(100ms, 0ms), std::invalid_argument);
}

}  // namespace
}  // namespace radio_follow::drivers
