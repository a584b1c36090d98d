// SPDX-License-Identifier: BSD-3-Clause
// The transport on loopback: datagrams arrive intact, and a bind that cannot succeed is
// retried with backoff instead of ending the transport.
#include "radio_follow/drivers/tdoa_udp_transport.hpp"

#include <gtest/gtest.h>

#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/udp.hpp>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace radio_follow {
namespace drivers {
namespace {

using boost::asio::ip::udp;
using namespace std::chrono_literals;

struct Inbox {
  std::mutex mutex;
  std::condition_variable cv;
  std::vector<std::vector<std::uint8_t>> datagrams;
  std::vector<std::string> errors;
  std::vector<double> delays;
};

TEST(TdoaUdpTransport, DeliversDatagramsFromLoopback) {
  Inbox inbox;
  TdoaUdpTransport::Config config;
  config.address = "127.0.0.1";
  config.port = 0;  // the kernel picks a free port
  TdoaUdpTransport transport(
      config,
      [&](const std::uint8_t* data, std::size_t size) {
        std::lock_guard<std::mutex> lock(inbox.mutex);
        inbox.datagrams.emplace_back(data, data + size);
        inbox.cv.notify_all();
      },
      [&](const std::string& what, double) {
        std::lock_guard<std::mutex> lock(inbox.mutex);
        inbox.errors.push_back(what);
      });
  transport.start();

  // The transport binds on its own thread; wait for the port it got.
  for (int i = 0; i < 2000 && transport.localPort() == 0; ++i) {
    std::this_thread::sleep_for(10ms);
  }
  ASSERT_NE(transport.localPort(), 0);
  boost::asio::io_context io;
  udp::socket sender(io, udp::v4());
  const udp::endpoint target(boost::asio::ip::make_address("127.0.0.1"), transport.localPort());
  const std::vector<std::uint8_t> payload{0x02, 0x01, 0xFF, 0x00, 0x7F};
  std::unique_lock<std::mutex> lock(inbox.mutex);
  for (int attempt = 0; attempt < 400 && inbox.datagrams.empty(); ++attempt) {
    lock.unlock();
    sender.send_to(boost::asio::buffer(payload), target);
    lock.lock();
    inbox.cv.wait_for(lock, 50ms, [&] { return !inbox.datagrams.empty(); });
  }
  ASSERT_FALSE(inbox.datagrams.empty());
  EXPECT_EQ(inbox.datagrams.front(), payload);
  EXPECT_TRUE(inbox.errors.empty());
  EXPECT_TRUE(transport.isOpen());
  EXPECT_EQ(transport.reconnects(), 0u);
  lock.unlock();
  // A second transport on the same port cannot bind (no SO_REUSEADDR) and says so.
  std::vector<std::string> errors;
  std::mutex errors_mutex;
  TdoaUdpTransport::Config same = config;
  same.port = transport.localPort();
  same.initial_backoff = 0.01;
  TdoaUdpTransport second(
      same, [](const std::uint8_t*, std::size_t) {},
      [&](const std::string& what, double) {
        std::lock_guard<std::mutex> guard(errors_mutex);
        errors.push_back(what);
      });
  second.start();
  for (int i = 0; i < 2000 && second.failures() == 0; ++i) {
    std::this_thread::sleep_for(10ms);
  }
  second.stop();
  EXPECT_GE(second.failures(), 1u);
  EXPECT_FALSE(second.isOpen());
  transport.stop();
  EXPECT_FALSE(transport.isOpen());
}

TEST(TdoaUdpTransport, RetriesAnUnavailableAddressWithGrowingBackoff) {
  Inbox inbox;
  TdoaUdpTransport::Config config;
  config.address = "192.0.2.1";  // TEST-NET-1: never assigned to a local interface
  config.port = 6666;
  config.initial_backoff = 0.01;
  config.max_backoff = 0.04;
  TdoaUdpTransport transport(
      config, [](const std::uint8_t*, std::size_t) {},
      [&](const std::string& what, double retry_in) {
        std::lock_guard<std::mutex> lock(inbox.mutex);
        inbox.errors.push_back(what);
        inbox.delays.push_back(retry_in);
        inbox.cv.notify_all();
      });
  transport.start();
  {
    std::unique_lock<std::mutex> lock(inbox.mutex);
    ASSERT_TRUE(inbox.cv.wait_for(lock, 20s, [&] { return inbox.errors.size() >= 4; }));
    EXPECT_NE(inbox.errors.front().find("cannot bind 192.0.2.1:6666"), std::string::npos)
        << inbox.errors.front();
    EXPECT_DOUBLE_EQ(inbox.delays[0], 0.01);
    EXPECT_DOUBLE_EQ(inbox.delays[1], 0.02);
    EXPECT_DOUBLE_EQ(inbox.delays[2], 0.04);
    EXPECT_DOUBLE_EQ(inbox.delays[3], 0.04);  // capped
  }
  EXPECT_FALSE(transport.isOpen());
  EXPECT_GE(transport.failures(), 4u);
  transport.stop();
}

TEST(TdoaUdpTransport, InvalidAddressIsReportedNotThrown) {
  Inbox inbox;
  TdoaUdpTransport::Config config;
  config.address = "not-an-address";
  config.initial_backoff = 0.01;
  TdoaUdpTransport transport(
      config, [](const std::uint8_t*, std::size_t) {},
      [&](const std::string& what, double) {
        std::lock_guard<std::mutex> lock(inbox.mutex);
        inbox.errors.push_back(what);
        inbox.cv.notify_all();
      });
  transport.start();
  std::unique_lock<std::mutex> lock(inbox.mutex);
  ASSERT_TRUE(inbox.cv.wait_for(lock, 20s, [&] { return !inbox.errors.empty(); }));
  EXPECT_NE(inbox.errors.front().find("invalid address"), std::string::npos);
}

}  // namespace
}  // namespace drivers
}  // namespace radio_follow
