// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/drivers/serial_transport.hpp"

#include <boost/asio/post.hpp>
#include <boost/asio/read.hpp>
#include <boost/asio/write.hpp>
#include <memory>
#include <utility>

namespace radio_follow::drivers {

namespace asio = boost::asio;

SerialTransport::SerialTransport(Options options, Callbacks callbacks)
    : options_(std::move(options)),
      callbacks_(std::move(callbacks)),
      port_(io_),
      retry_timer_(io_),
      backoff_(options_.initial_backoff, options_.max_backoff) {}

SerialTransport::~SerialTransport() {
  stop(std::chrono::milliseconds(0));
}

void SerialTransport::start() {
  if (thread_.joinable()) {
    return;
  }
  state_ = State::kClosed;
  asio::post(io_, [this] { tryOpen(); });
  thread_ = std::thread([this] { io_.run(); });
}

void SerialTransport::stop(std::chrono::milliseconds drain) {
  if (!thread_.joinable()) {
    return;
  }
  // Give queued writes (e.g. the command that stops a stream) a chance to leave. The
  // flags are shared: a check still queued when the deadline passes must not write to
  // this frame's stack.
  const auto deadline = std::chrono::steady_clock::now() + drain;
  while (std::chrono::steady_clock::now() < deadline) {
    auto empty = std::make_shared<std::atomic<bool>>(false);
    auto answered = std::make_shared<std::atomic<bool>>(false);
    asio::post(io_, [this, empty, answered] {
      *empty = write_queue_.empty();
      *answered = true;
    });
    while (!*answered && std::chrono::steady_clock::now() < deadline) {
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    if (!*answered || *empty) {
      break;
    }
  }
  io_.stop();
  thread_.join();
  boost::system::error_code ignored;
  port_.close(ignored);
  state_ = State::kStopped;
}

void SerialTransport::write(std::string text) {
  asio::post(io_, [this, text = std::move(text)]() mutable {
    if (state_ != State::kOpen) {
      return;
    }
    write_queue_.push_back(std::move(text));
    if (write_queue_.size() == 1) {
      startWrite();
    }
  });
}

void SerialTransport::tryOpen() {
  boost::system::error_code ec;
  port_.open(options_.port, ec);
  if (!ec) {
    port_.set_option(asio::serial_port::baud_rate(options_.baud), ec);
  }
  if (!ec) {
    port_.set_option(asio::serial_port::character_size(8), ec);
  }
  if (!ec) {
    port_.set_option(asio::serial_port::parity(asio::serial_port::parity::none), ec);
  }
  if (!ec) {
    port_.set_option(asio::serial_port::stop_bits(asio::serial_port::stop_bits::one), ec);
  }
  if (!ec) {
    port_.set_option(asio::serial_port::flow_control(asio::serial_port::flow_control::none), ec);
  }
  if (ec) {
    boost::system::error_code ignored;
    port_.close(ignored);
    // Report an absent device once per absence, not on every retry.
    if (!reported_absent_ && callbacks_.on_disconnected) {
      callbacks_.on_disconnected(options_.port + ": " + ec.message());
    }
    reported_absent_ = true;
    scheduleRetry();
    return;
  }
  if (ever_opened_) {
    ++reconnects_;
  }
  ever_opened_ = true;
  reported_absent_ = false;
  backoff_.reset();
  state_ = State::kOpen;
  if (callbacks_.on_connected) {
    callbacks_.on_connected();
  }
  startRead();
}

void SerialTransport::scheduleRetry() {
  retry_timer_.expires_after(backoff_.next());
  retry_timer_.async_wait([this](const boost::system::error_code& ec) {
    if (!ec) {
      tryOpen();
    }
  });
}

void SerialTransport::startRead() {
  port_.async_read_some(asio::buffer(read_buffer_),
                        [this](const boost::system::error_code& ec, std::size_t size) {
                          if (ec) {
                            if (ec != asio::error::operation_aborted) {
                              closeWithError(ec.message());
                            }
                            return;
                          }
                          if (callbacks_.on_bytes) {
                            callbacks_.on_bytes(read_buffer_.data(), size);
                          }
                          startRead();
                        });
}

void SerialTransport::startWrite() {
  asio::async_write(port_, asio::buffer(write_queue_.front()),
                    [this](const boost::system::error_code& ec, std::size_t) {
                      if (ec) {
                        if (ec != asio::error::operation_aborted) {
                          closeWithError(ec.message());
                        }
                        return;
                      }
                      write_queue_.pop_front();
                      if (!write_queue_.empty()) {
                        startWrite();
                      }
                    });
}

void SerialTransport::closeWithError(const std::string& reason) {
  if (state_ != State::kOpen) {
    return;
  }
  boost::system::error_code ignored;
  port_.close(ignored);  // cancels the other pending operation with operation_aborted
  write_queue_.clear();
  state_ = State::kClosed;
  reported_absent_ = true;
  if (callbacks_.on_disconnected) {
    callbacks_.on_disconnected(options_.port + ": " + reason);
  }
  scheduleRetry();
}

}  // namespace radio_follow::drivers
