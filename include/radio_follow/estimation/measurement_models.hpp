// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <vector>

#include "radio_follow/estimation/bearing_measurement.hpp"
#include "radio_follow/estimation/range_measurement.hpp"
#include "radio_follow/estimation/tdoa_measurement.hpp"

namespace radio_follow {
namespace estimation {

// The measurement kinds the locator fuses, each in its own file with its observation,
// model, Ceres cost and particle likelihood: range_measurement.hpp,
// tdoa_measurement.hpp, bearing_measurement.hpp (and rss_direction.hpp, which only
// weighs the particle estimator's hypotheses).

/// Distance assumed along a bearing when no range exists, m: the one default of the
/// locator's `default_range` (initializer, particle tracker).
constexpr double kDefaultRange = 3.0;

/// Everything one solve uses.
struct ObservationSet {
  std::vector<RangeObservation> ranges;
  std::vector<TdoaObservation> tdoas;
  std::vector<BearingObservation> bearings;

  bool empty() const { return ranges.empty() && tdoas.empty() && bearings.empty(); }
  void clear() {
    ranges.clear();
    tdoas.clear();
    bearings.clear();
  }
};

}  // namespace estimation
}  // namespace radio_follow
