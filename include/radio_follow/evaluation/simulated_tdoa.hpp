// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "radio_follow/common/pose2.hpp"
#include "radio_follow/config/layout.hpp"
#include "radio_follow/estimation/locator.hpp"

namespace radio_follow {
namespace evaluation {

/// Hands one simulated TDoA blink to a locator as LocatorInputs hands the driver's
/// messages: `differences` are against anchor `reference`, in anchor order (what
/// sim::simulateTdoa returns); a blink of one of the robot's own modules (`module`, an index
/// into the layout's twr_modules) calibrates the anchors, the target's (no module) is
/// fused with `variance` and `pose`.
void feedTdoaBlink(estimation::Locator& locator, const Layout& layout, std::size_t reference,
                   const std::vector<double>& differences, std::optional<std::size_t> module,
                   double variance, double t, const std::optional<Pose2>& pose = std::nullopt);

}  // namespace evaluation
}  // namespace radio_follow
