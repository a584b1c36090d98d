// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/sim/dwm_shell_emulator.hpp"

#include <gtest/gtest.h>

namespace radio_follow {
namespace sim {
namespace {

const std::vector<DwmAnchorRange> kRanges{{"DA12", Eigen::Vector3d(0, 0, 0), 3.21}};

TEST(DwmShellEmulator, OpensTheShellOnTwoCarriageReturnsOnly) {
  DwmShellEmulator dwm("5722");
  EXPECT_EQ(dwm.receive("hello\r", 0.0), "");
  EXPECT_EQ(dwm.mode(), DwmShellEmulator::Mode::kApi);
  EXPECT_EQ(dwm.receive("\r", 2.0), "");  // too late after the first CR: still API mode
  const std::string answer = dwm.receive("\r", 2.5);
  EXPECT_EQ(dwm.mode(), DwmShellEmulator::Mode::kShell);
  EXPECT_NE(answer.find("DWM1001 TWR"), std::string::npos);
  EXPECT_EQ(answer.substr(answer.size() - 5), "dwm> ");
}

TEST(DwmShellEmulator, SiReportsTheLabelAndStreamsToggle) {
  DwmShellEmulator dwm("5722");
  dwm.receive("\r\r", 0.0);
  const std::string si = dwm.receive("si\r", 0.1);
  EXPECT_EQ(si.rfind("si\r\n", 0), 0u);  // echoed
  EXPECT_NE(si.find("label=DW5722\r\n"), std::string::npos);
  EXPECT_NE(si.find("INF]"), std::string::npos);

  EXPECT_EQ(dwm.epoch(kRanges, std::nullopt, 0.2), "");
  dwm.receive("lec\r", 0.3);
  EXPECT_EQ(dwm.mode(), DwmShellEmulator::Mode::kStreaming);
  EXPECT_EQ(dwm.epoch(kRanges, std::nullopt, 0.4), "DIST,1,AN0,DA12,0.00,0.00,0.00,3.21\r\n");
  // Streaming does not echo; the same command stops it.
  EXPECT_EQ(dwm.receive("lec\r", 0.5), "\r\ndwm> ");
  EXPECT_EQ(dwm.epoch(kRanges, std::nullopt, 0.6), "");

  dwm.receive("les\r", 0.7);
  EXPECT_EQ(dwm.epoch(kRanges, std::nullopt, 0.8), "DA12[0.00,0.00,0.00]=3.21\r\n");
  dwm.receive("\r", 0.9);
  dwm.receive("quit\r", 1.0);
  EXPECT_EQ(dwm.mode(), DwmShellEmulator::Mode::kApi);
}

TEST(DwmShellEmulator, LepPrintsOnlyWithAPosition) {
  DwmShellEmulator dwm("5722");
  dwm.receive("\r\r", 0.0);
  dwm.receive("lep\r", 0.1);
  EXPECT_EQ(dwm.epoch(kRanges, std::nullopt, 0.2), "");
  DwmPosition p{Eigen::Vector3d(1.5, -2.25, 0.5), 87, 0};
  EXPECT_EQ(dwm.epoch(kRanges, p, 0.3), "POS,1.50,-2.25,0.50,87\r\n");
}

TEST(DwmShellEmulator, UnknownCommandsAnswerAndKeepTheShell) {
  DwmShellEmulator dwm("5722");
  dwm.receive("\r\r", 0.0);
  EXPECT_NE(dwm.receive("xyz\r", 0.1).find("Unknown command"), std::string::npos);
  EXPECT_EQ(dwm.mode(), DwmShellEmulator::Mode::kShell);
}

}  // namespace
}  // namespace sim
}  // namespace radio_follow
