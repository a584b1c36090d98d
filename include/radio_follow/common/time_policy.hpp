// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstdint>

namespace radio_follow {

/// How far ahead of the receiver's clock a stamp may be before it counts as "from the
/// future", seconds. Drivers stamp with the host's receive time, so on one machine a
/// stamp is never ahead; between machines NTP keeps clocks within a few milliseconds.
/// 50 ms admits that and one roscpp delivery, and is an order of magnitude below every
/// freshness timeout (estimate_timeout 0.5 s, range_timeout 1 s) it could extend.
constexpr double kFutureStampTolerance = 0.05;

/// A clock that steps back by more than this has jumped (a bag played with --loop, a
/// simulator restarted under /use_sim_time, a wall clock set back), seconds. Smaller
/// steps are jitter between callbacks reading the clock.
constexpr double kClockJumpTolerance = 0.1;

/// The project's one time rule for received stamps (doc/time.md): every freshness
/// decision is `now - stamp` on the receiver's clock, and
/// - a stamp more than kFutureStampTolerance ahead of `now` is refused and counted: it
///   would otherwise look fresh for as long as it stays ahead;
/// - a stamp that is old is stale by age, the consumer decides what that means (a short
///   range still stops the robot; it just does not count as fresh);
/// - the receiver's own clock running backwards beyond kClockJumpTolerance is reported
///   once by jumpedBack(), and the consumer resets its time-dependent state.
/// Clock-free: every call carries the times, in seconds on one clock.
class TimePolicy {
 public:
  enum class Verdict { kFresh, kFuture };

  /// Classifies `stamp` received at `now`; counts refusals.
  Verdict check(double stamp, double now);

  /// True once each time `now` is more than kClockJumpTolerance before the latest `now`
  /// seen; the latest time then restarts from `now`. Counts jumps.
  bool jumpedBack(double now);

  std::uint64_t futureRefused() const { return future_refused_; }
  std::uint64_t clockJumps() const { return clock_jumps_; }

 private:
  bool has_now_ = false;
  double latest_now_ = 0.0;
  std::uint64_t future_refused_ = 0;
  std::uint64_t clock_jumps_ = 0;
};

}  // namespace radio_follow
