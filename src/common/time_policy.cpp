// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/common/time_policy.hpp"

#include <cmath>

namespace radio_follow {

TimePolicy::Verdict TimePolicy::check(double stamp, double now) {
  // A NaN stamp cannot be placed in time: as untrustworthy as one from the future.
  if (!(stamp <= now + future_tolerance_)) {
    ++future_refused_;
    return Verdict::kFuture;
  }
  return Verdict::kFresh;
}

bool TimePolicy::jumpedBack(double now) {
  if (!has_now_ || now > latest_now_) {
    has_now_ = true;
    latest_now_ = now;
    return false;
  }
  if (latest_now_ - now > kClockJumpTolerance) {
    latest_now_ = now;
    ++clock_jumps_;
    return true;
  }
  return false;
}

}  // namespace radio_follow
