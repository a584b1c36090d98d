// SPDX-License-Identifier: BSD-3-Clause
#pragma once

namespace radio_follow {

/// At most one event per `period` seconds, per object: ROS_*_THROTTLE throttles per call
/// site, so one process with several devices (layout_drivers) would let one device's
/// warnings hide another's. Not thread-safe: one per thread that asks.
class Throttle {
 public:
  explicit Throttle(double period) : period_(period) {}

  /// True (and the period restarts) when `now` is at least a period after the last true.
  bool ready(double now) {
    if (last_ > 0.0 && now - last_ < period_ && now >= last_) {
      return false;
    }
    last_ = now;
    return true;
  }

 private:
  double period_;
  double last_ = 0.0;
};

}  // namespace radio_follow
