// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/drivers/backoff.hpp"

#include <algorithm>
#include <stdexcept>

namespace radio_follow::drivers {

Backoff::Backoff(Duration initial, Duration max)
    : first_(std::min(initial, max)), max_(max), current_(first_) {
  if (first_ <= Duration::zero()) {
    throw std::invalid_argument("Backoff: the initial and the longest wait must be positive");
  }
}

Backoff::Duration Backoff::next() {
  const Duration delay = current_;
  // Compared before doubling, so a max near Duration::max() cannot overflow.
  current_ = current_ > max_ / 2 ? max_ : current_ * 2;
  return delay;
}

}  // namespace radio_follow::drivers
