// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>

#include "radio_follow/common/param_source.hpp"
#include "radio_follow/common/param_table.hpp"
#include "radio_follow/drivers/serial_transport.hpp"

namespace radio_follow::drivers {

/// The parameters every serial-line driver has (dwm1001_driver, ublox_aoa_driver; the
/// same keys in config/dwm1001_driver.yaml and config/ublox_aoa_driver.yaml). A driver's
/// own Params derive from it and call its load() and validate() first.
struct SerialLineParams {
  std::string port;                ///< device path (udev symlink), required
  int baud = 115200;               ///< baud
  double reconnect_backoff = 1.0;  ///< s, longest wait between open attempts
  double silence_timeout = 2.0;    ///< s
  int max_line_length = 1024;      ///< bytes

  /// port, baud, reconnect_backoff, silence_timeout, max_line_length.
  static const ParamTable<SerialLineParams>& table();
  void load(const ParamSource& params);
  /// Throws ParamError naming the first invalid value; `example_port` (e.g.
  /// "/dev/aoa_front") completes the message for a missing port.
  void validate(const std::string& example_port) const;
  /// The transport's options: waits from 0.1 s doubling up to `reconnect_backoff`.
  SerialTransport::Options transportOptions() const;
};

}  // namespace radio_follow::drivers
