// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/drivers/serial_line_params.hpp"

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <chrono>
#include <string>

#include "../../support/expect_refused.hpp"
#include "radio_follow/common/param_error.hpp"
#include "radio_follow/common/yaml_params.hpp"

namespace radio_follow::drivers {
namespace {

using namespace std::chrono_literals;

// expectRefused() calls validate() without arguments, as on a driver's own Params.
struct Checked : SerialLineParams {
  void validate() const { SerialLineParams::validate("/dev/aoa_front"); }
};

TEST(SerialLineParams, LoadsTheSharedKeys) {
  const YamlParams yaml(
      YAML::Load("{port: /dev/aoa_front, baud: 57600, reconnect_backoff: 2, silence_timeout: 0.5, "
                 "max_line_length: 256}"));
  SerialLineParams p;
  p.load(yaml);
  yaml.requireAllKnown();
  EXPECT_EQ(p.port, "/dev/aoa_front");
  EXPECT_EQ(p.baud, 57600);
  EXPECT_DOUBLE_EQ(p.reconnect_backoff, 2.0);
  EXPECT_DOUBLE_EQ(p.silence_timeout, 0.5);
  EXPECT_EQ(p.max_line_length, 256);
}

TEST(SerialLineParams, Validation) {
  Checked p;
  try {
    p.validate();
    ADD_FAILURE() << "no port accepted";
  } catch (const ParamError& e) {
    EXPECT_EQ(e.name(), "~port");
    EXPECT_NE(std::string(e.what()).find("/dev/aoa_front"), std::string::npos) << e.what();
  }
  p.port = "/dev/aoa_front";
  EXPECT_NO_THROW(p.validate());
  auto invalid = [&p](auto change, const std::string& name) {
    radio_follow::test::expectRefused(p, change, name);
  };
  invalid([](auto& q) { q.baud = 0; }, "~baud");
  invalid([](auto& q) { q.reconnect_backoff = 0.0; }, "~reconnect_backoff");
  invalid([](auto& q) { q.reconnect_backoff = 10.5; }, "~reconnect_backoff");
  invalid([](auto& q) { q.silence_timeout = 0.0; }, "~silence_timeout");
  invalid([](auto& q) { q.max_line_length = 63; }, "~max_line_length");
}

TEST(SerialLineParams, TransportWaitsFromATenthUpToReconnectBackoff) {
  SerialLineParams p;
  p.port = "/dev/dwm1001_5722";
  p.baud = 115200;
  p.reconnect_backoff = 2.5;
  SerialTransport::Options options = p.transportOptions();
  EXPECT_EQ(options.port, "/dev/dwm1001_5722");
  EXPECT_EQ(options.baud, 115200u);
  EXPECT_EQ(options.initial_backoff, 100ms);
  EXPECT_EQ(options.max_backoff, 2500ms);
  p.reconnect_backoff = 1e-4;  // valid, but would round to a zero wait
  EXPECT_EQ(p.transportOptions().max_backoff, 1ms);
}

}  // namespace
}  // namespace radio_follow::drivers
