// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>

#include "radio_follow/drivers/driver_stats.hpp"
#include "radio_follow/drivers/line_framer.hpp"

namespace radio_follow::drivers {

/// What a driver made of one complete line, in the terms of DriverStats.
enum class LineVerdict {
  kMeasurement,  ///< decoded; to be delivered (counted when published)
  kIgnored,      ///< carries no measurement: echo, prompt, banner, log line
  kRejected,     ///< looked like data but did not decode (cut, merged, bad field)
  kImplausible,  ///< decoded, but a value no device can report; counted as rejected too
  kFiltered,     ///< a valid measurement dropped by configuration or state
};

/// The verdict on a line from its decoder's status: `measurement` is the decoder's code
/// for a decoded line; the codes named kIgnored and kImplausible (every decoder's status
/// has both) map to theirs, any other code is a rejection.
template <typename Status>
constexpr LineVerdict verdictOf(Status status, Status measurement) {
  if (status == measurement) {
    return LineVerdict::kMeasurement;
  }
  if (status == Status::kIgnored) {
    return LineVerdict::kIgnored;
  }
  return status == Status::kImplausible ? LineVerdict::kImplausible : LineVerdict::kRejected;
}

/// The ROS-free bookkeeping of a line-based serial driver, between SerialTransport's
/// events and the driver's decoder: the framer, the connection state and every counter of
/// DriverStats. Time is seconds on the caller's clock. It never logs: the caller reads
/// the counters (and what count() returns) and decides what to say.
///
/// onConnected(), onBytes() and pending() use the framer: call them from one thread at a
/// time (the driver's lock). The counters are atomics, so stats(), silent() and
/// onPublished() may be called from any thread.
class LineDriver {
 public:
  explicit LineDriver(std::size_t max_line_length) : framer_(max_line_length) {}

  /// The port opened at `now`: connected, silence counted from now, a partial line of the
  /// previous connection dropped. `reconnects` = the transport's count of re-opens.
  void onConnected(double now, std::uint64_t reconnects) {
    stats_.connected = true;
    stats_.last_data_time = now;
    stats_.reconnects = reconnects;
    framer_.reset();
  }

  /// The port was lost or could not be opened.
  void onDisconnected() { stats_.connected = false; }

  /// A chunk received at `now`: counts it and calls `sink(std::string_view line, double
  /// first_byte_time)` for every line it completes (LineFramer::feed).
  template <typename Sink>
  void onBytes(const char* data, std::size_t size, double now, Sink&& sink) {
    stats_.bytes += size;
    stats_.last_data_time = now;
    framer_.feed(data, size, now, sink);
    stats_.overflows = framer_.counters().overflows;
  }

  /// Bytes after the last line end (a prompt without a newline).
  std::string_view pending() const { return framer_.pending(); }

  /// Counts the verdict on one line; returns the lines rejected so far (for a log line).
  std::uint64_t count(LineVerdict verdict) {
    switch (verdict) {
      case LineVerdict::kIgnored:
        ++stats_.ignored;
        break;
      case LineVerdict::kImplausible:
        ++stats_.implausible;
        ++stats_.rejected;
        break;
      case LineVerdict::kRejected:
        ++stats_.rejected;
        break;
      case LineVerdict::kFiltered:
        ++stats_.filtered;
        break;
      case LineVerdict::kMeasurement:
        break;
    }
    return stats_.rejected.load(std::memory_order_relaxed);
  }

  /// A measurement went to the delivery queue; `kept` false = the queue was full and
  /// dropped its oldest. `peak` = the most the queue has held.
  void onQueued(bool kept, std::size_t peak) {
    if (!kept) {
      ++stats_.dropped;
    }
    stats_.queue_peak = peak;
  }

  /// One measurement published; true for the first one.
  bool onPublished() { return stats_.messages++ == 0; }

  /// Connected, and nothing received for longer than `timeout` at `now`.
  bool silent(double now, double timeout) const {
    return stats_.connected && now - stats_.last_data_time > timeout;
  }

  const DriverStats& stats() const { return stats_; }

 private:
  LineFramer framer_;
  DriverStats stats_;
};

}  // namespace radio_follow::drivers
