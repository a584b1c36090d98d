// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/drivers/tdoa_udp_transport.hpp"

#include <boost/asio/ip/address.hpp>
#include <boost/asio/post.hpp>
#include <chrono>
#include <utility>

namespace radio_follow {
namespace drivers {

namespace asio = boost::asio;
using asio::ip::udp;

namespace {

Backoff::Duration fromSeconds(double seconds) {
  return std::chrono::duration_cast<Backoff::Duration>(std::chrono::duration<double>(seconds));
}

}  // namespace

TdoaUdpTransport::TdoaUdpTransport(Config config, DatagramHandler on_datagram,
                                   ErrorHandler on_error)
    : config_(std::move(config)),
      on_datagram_(std::move(on_datagram)),
      on_error_(std::move(on_error)),
      socket_(io_),
      retry_timer_(io_),
      backoff_(fromSeconds(config_.initial_backoff), fromSeconds(config_.max_backoff)) {}

TdoaUdpTransport::~TdoaUdpTransport() {
  stop();
}

void TdoaUdpTransport::start() {
  asio::post(io_, [this] { tryOpen(); });
  thread_ = std::thread([this] { io_.run(); });
}

void TdoaUdpTransport::stop() {
  if (!thread_.joinable()) {
    return;
  }
  io_.stop();
  thread_.join();
  // The I/O thread is gone, so the socket and timer can be touched from here.
  boost::system::error_code ignored;
  retry_timer_.cancel();
  socket_.close(ignored);
  open_ = false;
}

void TdoaUdpTransport::tryOpen() {
  boost::system::error_code ec;
  const auto address = asio::ip::make_address(config_.address, ec);
  if (ec) {
    fail("invalid address '" + config_.address + "': " + ec.message());
    return;
  }
  const udp::endpoint local(address, config_.port);
  // No SO_REUSEADDR: a second driver on the same port should fail loudly (and retry)
  // rather than silently share the anchors' unicast datagrams with the first.
  socket_.open(local.protocol(), ec);
  if (!ec) {
    socket_.bind(local, ec);
  }
  if (ec) {
    fail("cannot bind " + config_.address + ":" + std::to_string(config_.port) + ": " +
         ec.message());
    return;
  }
  local_port_ = socket_.local_endpoint(ec).port();
  open_ = true;
  backoff_.reset();
  if (binds_++ > 0) {
    ++reconnects_;
  }
  receive();
}

void TdoaUdpTransport::receive() {
  socket_.async_receive_from(asio::buffer(buffer_), sender_,
                             [this](const boost::system::error_code& ec, std::size_t n) {
                               if (ec == asio::error::operation_aborted) {
                                 return;
                               }
                               if (ec) {
                                 fail("receive failed: " + ec.message());
                                 return;
                               }
                               on_datagram_(buffer_.data(), n);
                               receive();
                             });
}

void TdoaUdpTransport::fail(const std::string& what) {
  ++failures_;
  open_ = false;
  boost::system::error_code ignored;
  socket_.close(ignored);
  const Backoff::Duration delay = backoff_.next();
  on_error_(what, std::chrono::duration<double>(delay).count());
  retry_timer_.expires_after(delay);
  retry_timer_.async_wait([this](const boost::system::error_code& ec) {
    if (!ec) {
      tryOpen();
    }
  });
}

}  // namespace drivers
}  // namespace radio_follow
