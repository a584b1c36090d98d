// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/drivers/serial_line_params.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "radio_follow/common/param_error.hpp"

namespace radio_follow::drivers {

const ParamTable<SerialLineParams>& SerialLineParams::table() {
  using P = SerialLineParams;
  static const ParamTable<P> t =
      ParamTable<P>()
          .add("port", &P::port, "", "Serial device, the udev symlink (required).")
          .add("baud", &P::baud, "baud", "UART speed (the devices use 115200).", Range::above(0))
          .add("reconnect_backoff", &P::reconnect_backoff, "s",
               "Longest wait between attempts to reopen an absent device.",
               Range::aboveUpTo(0.0, 10.0))
          .add("silence_timeout", &P::silence_timeout, "s",
               "A connected device silent this long is reported.", Range::above(0.0))
          .add("max_line_length", &P::max_line_length, "bytes",
               "Longer lines are discarded and counted.", Range::atLeast(64));
  return t;
}

void SerialLineParams::load(const ParamSource& params) {
  table().load(params, *this);
}

void SerialLineParams::validate(const std::string& example_port) const {
  require(!port.empty(), "~port", port, "a device path such as " + example_port);
  table().check(*this);
}

SerialTransport::Options SerialLineParams::transportOptions() const {
  SerialTransport::Options options;
  options.port = port;
  options.baud = static_cast<unsigned>(baud);
  // At least 1 ms: a wait rounded to zero would retry in a busy loop.
  options.max_backoff =
      std::chrono::milliseconds(std::max(1L, std::lround(reconnect_backoff * 1000.0)));
  return options;
}

}  // namespace radio_follow::drivers
