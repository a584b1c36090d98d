// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>

namespace radio_follow::drivers {

/// A plain copy of DriverStats at one instant.
struct DriverStatsSnapshot {
  std::uint64_t bytes = 0;        ///< bytes received
  std::uint64_t messages = 0;     ///< measurements decoded and published
  std::uint64_t dropped = 0;      ///< measurements decoded but not published: queue full
  std::size_t queue_peak = 0;     ///< most measurements ever waiting to be published
  std::uint64_t ignored = 0;      ///< lines that carry no measurement (echoes, banners)
  std::uint64_t rejected = 0;     ///< lines that looked like data but did not decode
  std::uint64_t implausible = 0;  ///< of `rejected`: decoded, but a value is impossible
  std::uint64_t overflows = 0;    ///< over-long lines discarded by the framer
  std::uint64_t filtered = 0;     ///< valid measurements dropped by configuration
  std::uint64_t reconnects = 0;   ///< successful re-opens after a lost device
  double last_data_time = 0.0;    ///< receive time of the last byte, s; 0 = never
  bool connected = false;
};

/// Counters every line-based driver keeps. Written by the I/O thread, read by the
/// diagnostics thread, hence atomics (relaxed: each counter is independent).
struct DriverStats {
  std::atomic<std::uint64_t> bytes{0};
  std::atomic<std::uint64_t> messages{0};
  std::atomic<std::uint64_t> dropped{0};
  std::atomic<std::size_t> queue_peak{0};
  std::atomic<std::uint64_t> ignored{0};
  std::atomic<std::uint64_t> rejected{0};
  std::atomic<std::uint64_t> implausible{0};
  std::atomic<std::uint64_t> overflows{0};
  std::atomic<std::uint64_t> filtered{0};
  std::atomic<std::uint64_t> reconnects{0};
  std::atomic<double> last_data_time{0.0};
  std::atomic<bool> connected{false};

  DriverStatsSnapshot snapshot() const {
    constexpr auto r = std::memory_order_relaxed;
    DriverStatsSnapshot s;
    s.bytes = bytes.load(r);
    s.messages = messages.load(r);
    s.dropped = dropped.load(r);
    s.queue_peak = queue_peak.load(r);
    s.ignored = ignored.load(r);
    s.rejected = rejected.load(r);
    s.implausible = implausible.load(r);
    s.overflows = overflows.load(r);
    s.filtered = filtered.load(r);
    s.reconnects = reconnects.load(r);
    s.last_data_time = last_data_time.load(r);
    s.connected = connected.load(r);
    return s;
  }
};

}  // namespace radio_follow::drivers
