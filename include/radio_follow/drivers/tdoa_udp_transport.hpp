// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <array>
#include <atomic>
#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/udp.hpp>
#include <boost/asio/steady_timer.hpp>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <thread>

#include "radio_follow/drivers/backoff.hpp"

namespace radio_follow {
namespace drivers {

/// Receives UDP datagrams on its own io_context thread and keeps the socket alive:
/// any open/bind/receive error closes the socket and schedules a new attempt after a
/// Backoff (initial_backoff doubling up to max_backoff; reset by a bind that succeeds). It never
/// busy-waits and never logs; it reports through callbacks.
class TdoaUdpTransport {
 public:
  struct Config {
    std::string address = "0.0.0.0";  ///< Local IPv4/IPv6 address to bind.
    std::uint16_t port = 6666;        ///< 0 = any free port (see localPort()).
    double initial_backoff = 0.5;     ///< Seconds.
    double max_backoff = 10.0;        ///< Seconds.
  };

  /// Called on the I/O thread with each datagram (the bytes live only during the call).
  using DatagramHandler = std::function<void(const std::uint8_t* data, std::size_t size)>;
  /// Called on the I/O thread with a description of a socket failure and the retry delay.
  using ErrorHandler = std::function<void(const std::string& what, double retry_in)>;

  TdoaUdpTransport(Config config, DatagramHandler on_datagram, ErrorHandler on_error);
  ~TdoaUdpTransport();
  TdoaUdpTransport(const TdoaUdpTransport&) = delete;
  TdoaUdpTransport& operator=(const TdoaUdpTransport&) = delete;

  /// Starts the I/O thread (which binds, retrying as needed). Call once.
  void start();
  /// Stops the thread and closes the socket; safe to call twice.
  void stop();

  bool isOpen() const { return open_.load(); }
  /// Port of the last successful bind (the kernel's choice when Config::port is 0).
  std::uint16_t localPort() const { return local_port_.load(); }
  /// Successful binds after the first.
  std::uint64_t reconnects() const { return reconnects_.load(); }
  /// Failed open/bind/receive attempts.
  std::uint64_t failures() const { return failures_.load(); }

 private:
  void tryOpen();
  void receive();
  void fail(const std::string& what);

  Config config_;
  DatagramHandler on_datagram_;
  ErrorHandler on_error_;
  boost::asio::io_context io_;
  boost::asio::ip::udp::socket socket_;
  boost::asio::steady_timer retry_timer_;
  boost::asio::ip::udp::endpoint sender_;
  std::array<std::uint8_t, 65536> buffer_{};
  std::thread thread_;
  Backoff backoff_;
  std::atomic<bool> open_{false};
  std::atomic<std::uint16_t> local_port_{0};
  std::atomic<std::uint64_t> binds_{0};
  std::atomic<std::uint64_t> reconnects_{0};
  std::atomic<std::uint64_t> failures_{0};
};

}  // namespace drivers
}  // namespace radio_follow
