// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/drivers/serial_line_params.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "radio_follow/common/param_error.hpp"

namespace radio_follow::drivers {

void SerialLineParams::load(const ParamSource& params) {
  params.param("port", port, port);
  params.param("baud", baud, baud);
  params.param("reconnect_backoff", reconnect_backoff, reconnect_backoff);
  params.param("silence_timeout", silence_timeout, silence_timeout);
  params.param("max_line_length", max_line_length, max_line_length);
}

void SerialLineParams::validate(const std::string& example_port) const {
  require(!port.empty(), "port", port, "a device path such as " + example_port);
  require(baud > 0, "baud", baud, "a positive baud rate (the devices use 115200)");
  require(reconnect_backoff > 0.0 && reconnect_backoff <= 10.0, "reconnect_backoff",
          reconnect_backoff, "seconds in (0, 10]");
  require(silence_timeout > 0.0, "silence_timeout", silence_timeout, "positive seconds");
  require(max_line_length >= 64, "max_line_length", max_line_length, "at least 64 bytes");
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
