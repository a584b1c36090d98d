// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/drivers/tdoa_grouper.hpp"

#include <algorithm>
#include <utility>

namespace radio_follow {
namespace drivers {

TdoaBlinkGrouper::TdoaBlinkGrouper(std::size_t anchor_count, double window,
                                   std::size_t max_open_groups)
    : anchor_count_(anchor_count), window_(window), max_open_groups_(max_open_groups) {
  open_.reserve(max_open_groups_ + 1);
}

TdoaBlinkGrouper::AddResult TdoaBlinkGrouper::add(std::uint16_t tag, std::uint8_t sequence,
                                                  const TdoaReception& reception, double now,
                                                  std::vector<TdoaBlinkGroup>* emitted) {
  expire(now, emitted);
  auto group = std::find_if(open_.begin(), open_.end(), [&](const TdoaBlinkGroup& g) {
    return g.tag == tag && g.sequence == sequence;
  });
  if (group == open_.end()) {
    if (open_.size() >= max_open_groups_) {
      ++overflows_;
      emitted->push_back(std::move(open_.front()));
      open_.erase(open_.begin());
    }
    TdoaBlinkGroup fresh;
    fresh.tag = tag;
    fresh.sequence = sequence;
    fresh.first_arrival = now;
    fresh.receptions.reserve(anchor_count_);
    open_.push_back(std::move(fresh));
    group = open_.end() - 1;
  } else {
    const bool seen =
        std::any_of(group->receptions.begin(), group->receptions.end(),
                    [&](const TdoaReception& r) { return r.anchor == reception.anchor; });
    if (seen) {
      return AddResult::kDuplicate;
    }
  }
  group->receptions.push_back(reception);
  if (group->receptions.size() >= anchor_count_) {
    group->complete = true;
    emitted->push_back(std::move(*group));
    open_.erase(group);
  }
  return AddResult::kFiled;
}

void TdoaBlinkGrouper::expire(double now, std::vector<TdoaBlinkGroup>* emitted) {
  // Groups are ordered by first arrival, so the expired ones form a prefix.
  auto first_alive = std::find_if(open_.begin(), open_.end(), [&](const TdoaBlinkGroup& g) {
    return now - g.first_arrival < window_;
  });
  for (auto it = open_.begin(); it != first_alive; ++it) {
    emitted->push_back(std::move(*it));
  }
  open_.erase(open_.begin(), first_alive);
}

}  // namespace drivers
}  // namespace radio_follow
