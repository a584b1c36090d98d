// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstddef>
#include <string>

namespace radio_follow {
namespace sim {

/// A fake serial device: a pseudo-terminal in raw mode whose slave side is reachable at a
/// fixed symlink path (as a udev rule gives a real device), so an unchanged driver can
/// open it. `unplug()` closes the master and removes the link, which a driver sees as a
/// vanished USB device (EIO/hang-up, then ENOENT); `plug()` brings up a new terminal at
/// the same path. POSIX only; no ROS.
class PtyDevice {
 public:
  explicit PtyDevice(std::string link_path);
  ~PtyDevice();
  PtyDevice(const PtyDevice&) = delete;
  PtyDevice& operator=(const PtyDevice&) = delete;

  /// Creates the terminal and the link. Returns false and sets error() on failure.
  bool plug();
  /// Closes the terminal and removes the link (idempotent).
  void unplug();
  bool plugged() const { return master_ >= 0; }

  /// Bytes the host wrote since the last call (non-blocking; empty when none).
  std::string read();
  /// Writes bytes towards the host without blocking; bytes that do not fit (nobody reads
  /// for a long time) are dropped and counted, like a UART overrun.
  void write(const std::string& bytes);

  const std::string& linkPath() const { return link_path_; }
  const std::string& error() const { return error_; }
  std::size_t droppedBytes() const { return dropped_; }

 private:
  std::string link_path_;
  int master_ = -1;
  int slave_ = -1;
  std::string error_;
  std::size_t dropped_ = 0;
};

}  // namespace sim
}  // namespace radio_follow
