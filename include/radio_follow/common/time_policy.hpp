// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstdint>

namespace radio_follow {

/// How far ahead of the receiver's clock a stamp may be before it counts as "from the
/// future", seconds. Drivers stamp with the host's receive time, so on one machine a
/// stamp is never ahead; between machines NTP keeps clocks within a few milliseconds.
/// 50 ms admits that and one roscpp delivery, and is an order of magnitude below the
/// shipped freshness timeouts (estimate_timeout, range_timeout) it could extend.
constexpr double kFutureStampTolerance = 0.05;

/// The same under simulated time (/use_sim_time: the simulator, a replayed bag), seconds
/// of that clock. There each node's clock is the last /clock message its roscpp thread
/// handled, so on a busy machine a receiver's clock trails its sender's by a scheduling
/// delay: tens of milliseconds of wall time, times the time factor (the demo runs at 4x).
/// 0.5 s admits 0.125 s of wall delay at 4x. A stamp within the tolerance is taken as
/// received now (never as fresher), so a wider tolerance keeps nothing fresh for longer;
/// a stamp beyond it still stops the robot.
constexpr double kSimFutureStampTolerance = 0.5;

/// The tolerance for a receiver on the wall clock (false) or on simulated time (true).
constexpr double futureStampTolerance(bool simulated_time) {
  return simulated_time ? kSimFutureStampTolerance : kFutureStampTolerance;
}

/// A clock that steps back by more than this has jumped (a bag played with --loop, a
/// simulator restarted under /use_sim_time, a wall clock set back), seconds. Smaller
/// steps are jitter between callbacks reading the clock.
constexpr double kClockJumpTolerance = 0.1;

/// The project's one time rule for received stamps (doc/time.md): every freshness
/// decision is `now - stamp` on the receiver's clock, and
/// - a stamp more than the future tolerance (kFutureStampTolerance on the wall clock,
///   futureStampTolerance()) ahead of `now` is refused and counted: it would otherwise
///   look fresh for as long as it stays ahead; the consumer takes one within the
///   tolerance as received at `now` (received());
/// - a stamp that is old is stale by age, the consumer decides what that means (a short
///   range still stops the robot; it just does not count as fresh);
/// - the receiver's own clock running backwards beyond kClockJumpTolerance is reported
///   once by jumpedBack(), and the consumer resets its time-dependent state.
/// Clock-free: every call carries the times, in seconds on one clock.
class TimePolicy {
 public:
  enum class Verdict { kFresh, kFuture };

  explicit TimePolicy(double future_tolerance = kFutureStampTolerance)
      : future_tolerance_(future_tolerance) {}

  /// Classifies `stamp` received at `now`; counts refusals.
  Verdict check(double stamp, double now);
  /// The time a stamp that check() accepted counts as: never later than `now`, so a
  /// tolerated lead cannot keep it fresh for longer.
  static double received(double stamp, double now) { return stamp < now ? stamp : now; }

  double futureTolerance() const { return future_tolerance_; }
  void setFutureTolerance(double seconds) { future_tolerance_ = seconds; }

  /// True once each time `now` is more than kClockJumpTolerance before the latest `now`
  /// seen; the latest time then restarts from `now`. Counts jumps.
  bool jumpedBack(double now);

  std::uint64_t futureRefused() const { return future_refused_; }
  std::uint64_t clockJumps() const { return clock_jumps_; }

 private:
  double future_tolerance_;
  bool has_now_ = false;
  double latest_now_ = 0.0;
  std::uint64_t future_refused_ = 0;
  std::uint64_t clock_jumps_ = 0;
};

}  // namespace radio_follow
