// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/drivers/dwm1001_shell.hpp"

#include <gtest/gtest.h>

namespace radio_follow::drivers {
namespace {

using State = Dwm1001Shell::State;

TEST(Dwm1001Shell, FullDialogue) {
  Dwm1001Shell shell("lec", 2.0);
  EXPECT_EQ(shell.state(), State::kDisconnected);
  EXPECT_EQ(shell.onConnected(0.0), "\r\r");
  EXPECT_EQ(shell.onLine("DWM1001 TWR Real Time Location System", 0.1), "");
  EXPECT_EQ(shell.onPending("dwm", 0.2), "");
  EXPECT_EQ(shell.onPending("dwm> ", 0.2), "si\r");
  EXPECT_EQ(shell.state(), State::kWaitLabel);
  EXPECT_EQ(shell.onPending("dwm> ", 0.3), "");  // the same prompt seen again
  EXPECT_EQ(shell.onLine("dwm> si", 0.3), "");
  EXPECT_EQ(shell.onLine("[000007.930 INF] sys: fw2 fw_ver=x01030001 cfg_ver=x00010700", 0.3), "");
  EXPECT_EQ(shell.onLine("[000008.340 INF] cfg: sync=0 fwup=0 ble=1 leds=1 le=1 lp=0 "
                         "stat_det=1 (sens=0) mode=0 upd_rate_norm=10 upd_rate_stat=10 "
                         "label=DW5722",
                         0.4),
            "");
  EXPECT_EQ(shell.tagId(), "5722");
  EXPECT_EQ(shell.state(), State::kWaitPromptAfterInfo);
  EXPECT_EQ(shell.onLine("[000008.350 INF] enc: off", 0.4), "");
  EXPECT_EQ(shell.onPending("dwm> ", 0.5), "lec\r");
  EXPECT_EQ(shell.state(), State::kStreaming);
  EXPECT_EQ(shell.onTick(100.0), "");  // streaming never times out here
  EXPECT_EQ(shell.stopText(), "lec\rquit\r");
}

TEST(Dwm1001Shell, PromptAsCompleteLine) {
  Dwm1001Shell shell("les", 2.0);
  shell.onConnected(0.0);
  EXPECT_EQ(shell.onLine("dwm> ", 0.1), "si\r");
  EXPECT_EQ(shell.onLine("dwm> si", 0.1), "");
}

TEST(Dwm1001Shell, SilentModuleRestartsDialogue) {
  Dwm1001Shell shell("les", 2.0);
  shell.onConnected(0.0);
  EXPECT_EQ(shell.onTick(1.9), "");
  EXPECT_EQ(shell.onTick(2.1), "\r\r");
  EXPECT_EQ(shell.restarts(), 1u);
  EXPECT_EQ(shell.onPending("dwm> ", 2.5), "si\r");
  EXPECT_EQ(shell.onTick(4.6), "\r\r");  // no label either
  EXPECT_EQ(shell.state(), State::kWaitPrompt);
}

TEST(Dwm1001Shell, SilentStreamRestartsDialogue) {
  Dwm1001Shell shell("lec", 2.0);
  EXPECT_EQ(shell.onSilence(0.0), "");  // not streaming yet: the step timeout applies
  shell.onConnected(0.0);
  shell.onLine("dwm> ", 0.1);
  shell.onLine("[000008.340 INF] cfg: label=DW5722", 0.2);
  ASSERT_EQ(shell.onLine("dwm> ", 0.3), "lec\r");
  EXPECT_EQ(shell.onSilence(5.0), "\r\r");
  EXPECT_EQ(shell.state(), State::kWaitPrompt);
  EXPECT_EQ(shell.restarts(), 1u);
  EXPECT_EQ(shell.onSilence(5.5), "");  // already restarting
}

TEST(Dwm1001Shell, DisconnectStopsDialogueAndReconnectStartsOver) {
  Dwm1001Shell shell("lec", 2.0);
  shell.onConnected(0.0);
  shell.onDisconnected();
  EXPECT_EQ(shell.onTick(10.0), "");
  EXPECT_EQ(shell.onPending("dwm> ", 10.0), "");
  EXPECT_EQ(shell.stopText(), "quit\r");
  EXPECT_EQ(shell.onConnected(11.0), "\r\r");
  EXPECT_EQ(shell.state(), State::kWaitPrompt);
}

TEST(Dwm1001Shell, ParseLabel) {
  EXPECT_EQ(Dwm1001Shell::parseLabel("x label=DW5722 y"), "5722");
  EXPECT_EQ(Dwm1001Shell::parseLabel("label=0CA8"), "0CA8");
  EXPECT_EQ(Dwm1001Shell::parseLabel("no label here"), "");
}

}  // namespace
}  // namespace radio_follow::drivers
