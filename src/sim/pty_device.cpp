// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/sim/pty_device.hpp"

#include <fcntl.h>
#include <pty.h>
#include <termios.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <utility>

namespace radio_follow {
namespace sim {

PtyDevice::PtyDevice(std::string link_path) : link_path_(std::move(link_path)) {}

PtyDevice::~PtyDevice() {
  unplug();
}

bool PtyDevice::plug() {
  if (plugged()) {
    return true;
  }
  char name[256] = {0};
  if (::openpty(&master_, &slave_, name, nullptr, nullptr) != 0) {
    error_ = std::string("openpty: ") + std::strerror(errno);
    master_ = slave_ = -1;
    return false;
  }
  // Raw 8N1 with no echo, like a USB CDC serial port.
  termios tio{};
  ::tcgetattr(slave_, &tio);
  ::cfmakeraw(&tio);
  ::tcsetattr(slave_, TCSANOW, &tio);
  ::fcntl(master_, F_SETFL, ::fcntl(master_, F_GETFL) | O_NONBLOCK);
  ::unlink(link_path_.c_str());
  if (::symlink(name, link_path_.c_str()) != 0) {
    error_ = "symlink " + link_path_ + ": " + std::strerror(errno);
    unplug();
    return false;
  }
  return true;
}

void PtyDevice::unplug() {
  if (master_ >= 0) {
    ::unlink(link_path_.c_str());
    ::close(master_);
    master_ = -1;
  }
  if (slave_ >= 0) {
    ::close(slave_);
    slave_ = -1;
  }
}

std::string PtyDevice::read() {
  std::string out;
  if (!plugged()) {
    return out;
  }
  char buffer[512];
  for (;;) {
    const ssize_t n = ::read(master_, buffer, sizeof(buffer));
    if (n <= 0) {
      break;  // EAGAIN: nothing more now
    }
    out.append(buffer, static_cast<std::size_t>(n));
  }
  return out;
}

void PtyDevice::write(const std::string& bytes) {
  if (!plugged()) {
    dropped_ += bytes.size();
    return;
  }
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(master_, bytes.data() + done, bytes.size() - done);
    if (n <= 0) {
      dropped_ += bytes.size() - done;
      return;
    }
    done += static_cast<std::size_t>(n);
  }
}

}  // namespace sim
}  // namespace radio_follow
