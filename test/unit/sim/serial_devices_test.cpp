// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/sim/serial_devices.hpp"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <poll.h>
#include <sys/stat.h>
#include <unistd.h>

#include <string>

#include "radio_follow/common/param_error.hpp"

namespace radio_follow {
namespace sim {
namespace {

std::string directory() {
  const std::string d = "/tmp/rf_serial_test_" + std::to_string(::getpid());
  ::mkdir(d.c_str(), 0755);
  return d;
}

Layout layout() {
  return parseLayout(R"(
target: {uwb_anchor_id: DA12, aoa_tag_id: CCF9578E0D8A}
twr_modules: [{id: "5722", position: [0, 0, 0]}]
aoa_boards: [{id: front, position: [0, 0, 0]}]
)",
                     "test");
}

/// Reads until `marker` has arrived (or 2 s pass), servicing the devices meanwhile.
std::string readUntil(int fd, SerialDevices& devices, const std::string& marker) {
  std::string out;
  char buffer[512];
  for (int i = 0; i < 200 && out.find(marker) == std::string::npos; ++i) {
    devices.service(0.1);
    pollfd p{fd, POLLIN, 0};
    if (::poll(&p, 1, 10) > 0) {
      const ssize_t n = ::read(fd, buffer, sizeof(buffer));
      if (n > 0)
        out.append(buffer, static_cast<std::size_t>(n));
    }
  }
  return out;
}

TEST(SerialDevices, DwmShellDialogueAndStreamOverThePty) {
  SerialDevices devices(layout(), directory(), {});
  const int host = ::open(devices.pathOf("uwb_5722").c_str(), O_RDWR | O_NOCTTY);
  ASSERT_GE(host, 0);
  ASSERT_EQ(::write(host, "\r\r", 2), 2);
  EXPECT_NE(readUntil(host, devices, "dwm> ").find("dwm> "), std::string::npos);
  ASSERT_EQ(::write(host, "si\r", 3), 3);
  EXPECT_NE(readUntil(host, devices, "label=DW5722").find("label=DW5722"), std::string::npos);
  ASSERT_EQ(::write(host, "lec\r", 4), 4);
  readUntil(host, devices, "lec\r\n");
  StepEvents events;
  events.twr.push_back(TwrEvent{0.2, 0, 4.321});
  devices.write(events);
  EXPECT_NE(readUntil(host, devices, "\r\n").find("DIST,1,AN0,DA12,0.00,0.00,0.00,4.32\r\n"),
            std::string::npos);
  ::close(host);
}

TEST(SerialDevices, AoaEventsAreUudfLinesInDeviceConventions) {
  SerialDevices devices(layout(), directory(), {});
  const int host = ::open(devices.pathOf("aoa_front").c_str(), O_RDWR | O_NOCTTY);
  ASSERT_GE(host, 0);
  StepEvents events;
  AoaSample sample;
  sample.azimuth = 0.349066;  // 20 deg counter-clockwise = -20 on the device
  sample.elevation = 0.0;
  sample.rssi = -48.4;
  sample.rssi_second = -50.6;
  events.aoa.push_back(AoaEvent{15.869, 0, sample});
  devices.write(events);
  EXPECT_EQ(readUntil(host, devices, "\r\n"),
            "+UUDF:CCF9578E0D8A,-48,-20,0,-51,37,\"front\",\"\",15869\r\n");
  ::close(host);
}

TEST(SerialDevices, UnplugFaultRemovesAndRestoresTheDevice) {
  SerialDevices devices(layout(), directory(), {{"uwb_5722", 1.0, 0.5}});
  const std::string path = devices.pathOf("uwb_5722");
  devices.service(0.5);
  EXPECT_EQ(::access(path.c_str(), F_OK), 0);
  devices.service(1.2);
  EXPECT_NE(::access(path.c_str(), F_OK), 0);
  devices.service(1.6);
  EXPECT_EQ(::access(path.c_str(), F_OK), 0);
}

TEST(SerialDevices, FaultOnAnUnknownDeviceIsAParamError) {
  try {
    SerialDevices devices(layout(), directory(), {{"uwb_9999", 1.0, 0.5}});
    FAIL();
  } catch (const ParamError& e) {
    EXPECT_EQ(e.name(), "~unplug[0].device");
  }
}

}  // namespace
}  // namespace sim
}  // namespace radio_follow
