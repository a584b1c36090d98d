// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstddef>

#include "radio_follow/AoaBearing.h"
#include "radio_follow/TdoaMeasurements.h"
#include "radio_follow/UwbRanges.h"
#include "radio_follow/estimation/locator.hpp"

namespace radio_follow {

/// Hands driver messages to a Locator the one way both the locator node and the offline
/// evaluator do: only ranges to the target's anchor, only bearings of the target's tag
/// (when the layout names one), a module named by its ID or else its frame, every value
/// stamped with its message's header.
class LocatorInputs {
 public:
  explicit LocatorInputs(Locator& locator) : locator_(locator) {}

  /// Each returns how many entries the locator refused (unknown sensor, invalid value).
  std::size_t add(const UwbRanges& msg);
  std::size_t add(const AoaBearing& msg);
  std::size_t add(const TdoaMeasurements& msg);

 private:
  Locator& locator_;
};

}  // namespace radio_follow
