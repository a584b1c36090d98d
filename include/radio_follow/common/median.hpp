// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace radio_follow {

/// The median of `values` (the mean of the two middle ones for an even count); NaN for
/// none. Linear time (std::nth_element on the copy it takes).
inline double median(std::vector<double> values) {
  if (values.empty()) {
    return std::nan("");
  }
  const auto mid = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
  std::nth_element(values.begin(), mid, values.end());
  if (values.size() % 2 == 1) {
    return *mid;
  }
  return 0.5 * (*mid + *std::max_element(values.begin(), mid));
}

}  // namespace radio_follow
