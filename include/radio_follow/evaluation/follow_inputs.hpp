// SPDX-License-Identifier: BSD-3-Clause
#pragma once

// What a follow law takes from the locator's estimate: the one translation between the
// estimator's output and the control laws' input, used by the controllers' ROS wrappers
// and by the lockstep closed loop. Header-only, so that a controller links neither.
#include <cmath>
#include <optional>

#include "radio_follow/control/safety_monitor.hpp"
#include "radio_follow/control/velocity_law.hpp"
#include "radio_follow/estimation/target_status.hpp"

namespace radio_follow {
namespace evaluation {

/// AMBIGUOUS is its own quality; a position or a direction with a finite range and
/// bearing is usable; anything else is lost.
inline control::EstimateQuality estimateQuality(estimation::TargetStatus status, double range,
                                                double bearing) {
  if (status == estimation::TargetStatus::kAmbiguous) {
    return control::EstimateQuality::kAmbiguous;
  }
  const bool known = hasPosition(status) || status == estimation::TargetStatus::kHeadingOnly;
  return known && std::isfinite(bearing) && std::isfinite(range) ? control::EstimateQuality::kUsable
                                                                 : control::EstimateQuality::kLost;
}

/// The velocity law's input: HEADING_ONLY has no range, DEGRADED is flagged, the
/// target's receding speed when known, the nearest module's gap to the stop.
inline control::TargetPolar targetPolar(estimation::TargetStatus status, double range,
                                        double bearing, std::optional<double> receding_speed,
                                        double module_gap) {
  control::TargetPolar t;
  t.receding_speed = receding_speed.value_or(0.0);
  t.module_gap = module_gap;
  t.range = range;
  t.bearing = bearing;
  t.range_valid = hasPosition(status);
  t.degraded = status == estimation::TargetStatus::kDegraded;
  return t;
}

}  // namespace evaluation
}  // namespace radio_follow
