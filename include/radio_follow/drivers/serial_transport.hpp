// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <array>
#include <atomic>
#include <boost/asio/io_context.hpp>
#include <boost/asio/serial_port.hpp>
#include <boost/asio/steady_timer.hpp>
#include <chrono>
#include <cstddef>
#include <deque>
#include <functional>
#include <string>
#include <thread>

#include "radio_follow/drivers/backoff.hpp"

namespace radio_follow::drivers {

/// A serial device on its own Boost.Asio I/O thread, with an explicit reconnect state
/// machine: Closed -> (open ok) Open -> (read error: unplug) Closed -> retry after a
/// Backoff that doubles from `initial_backoff` up to `max_backoff` while the device is
/// absent. The path is re-resolved on every attempt, so a udev symlink that comes back
/// pointing at a new tty node is picked up. The thread sleeps on a timer while the
/// device is absent: a dead port never spins a core. No ROS, no logging: events go to
/// the callbacks, which run on the I/O thread.
class SerialTransport {
 public:
  struct Options {
    std::string port;
    unsigned baud = 115200;
    std::chrono::milliseconds initial_backoff{100};
    std::chrono::milliseconds max_backoff{1000};
  };

  struct Callbacks {
    /// Bytes received (called for every chunk; the pointer is valid during the call).
    std::function<void(const char* data, std::size_t size)> on_bytes;
    /// The port opened (first time or again).
    std::function<void()> on_connected;
    /// The port was lost or could not be opened; `reason` is the system error text.
    std::function<void(const std::string& reason)> on_disconnected;
  };

  enum class State { kStopped, kClosed, kOpen };

  SerialTransport(Options options, Callbacks callbacks);
  ~SerialTransport();
  SerialTransport(const SerialTransport&) = delete;
  SerialTransport& operator=(const SerialTransport&) = delete;

  /// Starts the I/O thread, which tries to open the port at once.
  void start();
  /// Sends what is queued (waiting at most `drain`), closes the port, joins the thread.
  void stop(std::chrono::milliseconds drain = std::chrono::milliseconds(300));
  /// Queues `text` for writing (thread-safe, never blocks). Dropped while closed: a
  /// command meant for the old connection must not reach the next one.
  void write(std::string text);

  State state() const { return state_.load(); }
  /// Successful opens after the first one.
  unsigned reconnects() const { return reconnects_.load(); }

 private:
  void tryOpen();
  void scheduleRetry();
  void startRead();
  void startWrite();
  void closeWithError(const std::string& reason);

  Options options_;
  Callbacks callbacks_;
  boost::asio::io_context io_;
  boost::asio::serial_port port_;
  boost::asio::steady_timer retry_timer_;
  std::array<char, 4096> read_buffer_{};
  std::deque<std::string> write_queue_;  // I/O thread only
  Backoff backoff_;
  std::atomic<State> state_{State::kStopped};
  std::atomic<unsigned> reconnects_{0};
  bool ever_opened_ = false;
  bool reported_absent_ = false;
  std::thread thread_;
};

}  // namespace radio_follow::drivers
