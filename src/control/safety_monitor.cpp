// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/control/safety_monitor.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "radio_follow/common/param_error.hpp"
#include "radio_follow/control/rate_limiter.hpp"

namespace radio_follow {
namespace control {

const ParamTable<SafetyParams>& SafetyParams::table() {
  // Physical bounds, not just signs: a stop distance below a UWB module's own error (a
  // few cm, Table 3.1) is no stop at all, and a freshness timeout of minutes means a
  // dead sensor keeps the robot driving on its last word.
  static const ParamTable<SafetyParams> t =
      ParamTable<SafetyParams>()
          .add("safe_distance", &SafetyParams::safe_distance, "m",
               "Stop below this range (calibrated per calibrate_ranges).",
               Range::closed(kMinSafeDistance, kMaxSafeDistance))
          .add("estimate_timeout", &SafetyParams::estimate_timeout, "s",
               "Stop when the estimate is older.", Range::aboveUpTo(0.0, kMaxFreshnessTimeout))
          .add("range_timeout", &SafetyParams::range_timeout, "s",
               "Forget a silent range source; all silent = stop.",
               Range::aboveUpTo(0.0, kMaxFreshnessTimeout))
          .add("hold_time", &SafetyParams::hold_time, "s",
               "A stop condition must be clear this long to resume.",
               Range::closed(0.0, kMaxHoldTime));
  return t;
}

void SafetyParams::validate() const {
  table().check(*this);
}

SafetyMonitor::SafetyMonitor(const SafetyParams& params) : params_(params) {}

void SafetyMonitor::setParams(const SafetyParams& params) {
  params.validate();
  params_ = params;
}

void SafetyMonitor::block(double now, StopReason reason) {
  blocked_once_ = true;
  last_block_time_ = std::max(last_block_time_, now);
  last_block_reason_ = reason;
}

void SafetyMonitor::observe(double now) {
  if (!time_.jumpedBack(now)) {
    return;
  }
  // Every stored stamp is now "in the future" of the new clock: keeping them would freeze
  // the monitor (nothing newer ever arrives) or trust them for as long as they lead.
  ranges_.clear();
  has_estimate_ = false;
  estimate_quality_ = EstimateQuality::kLost;
  last_implausible_ = -std::numeric_limits<double>::infinity();
  last_block_time_ = now;
  blocked_once_ = true;
  last_block_reason_ = StopReason::kClockJumped;
}

bool SafetyMonitor::onRange(double stamp, double now, const std::string& source, double range) {
  observe(now);
  if (time_.check(stamp, now) == TimePolicy::Verdict::kFuture) {
    block(now, StopReason::kFutureStamp);
    return true;
  }
  stamp = TimePolicy::received(stamp, now);
  // A NaN range cannot prove the target is far away: it counts as a violation. A stale
  // one too: it says the person was close, and the hold runs from when we heard it.
  const bool violation = !(range >= params_.safe_distance);
  if (violation) {
    block(now, StopReason::kTooClose);
  }
  const auto it = ranges_.find(source);
  if (it == ranges_.end() || stamp >= it->second.first) {
    ranges_[source] = {stamp, range};
  }
  return violation;
}

void SafetyMonitor::onImplausibleRange(double now) {
  observe(now);
  block(now, StopReason::kImplausibleRange);
  ++implausible_ranges_;
  last_implausible_ = now;
}

void SafetyMonitor::onFault(double now) {
  observe(now);
  block(now, StopReason::kInternalFault);
}

bool SafetyMonitor::onEstimate(double stamp, double now, EstimateQuality quality) {
  observe(now);
  if (time_.check(stamp, now) == TimePolicy::Verdict::kFuture) {
    block(now, StopReason::kFutureStamp);
    return false;
  }
  stamp = TimePolicy::received(stamp, now);
  if (!has_estimate_ || stamp >= estimate_stamp_) {
    has_estimate_ = true;
    estimate_stamp_ = stamp;
    estimate_quality_ = quality;
  }
  return true;
}

double SafetyMonitor::nearestRange(double now) const {
  double nearest = std::numeric_limits<double>::infinity();
  for (const auto& [source, sample] : ranges_) {
    if (now - sample.first <= params_.range_timeout) {
      nearest = std::min(nearest, sample.second);
    }
  }
  return nearest;
}

StopReason SafetyMonitor::rawReason(double now) {
  if (params_.watch_ranges) {
    bool any_fresh = false;
    for (auto it = ranges_.begin(); it != ranges_.end();) {
      const auto [time, range] = it->second;
      if (now - time > params_.range_timeout) {
        it = ranges_.erase(it);
        continue;
      }
      any_fresh = true;
      if (!(range >= params_.safe_distance)) {
        return StopReason::kTooClose;
      }
      ++it;
    }
    if (!any_fresh) {
      // Ranges that arrive but are implausible are named as such, not as silence.
      const bool implausible = now - last_implausible_ <= params_.range_timeout;
      return implausible ? StopReason::kImplausibleRange : StopReason::kRangesSilent;
    }
  }
  if (!has_estimate_) {
    return StopReason::kNoEstimateYet;
  }
  if (!(now - estimate_stamp_ <= params_.estimate_timeout)) {
    return StopReason::kEstimateStale;
  }
  switch (estimate_quality_) {
    case EstimateQuality::kUsable:
      break;
    case EstimateQuality::kAmbiguous:
      return StopReason::kTargetAmbiguous;
    case EstimateQuality::kLost:
      return StopReason::kTargetLost;
  }
  return StopReason::kNone;
}

SafetyDecision SafetyMonitor::evaluate(double now) {
  observe(now);
  if (!enabled_) {
    return {false, StopReason::kDisabled};
  }
  const StopReason reason = rawReason(now);
  if (reason != StopReason::kNone) {
    // Waiting for a first estimate is not a hazard that needs a hold afterwards.
    if (reason != StopReason::kNoEstimateYet) {
      block(now, reason);
    }
    return {false, reason};
  }
  if (blocked_once_ && now - last_block_time_ < params_.hold_time) {
    return {false, last_block_reason_};
  }
  return {true, StopReason::kNone};
}

VelocityCommand gateCommand(const SafetyDecision& decision, const VelocityCommand& command) {
  if (!decision.may_move || !std::isfinite(command.linear) || !std::isfinite(command.angular)) {
    return VelocityCommand{};
  }
  return command;
}

}  // namespace control
}  // namespace radio_follow
