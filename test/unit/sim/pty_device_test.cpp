// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/sim/pty_device.hpp"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <poll.h>
#include <unistd.h>

#include <cerrno>
#include <string>

namespace radio_follow {
namespace sim {
namespace {

std::string linkPath() {
  return "/tmp/rf_pty_test_" + std::to_string(::getpid());
}

std::string readWithTimeout(int fd, std::size_t want) {
  std::string out;
  char buffer[256];
  while (out.size() < want) {
    pollfd p{fd, POLLIN, 0};
    if (::poll(&p, 1, 2000) <= 0)
      break;
    const ssize_t n = ::read(fd, buffer, sizeof(buffer));
    if (n <= 0)
      break;
    out.append(buffer, static_cast<std::size_t>(n));
  }
  return out;
}

TEST(PtyDevice, HostSeesBytesBothWaysThroughTheLink) {
  PtyDevice device(linkPath());
  ASSERT_TRUE(device.plug()) << device.error();
  const int host = ::open(device.linkPath().c_str(), O_RDWR | O_NOCTTY);
  ASSERT_GE(host, 0);
  device.write("DIST,0\r\n");
  EXPECT_EQ(readWithTimeout(host, 8), "DIST,0\r\n");
  ASSERT_EQ(::write(host, "\r\r", 2), 2);
  std::string received;
  for (int i = 0; i < 100 && received.size() < 2; ++i) {
    received += device.read();
    ::usleep(10000);
  }
  EXPECT_EQ(received, "\r\r");  // raw: no echo, no CR translation
  ::close(host);
}

TEST(PtyDevice, UnplugLooksLikeAVanishedUsbDevice) {
  PtyDevice device(linkPath());
  ASSERT_TRUE(device.plug()) << device.error();
  const int host = ::open(device.linkPath().c_str(), O_RDWR | O_NOCTTY);
  ASSERT_GE(host, 0);
  device.unplug();
  char c;
  const ssize_t n = ::read(host, &c, 1);  // hang-up: EIO or end of file, never a block
  EXPECT_LE(n, 0);
  ::close(host);
  EXPECT_NE(::access(device.linkPath().c_str(), F_OK), 0);  // the path is gone
  device.write("lost");
  EXPECT_EQ(device.droppedBytes(), 4u);
  ASSERT_TRUE(device.plug());  // back at the same path
  EXPECT_EQ(::access(device.linkPath().c_str(), F_OK), 0);
}

}  // namespace
}  // namespace sim
}  // namespace radio_follow
