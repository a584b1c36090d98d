// SPDX-License-Identifier: BSD-3-Clause
#pragma once

// The shipped configuration of a closed-loop run, for the lab's unit tests.

#include <optional>
#include <string>

#include "radio_follow/evaluation/closed_loop.hpp"

namespace radio_follow::test {

/// What follower.launch and simulator.launch run for `layout` on the outdoor loop with the
/// velocity controller and seed 1; `profile` replaces simulator.yaml's sensor profile.
inline evaluation::ClosedLoopConfig shippedLoop(
    const std::string& layout, std::optional<sim::SensorProfile> profile = std::nullopt) {
  return evaluation::loadClosedLoopConfig(RF_CONFIG_DIR, layout, "outdoor_loop",
                                          evaluation::FollowController::kVelocity, 1, "", "",
                                          profile);
}

}  // namespace radio_follow::test
