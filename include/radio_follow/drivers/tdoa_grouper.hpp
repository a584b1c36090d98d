// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace radio_follow {
namespace drivers {

/// One anchor's receive time of a blink.
struct TdoaReception {
  std::size_t anchor = 0;      ///< Index into the configured anchor list.
  std::uint64_t rx_ticks = 0;  ///< Receive time, ticks.
};

/// The receptions of one blink of one tag, collected across anchors.
struct TdoaBlinkGroup {
  std::uint16_t tag = 0;
  std::uint8_t sequence = 0;
  double first_arrival = 0.0;  ///< Host time the first report arrived, seconds.
  bool complete = false;       ///< Every anchor reported (otherwise: timed out).
  std::vector<TdoaReception> receptions;
};

/// Collects anchor reports of one blink, keyed by (tag, sequence number). A group is
/// emitted when every anchor has reported or when `window` seconds have passed since its
/// first report. The 8-bit sequence number wraps every 256 blinks; a key seen again
/// after its group's window is a new blink, because expired groups are emitted before a
/// report is filed. Not thread-safe.
class TdoaBlinkGrouper {
 public:
  /// `anchor_count` reports complete a group; at most `max_open_groups` are kept (the
  /// oldest is emitted early when a new one would exceed it).
  TdoaBlinkGrouper(std::size_t anchor_count, double window, std::size_t max_open_groups = 64);

  enum class AddResult {
    kFiled,      ///< Added to a (possibly new) open group.
    kDuplicate,  ///< This anchor already reported this blink: dropped.
  };

  /// Files a report received at host time `now` (seconds, non-decreasing). Groups that
  /// complete or expire are appended to `emitted`.
  AddResult add(std::uint16_t tag, std::uint8_t sequence, const TdoaReception& reception,
                double now, std::vector<TdoaBlinkGroup>* emitted);

  /// Emits every group whose window has passed at `now`.
  void expire(double now, std::vector<TdoaBlinkGroup>* emitted);

  /// Groups emitted early because more than max_open_groups were open.
  std::uint64_t overflows() const { return overflows_; }
  std::size_t openGroups() const { return open_.size(); }

 private:
  std::size_t anchor_count_;
  double window_;
  std::size_t max_open_groups_;
  std::uint64_t overflows_ = 0;
  std::vector<TdoaBlinkGroup> open_;  // in order of first arrival
};

}  // namespace drivers
}  // namespace radio_follow
