// SPDX-License-Identifier: BSD-3-Clause
#pragma once

// What a follow law takes from the locator's estimate: the one translation between the
// estimator's output and the control laws' input, used by the controllers' ROS wrappers
// and by the lockstep closed loop. Header-only, so that a controller links neither.
#include <cmath>
#include <optional>

#include "radio_follow/common/geometry.hpp"
#include "radio_follow/common/plausibility.hpp"
#include "radio_follow/common/target_status.hpp"
#include "radio_follow/control/safety_monitor.hpp"
#include "radio_follow/control/velocity_law.hpp"

namespace radio_follow {
namespace control {

/// AMBIGUOUS is its own quality; a position or a direction with a range a module could
/// measure (plausibility.hpp) and a bearing within a half turn is usable; anything else
/// is lost.
inline EstimateQuality estimateQuality(TargetStatus status, double range, double bearing) {
  if (status == TargetStatus::kAmbiguous) {
    return EstimateQuality::kAmbiguous;
  }
  const bool known = hasPosition(status) || status == TargetStatus::kHeadingOnly;
  return known && plausibleAngleRad(bearing) && plausibleRange(range) ? EstimateQuality::kUsable
                                                                      : EstimateQuality::kLost;
}

/// The velocity law's input: HEADING_ONLY has no range, DEGRADED is flagged with the
/// way it is uncertain (`spread` of the position, a second hypothesis: `hypotheses` 2),
/// the target's receding speed when known, the nearest module's gap to the stop.
inline TargetPolar targetPolar(TargetStatus status, double range, double bearing,
                               const PolarSpread& spread, int hypotheses,
                               std::optional<double> receding_speed, double module_gap) {
  TargetPolar t;
  t.range_sigma = spread.range_sigma;
  t.bearing_sigma = spread.bearing_sigma;
  t.mirror = hypotheses >= 2;
  t.receding_speed = receding_speed.value_or(0.0);
  t.module_gap = module_gap;
  t.range = range;
  t.bearing = bearing;
  t.range_valid = hasPosition(status);
  t.degraded = status == TargetStatus::kDegraded;
  return t;
}

/// Which estimates become points of the target's track (the path follower's stored path,
/// the target's speed): OK ones, and DEGRADED ones of a track that has been OK since it
/// last had no position. A DEGRADED estimate before that is a young track's wide cloud:
/// a cold start's first epochs, once 3.8 m off and behind the robot in a closed-loop run,
/// where a path point turned the robot away from the person for the rest of the walk. A
/// DEGRADED estimate of a confirmed track is that track gone wide for a while (far away,
/// a sensor silent): still the best place known, and a path that ended before it would
/// stall the robot.
class TrackGate {
 public:
  /// Whether this estimate, the newest, is a track point.
  bool accept(TargetStatus status) {
    confirmed_ = status == TargetStatus::kOk || (confirmed_ && status == TargetStatus::kDegraded);
    return confirmed_;
  }

 private:
  bool confirmed_ = false;
};

}  // namespace control
}  // namespace radio_follow
