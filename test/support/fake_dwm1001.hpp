// SPDX-License-Identifier: BSD-3-Clause
#pragma once

// A DWM1001 tag on its UART for PtyDevice: the simulator's shell emulator
// (sim::DwmShellEmulator: two carriage returns open the shell, echo, `si` with
// `label=DW5722`, `lec`/`les` streams, Enter stops, `quit`) streaming a fixed epoch of four
// anchors every 50 ms, with every tenth line cut in half as a noisy link would deliver it,
// which the driver must reject.

#include <chrono>
#include <string>
#include <vector>

#include "pty_device.hpp"
#include "radio_follow/sim/dwm_shell_emulator.hpp"

namespace radio_follow::test {

class FakeDwm1001 {
 public:
  /// A behaviour bound to this object (which must outlive the PtyDevice).
  PtyDevice::Behaviour behaviour() {
    PtyDevice::Behaviour b;
    b.on_input = [this](const std::string& input) { return shell_.receive(input, now()); };
    b.periodic = [this] { return periodic(); };
    b.period = std::chrono::milliseconds(50);
    return b;
  }

  /// Back to power-on state (binary API mode, no stream), as after a replug.
  void powerCycle() { shell_ = sim::DwmShellEmulator("5722"); }

 private:
  static double now() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch())
        .count();
  }

  std::string periodic() {
    // The thesis's example epoch (Appendix A.1).
    static const std::vector<sim::DwmAnchorRange> kRanges{
        {"1151", {5.0, 8.0, 2.25}, 6.48},
        {"0CA8", {0.0, 8.0, 2.25}, 6.51},
        {"111C", {5.0, 0.0, 2.25}, 3.18},
        {"1150", {0.0, 0.0, 2.25}, 3.16}};
    static const sim::DwmPosition kPosition{{2.57, 1.98, 1.68}, 100, 2576};
    const std::string line = shell_.epoch(kRanges, kPosition, now());
    if (line.empty()) {
      return line;
    }
    if (++count_ % 10 == 0) {
      return line.substr(0, line.size() / 2) + "\r\n";  // a cut line
    }
    return line;
  }

  sim::DwmShellEmulator shell_{"5722"};
  unsigned count_ = 0;
};

}  // namespace radio_follow::test
