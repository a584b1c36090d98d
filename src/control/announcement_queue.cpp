// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/control/announcement_queue.hpp"

#include <algorithm>

namespace radio_follow {
namespace control {

AnnouncementQueue::AnnouncementQueue(double repeat_interval, std::size_t max_queued)
    : repeat_interval_(repeat_interval), max_queued_(max_queued) {}

bool AnnouncementQueue::push(const std::string& text, double now) {
  if (text.empty() || queue_.size() >= max_queued_) {
    return false;
  }
  if (std::find(queue_.begin(), queue_.end(), text) != queue_.end()) {
    return false;
  }
  const auto it = last_spoken_.find(text);
  if (it != last_spoken_.end() && now - it->second < repeat_interval_) {
    return false;
  }
  queue_.push_back(text);
  return true;
}

std::optional<std::string> AnnouncementQueue::pop(double now) {
  if (queue_.empty()) {
    return std::nullopt;
  }
  std::string text = queue_.front();
  queue_.pop_front();
  last_spoken_[text] = now;
  return text;
}

}  // namespace control
}  // namespace radio_follow
