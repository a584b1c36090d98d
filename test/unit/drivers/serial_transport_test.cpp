// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/drivers/serial_transport.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <condition_variable>
#include <mutex>
#include <string>
#include <thread>

#include "../../support/pty_device.hpp"

namespace radio_follow::drivers {
namespace {

using namespace std::chrono_literals;

// Collects transport events; waits are for events, with a generous deadline only so a
// broken build fails instead of hanging.
struct Events {
  std::mutex mutex;
  std::condition_variable changed;
  std::string bytes;
  int connects = 0;
  int disconnects = 0;

  template <typename Predicate>
  bool waitFor(Predicate predicate) {
    std::unique_lock<std::mutex> lock(mutex);
    return changed.wait_for(lock, 20s, [&] { return predicate(); });
  }
};

SerialTransport::Callbacks callbacksFor(Events& events) {
  SerialTransport::Callbacks callbacks;
  callbacks.on_bytes = [&events](const char* data, std::size_t size) {
    std::lock_guard<std::mutex> lock(events.mutex);
    events.bytes.append(data, size);
    events.changed.notify_all();
  };
  callbacks.on_connected = [&events] {
    std::lock_guard<std::mutex> lock(events.mutex);
    ++events.connects;
    events.changed.notify_all();
  };
  callbacks.on_disconnected = [&events](const std::string&) {
    std::lock_guard<std::mutex> lock(events.mutex);
    ++events.disconnects;
    events.changed.notify_all();
  };
  return callbacks;
}

std::string linkPath(const char* name) {
  return "/tmp/radio_follow_" + std::string(name) + "_" + std::to_string(::getpid());
}

TEST(SerialTransport, ReadsWritesAndSurvivesUnplugReplug) {
  const std::string link = linkPath("transport");
  test::PtyDevice::Behaviour behaviour;
  behaviour.on_input = [](const std::string& input) { return "echo:" + input; };
  test::PtyDevice device(link, behaviour);

  Events events;
  SerialTransport::Options options;
  options.port = link;
  options.max_backoff = 200ms;
  SerialTransport transport(options, callbacksFor(events));
  transport.start();
  ASSERT_TRUE(events.waitFor([&] { return events.connects == 1; }));
  EXPECT_EQ(transport.state(), SerialTransport::State::kOpen);

  transport.write("ping\r");
  ASSERT_TRUE(
      events.waitFor([&] { return events.bytes.find("echo:ping\r") != std::string::npos; }));
  device.send("hello\n");
  ASSERT_TRUE(events.waitFor([&] { return events.bytes.find("hello\n") != std::string::npos; }));

  device.vanish();
  ASSERT_TRUE(events.waitFor([&] { return events.disconnects >= 1; }));
  EXPECT_EQ(transport.state(), SerialTransport::State::kClosed);
  // While absent the transport keeps retrying on a timer and reports the absence once.
  std::this_thread::sleep_for(600ms);
  {
    std::lock_guard<std::mutex> lock(events.mutex);
    EXPECT_EQ(events.disconnects, 1);
    EXPECT_EQ(events.connects, 1);
  }
  transport.write("lost\r");  // dropped: there is no connection to send it on

  ASSERT_TRUE(device.appear());
  ASSERT_TRUE(events.waitFor([&] { return events.connects == 2; }));
  EXPECT_EQ(transport.reconnects(), 1u);
  device.send("again\n");
  ASSERT_TRUE(events.waitFor([&] { return events.bytes.find("again\n") != std::string::npos; }));
  transport.write("pong\r");
  ASSERT_TRUE(
      events.waitFor([&] { return events.bytes.find("echo:pong\r") != std::string::npos; }));
  EXPECT_EQ(device.received().find("lost"), std::string::npos);

  transport.stop();
  EXPECT_EQ(transport.state(), SerialTransport::State::kStopped);
}

TEST(SerialTransport, StartsBeforeDeviceExists) {
  const std::string link = linkPath("late");
  ::unlink(link.c_str());
  Events events;
  SerialTransport::Options options;
  options.port = link;
  SerialTransport transport(options, callbacksFor(events));
  transport.start();
  ASSERT_TRUE(events.waitFor([&] { return events.disconnects == 1; }));
  test::PtyDevice device(link, {});
  ASSERT_TRUE(events.waitFor([&] { return events.connects == 1; }));
  EXPECT_EQ(transport.reconnects(), 0u);
  transport.stop();
}

TEST(SerialTransport, StopDrainsQueuedWrites) {
  const std::string link = linkPath("drain");
  test::PtyDevice device(link, {});
  Events events;
  SerialTransport::Options options;
  options.port = link;
  SerialTransport transport(options, callbacksFor(events));
  transport.start();
  ASSERT_TRUE(events.waitFor([&] { return events.connects == 1; }));
  transport.write("lec\rquit\r");
  transport.stop(1000ms);
  // The PTY delivers what was written; give the device thread a moment to read it.
  for (int i = 0; i < 200 && device.received() != "lec\rquit\r"; ++i) {
    std::this_thread::sleep_for(10ms);
  }
  EXPECT_EQ(device.received(), "lec\rquit\r");
}

}  // namespace
}  // namespace radio_follow::drivers
