// SPDX-License-Identifier: BSD-3-Clause
#pragma once

// A fake serial device for tests: a pseudo-terminal whose slave side is reachable
// through a symlink (like a udev symlink), driven by a behaviour callback on its own
// thread. vanish() closes the PTY and removes the link (an unplug); appear() creates a
// new PTY and points the same link at it (a replug, usually on a new tty node).
// Header-only and ROS-free, so unit tests and rostest nodes can both use it.

#include <fcntl.h>
#include <poll.h>
#include <pty.h>
#include <termios.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <functional>
#include <mutex>
#include <string>
#include <thread>

namespace radio_follow::test {

class PtyDevice {
 public:
  /// Device logic: `on_input` gets bytes the driver wrote and returns the reply;
  /// `periodic` is called every `period` and returns bytes to emit (e.g. a stream).
  struct Behaviour {
    std::function<std::string(const std::string& input)> on_input;
    std::function<std::string()> periodic;
    std::chrono::milliseconds period{20};
  };

  PtyDevice(std::string link_path, Behaviour behaviour)
      : link_path_(std::move(link_path)), behaviour_(std::move(behaviour)) {
    appear();
    thread_ = std::thread([this] { run(); });
  }

  ~PtyDevice() {
    running_ = false;
    thread_.join();
    vanish();
  }

  PtyDevice(const PtyDevice&) = delete;
  PtyDevice& operator=(const PtyDevice&) = delete;

  /// Unplug: close both PTY ends (the driver's reads fail) and remove the link.
  void vanish() {
    std::lock_guard<std::mutex> lock(mutex_);
    if (master_ >= 0) {
      ::close(master_);
      ::close(slave_);
      master_ = slave_ = -1;
    }
    ::unlink(link_path_.c_str());
  }

  /// Plug in (again): a fresh PTY behind the same link path. False on failure.
  bool appear() {
    std::lock_guard<std::mutex> lock(mutex_);
    if (master_ >= 0) {
      return true;
    }
    char name[256] = {};
    if (::openpty(&master_, &slave_, name, nullptr, nullptr) != 0) {
      master_ = slave_ = -1;
      return false;
    }
    termios tio{};
    ::tcgetattr(slave_, &tio);
    ::cfmakeraw(&tio);
    ::tcsetattr(slave_, TCSANOW, &tio);
    // Non-blocking: with nobody reading the slave a blocking write would hang the test.
    ::fcntl(master_, F_SETFL, ::fcntl(master_, F_GETFL) | O_NONBLOCK);
    ::unlink(link_path_.c_str());
    return ::symlink(name, link_path_.c_str()) == 0;
  }

  /// Everything the driver has written so far.
  std::string received() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return received_;
  }

  /// Runs `fn` while the behaviour callbacks are held off (to change the fake's state).
  template <typename Fn>
  void locked(Fn&& fn) {
    std::lock_guard<std::mutex> lock(mutex_);
    fn();
  }

  /// Emits `bytes` now (outside the periodic schedule).
  void send(const std::string& bytes) {
    std::lock_guard<std::mutex> lock(mutex_);
    writeLocked(bytes);
  }

 private:
  void writeLocked(const std::string& bytes) {
    if (master_ < 0 || bytes.empty()) {
      return;
    }
    // Bytes that do not fit (nobody reading) are lost, as on a real UART.
    const ssize_t written = ::write(master_, bytes.data(), bytes.size());
    (void)written;
  }

  void run() {
    auto next = std::chrono::steady_clock::now();
    while (running_) {
      int fd = -1;
      {
        std::lock_guard<std::mutex> lock(mutex_);
        fd = master_;
      }
      if (fd < 0) {
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
        continue;
      }
      pollfd p{fd, POLLIN, 0};
      if (::poll(&p, 1, 5) > 0 && (p.revents & POLLIN) != 0) {
        char buffer[512];
        std::lock_guard<std::mutex> lock(mutex_);
        if (master_ == fd) {
          const ssize_t n = ::read(fd, buffer, sizeof(buffer));
          if (n > 0) {
            const std::string input(buffer, static_cast<std::size_t>(n));
            received_ += input;
            if (behaviour_.on_input) {
              writeLocked(behaviour_.on_input(input));
            }
          }
        }
      }
      if (std::chrono::steady_clock::now() >= next) {
        next += behaviour_.period;
        if (behaviour_.periodic) {
          std::lock_guard<std::mutex> lock(mutex_);
          writeLocked(behaviour_.periodic());
        }
      }
    }
  }

  std::string link_path_;
  Behaviour behaviour_;
  mutable std::mutex mutex_;
  int master_ = -1;
  int slave_ = -1;
  std::string received_;
  std::atomic<bool> running_{true};
  std::thread thread_;
};

}  // namespace radio_follow::test
