// SPDX-License-Identifier: BSD-3-Clause
#pragma once

// A fake serial device for tests: a pseudo-terminal whose slave side is reachable
// through a symlink (like a udev symlink), driven by a behaviour callback on its own
// thread. vanish() closes the PTY and removes the link (an unplug); appear() creates a
// new PTY and points the same link at it (a replug, usually on a new tty node). The
// terminal itself is the simulator's sim::PtyDevice; this adds the behaviour thread.
// Header-only and ROS-free, so unit tests and rostest nodes can both use it.

#include <atomic>
#include <chrono>
#include <functional>
#include <mutex>
#include <string>
#include <thread>

#include "radio_follow/sim/pty_device.hpp"

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
      : behaviour_(std::move(behaviour)), device_(std::move(link_path)) {
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

  /// Unplug: close the terminal (the driver's reads fail) and remove the link.
  void vanish() {
    std::lock_guard<std::mutex> lock(mutex_);
    device_.unplug();
  }

  /// Plug in (again): a fresh PTY behind the same link path. False on failure.
  bool appear() {
    std::lock_guard<std::mutex> lock(mutex_);
    return device_.plug();
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
    if (!bytes.empty()) {
      device_.write(bytes);  // bytes nobody reads are dropped, as on a real UART
    }
  }

  void run() {
    auto next = std::chrono::steady_clock::now();
    while (running_) {
      {
        std::lock_guard<std::mutex> lock(mutex_);
        const std::string input = device_.read();
        if (!input.empty()) {
          received_ += input;
          if (behaviour_.on_input) {
            writeLocked(behaviour_.on_input(input));
          }
        }
        if (std::chrono::steady_clock::now() >= next) {
          next += behaviour_.period;
          if (behaviour_.periodic) {
            writeLocked(behaviour_.periodic());
          }
        }
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
  }

  Behaviour behaviour_;
  mutable std::mutex mutex_;
  sim::PtyDevice device_;
  std::string received_;
  std::atomic<bool> running_{true};
  std::thread thread_;
};

}  // namespace radio_follow::test
