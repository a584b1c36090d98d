// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstddef>
#include <deque>
#include <map>
#include <optional>
#include <string>

namespace radio_follow {
namespace control {

/// What the announcer speaks next (thesis Section 4.8): one message at a time, in
/// arrival order, and an identical message at most once per `repeat_interval`.
class AnnouncementQueue {
 public:
  AnnouncementQueue(double repeat_interval, std::size_t max_queued);

  /// Queues `text` received at `now` (seconds). Returns false when it was dropped as a
  /// repeat, as already queued, or because the queue is full.
  bool push(const std::string& text, double now);

  /// The next message to speak at `now`, or nullopt; the caller calls this only while
  /// nothing is being spoken.
  std::optional<std::string> pop(double now);

  std::size_t size() const { return queue_.size(); }

 private:
  double repeat_interval_;
  std::size_t max_queued_;
  std::deque<std::string> queue_;
  std::map<std::string, double> last_spoken_;
};

}  // namespace control
}  // namespace radio_follow
