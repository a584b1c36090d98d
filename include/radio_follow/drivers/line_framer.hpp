// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace radio_follow::drivers {

/// Turns a byte stream into complete text lines. A line ends at '\n' or '\r' (so CRLF,
/// LF and bare CR all work); empty lines are dropped. Bytes after the last terminator are
/// kept until the next chunk completes them. A line longer than `max_line_length` (a
/// device spewing garbage without terminators) is discarded up to its terminator and
/// counted, so memory stays bounded. The framer never logs; it only counts.
class LineFramer {
 public:
  /// Counters since construction (or reset()).
  struct Counters {
    std::uint64_t bytes = 0;      ///< bytes fed
    std::uint64_t lines = 0;      ///< non-empty lines delivered
    std::uint64_t overflows = 0;  ///< over-long lines discarded
  };

  explicit LineFramer(std::size_t max_line_length = 1024) : max_line_length_(max_line_length) {}

  /// Feeds a chunk received at `receive_time` (any clock, seconds) and calls
  /// `sink(std::string_view line, double first_byte_time)` for each completed line. The
  /// time passed is that of the chunk which carried the line's first byte. The view is
  /// valid only during the call.
  template <typename Sink>
  void feed(const char* data, std::size_t size, double receive_time, Sink&& sink) {
    counters_.bytes += size;
    std::size_t start = 0;
    for (std::size_t i = 0; i < size; ++i) {
      const char c = data[i];
      if (c != '\n' && c != '\r') {
        continue;
      }
      if (discarding_) {
        // The tail of an over-long line: drop it and resynchronise here.
        discarding_ = false;
        buffer_.clear();
      } else if (buffer_.empty()) {
        // Common case: the whole line sits in this chunk, no copy.
        emit(std::string_view(data + start, i - start), receive_time, sink);
      } else if (append(data + start, i - start)) {
        emit(std::string_view(buffer_), buffer_time_, sink);
      }
      buffer_.clear();
      start = i + 1;
    }
    if (start < size) {
      if (buffer_.empty() && !discarding_) {
        buffer_time_ = receive_time;
      }
      append(data + start, size - start);
    }
  }

  /// Bytes received after the last terminator (e.g. a shell prompt "dwm> ").
  std::string_view pending() const { return discarding_ ? std::string_view() : buffer_; }

  /// Drops any partial line (after a reconnect the old tail belongs to nobody).
  void reset() {
    buffer_.clear();
    discarding_ = false;
  }

  const Counters& counters() const { return counters_; }

 private:
  // Appends to the partial line; false (and discard mode) when it would grow too long.
  bool append(const char* data, std::size_t size) {
    if (discarding_) {
      return false;
    }
    if (buffer_.size() + size > max_line_length_) {
      ++counters_.overflows;
      discarding_ = true;
      buffer_.clear();
      return false;
    }
    buffer_.append(data, size);
    return true;
  }

  template <typename Sink>
  void emit(std::string_view line, double time, Sink& sink) {
    if (line.empty()) {
      return;
    }
    if (line.size() > max_line_length_) {
      ++counters_.overflows;
      return;
    }
    ++counters_.lines;
    sink(line, time);
  }

  std::size_t max_line_length_;
  std::string buffer_;
  double buffer_time_ = 0.0;
  bool discarding_ = false;
  Counters counters_;
};

}  // namespace radio_follow::drivers
