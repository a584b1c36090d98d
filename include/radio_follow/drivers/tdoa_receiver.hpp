// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "radio_follow/drivers/tdoa_differences.hpp"
#include "radio_follow/drivers/tdoa_grouper.hpp"
#include "radio_follow/drivers/tdoa_packet.hpp"

namespace radio_follow {
namespace drivers {

/// Counters of the TDoA pipeline, one per outcome; the node turns them into diagnostics.
struct TdoaStats {
  std::uint64_t packets = 0;  ///< Datagrams handed in.
  std::uint64_t reports = 0;  ///< Reports filed into a blink group.
  std::array<std::uint64_t, kTdoaDecodeErrorCount> decode_errors{};  ///< By TdoaDecodeError.
  std::uint64_t unknown_anchor = 0;     ///< Decoded, but from an address not configured.
  std::uint64_t missing_tlv = 0;        ///< No MAC (tag) or no timestamp TLV.
  std::uint64_t duplicate = 0;          ///< Same anchor reported the same blink twice.
  std::uint64_t blinks = 0;             ///< Blinks published.
  std::uint64_t blinks_incomplete = 0;  ///< Of those, published after a timeout.
  std::uint64_t blinks_dropped = 0;     ///< Too few anchors / no reference / none plausible.
  std::uint64_t implausible_differences = 0;

  /// Datagrams that did not become a filed report.
  std::uint64_t rejected() const;
};

/// All distance differences of one blink, ready to publish.
struct TdoaBlink {
  std::uint16_t tag = 0;
  double first_arrival = 0.0;  ///< Host seconds.
  std::vector<TdoaDistanceDifference> differences;
};

/// Datagram in, blinks out: decode -> look up the anchor -> group -> differences.
/// Time is host seconds passed in by the caller. Not thread-safe.
class TdoaReceiver {
 public:
  /// Throws ParamError for an invalid configuration or a non-positive window.
  TdoaReceiver(TdoaDifferenceConfig config, double group_window);

  /// Handles one datagram that arrived at `now`; finished blinks go to `out`. Returns the
  /// decode result (kOk also when the report was dropped for another counted reason).
  TdoaDecodeError onDatagram(const std::uint8_t* data, std::size_t size, double now,
                             std::vector<TdoaBlink>* out);

  /// Publishes groups whose window has passed at `now`; call periodically.
  void onTimer(double now, std::vector<TdoaBlink>* out);

  const TdoaStats& stats() const { return stats_; }
  const TdoaDifferenceConfig& config() const { return calculator_.config(); }

 private:
  void finish(std::vector<TdoaBlink>* out);

  TdoaDifferenceCalculator calculator_;
  TdoaBlinkGrouper grouper_;
  TdoaStats stats_;
  std::vector<TdoaBlinkGroup> emitted_;  // reused between calls
};

}  // namespace drivers
}  // namespace radio_follow
