// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/control/safety_monitor.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "radio_follow/common/param_error.hpp"
#include "radio_follow/control/rate_limiter.hpp"

namespace radio_follow {
namespace control {

void SafetyParams::validate() const {
  require(std::isfinite(safe_distance) && safe_distance >= 0.0, "~safe_distance", safe_distance,
          "a distance >= 0 in metres");
  require(std::isfinite(estimate_timeout) && estimate_timeout > 0.0, "~estimate_timeout",
          estimate_timeout, "a timeout > 0 in seconds");
  require(std::isfinite(range_timeout) && range_timeout > 0.0, "~range_timeout", range_timeout,
          "a timeout > 0 in seconds");
  require(std::isfinite(hold_time) && hold_time >= 0.0, "~hold_time", hold_time,
          "a time >= 0 in seconds");
}

SafetyMonitor::SafetyMonitor(const SafetyParams& params) : params_(params) {}

void SafetyMonitor::setParams(const SafetyParams& params) {
  params.validate();
  params_ = params;
}

bool SafetyMonitor::onRange(double time, const std::string& source, double range) {
  // A NaN range cannot prove the target is far away: it counts as a violation.
  const bool violation = !(range >= params_.safe_distance);
  ranges_[source] = {time, range};
  if (violation) {
    blocked_once_ = true;
    last_block_time_ = std::max(last_block_time_, time);
    last_block_reason_ = StopReason::kTooClose;
  }
  return violation;
}

void SafetyMonitor::onEstimate(double stamp, bool usable) {
  if (!has_estimate_ || stamp >= estimate_stamp_) {
    has_estimate_ = true;
    estimate_stamp_ = stamp;
    estimate_usable_ = usable;
  }
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
      return StopReason::kRangesSilent;
    }
  }
  if (!has_estimate_) {
    return StopReason::kNoEstimateYet;
  }
  if (!(now - estimate_stamp_ <= params_.estimate_timeout)) {
    return StopReason::kEstimateStale;
  }
  if (!estimate_usable_) {
    return StopReason::kTargetLost;
  }
  return StopReason::kNone;
}

SafetyDecision SafetyMonitor::evaluate(double now) {
  if (!enabled_) {
    return {false, StopReason::kDisabled};
  }
  const StopReason reason = rawReason(now);
  if (reason != StopReason::kNone) {
    // Waiting for a first estimate is not a hazard that needs a hold afterwards.
    if (reason != StopReason::kNoEstimateYet) {
      blocked_once_ = true;
      last_block_time_ = std::max(last_block_time_, now);
      last_block_reason_ = reason;
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
