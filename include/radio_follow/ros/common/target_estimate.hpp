// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "radio_follow/TargetEstimate.h"
#include "radio_follow/control/follower_state.hpp"

namespace radio_follow {

/// OK or DEGRADED: `position` may be driven towards (HEADING_ONLY: only the direction;
/// every other status, the unset zero included: nothing).
bool hasPosition(const TargetEstimate& estimate);

/// What the safety layer makes of an estimate: usable (OK, DEGRADED, HEADING_ONLY, with a
/// finite range and bearing), ambiguous (AMBIGUOUS), else lost (LOST, UNSET, any unknown
/// status, a non-finite range or bearing, an implausible position, or with `odom_frame`
/// set an implausible `odom_position`, `odom_robot` or `odom_velocity`; NaN velocity is
/// the documented "not tracked").
control::EstimateQuality estimateQuality(const TargetEstimate& estimate);

}  // namespace radio_follow
