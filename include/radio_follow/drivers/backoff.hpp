// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <chrono>

namespace radio_follow::drivers {

/// The wait before the next reconnect attempt of a transport: `initial` after the first
/// failure, twice as long after each further one, never more than `max` (the first wait
/// included), and `initial` again once an attempt succeeds. It keeps no clock: the owner
/// asks for the delay and waits on its own timer.
class Backoff {
 public:
  using Duration = std::chrono::nanoseconds;

  /// Throws std::invalid_argument unless both are positive: a zero wait would retry in a
  /// busy loop.
  Backoff(Duration initial, Duration max);

  /// The wait before the next attempt; the one after it will be twice as long (capped).
  Duration next();
  /// An attempt succeeded: the next failure waits `initial` again.
  void reset() { current_ = first_; }
  /// What next() would return, without advancing.
  Duration peek() const { return current_; }

 private:
  Duration first_;
  Duration max_;
  Duration current_;
};

}  // namespace radio_follow::drivers
