// SPDX-License-Identifier: BSD-3-Clause
#pragma once

// Behaviour of a DWM1001 tag on its UART for PtyDevice: two carriage returns enter the
// shell (banner + prompt), commands are echoed, `si` prints a system-info block with
// `label=DW5722`, `lec`/`les` toggle a stream of lines, Enter stops a stream, `quit`
// returns to the binary API. Streams include an occasional cut line, as a noisy link
// would deliver, which the driver must reject.

#include <string>

#include "pty_device.hpp"

namespace radio_follow::test {

class FakeDwm1001 {
 public:
  static constexpr const char* kLec =
      "DIST,4,AN0,1151,5.00,8.00,2.25,6.48,AN1,0CA8,0.00,8.00,2.25,6.51,AN2,111C,5.00,0.00,"
      "2.25,3.18,AN3,1150,0.00,0.00,2.25,3.16,POS,2.57,1.98,1.68,100";
  static constexpr const char* kLes =
      "1151[5.00,8.00,2.25]=6.48 0CA8[0.00,8.00,2.25]=6.51 111C[5.00,0.00,2.25]=3.18 "
      "1150[0.00,0.00,2.25]=3.16 le_us=2576 est[2.57,1.98,1.68,100]";

  /// A behaviour bound to this object (which must outlive the PtyDevice).
  PtyDevice::Behaviour behaviour() {
    PtyDevice::Behaviour b;
    b.on_input = [this](const std::string& input) { return onInput(input); };
    b.periodic = [this] { return periodic(); };
    b.period = std::chrono::milliseconds(50);
    return b;
  }

  /// Back to power-on state (binary API mode, no stream), as after a replug.
  void powerCycle() {
    shell_ = false;
    stream_.clear();
    line_.clear();
    returns_ = 0;
  }

 private:
  std::string onInput(const std::string& input) {
    std::string reply;
    for (char c : input) {
      if (!shell_) {
        returns_ = c == '\r' ? returns_ + 1 : 0;
        if (returns_ >= 2) {
          shell_ = true;
          reply +=
              "DWM1001 TWR Real Time Location System\r\n\r\nCopyright :  2016-2019 LEAPS and "
              "Decawave\r\nLicense   :  Please visit https://decawave.com/dwm1001_license\r\n"
              "Compiled  :  Mar 25 2019 11:34:37\r\n\r\nHelp      :  ? or help\r\n\r\ndwm> ";
        }
        continue;
      }
      if (c != '\r') {
        line_ += c;
        continue;
      }
      reply += line_ + "\r\n";
      if (!stream_.empty()) {
        stream_.clear();  // any Enter stops a running stream
      } else if (line_ == "si") {
        reply +=
            "[000007.930 INF] sys: fw2 fw_ver=x01030001 cfg_ver=x00010700\r\n"
            "[000007.930 INF] uwb0: panid=x0001 addr=xDECA4BF6A3395722\r\n"
            "[000007.940 INF] mode: tn (act,twr,np,le)\r\n"
            "[000007.940 INF] uwbmac: connected prov (1)\r\n"
            "[000007.950 INF] cfg: sync=0 fwup=0 ble=1 leds=1 le=1 lp=0 stat_det=1 (sens=0) "
            "mode=0 upd_rate_norm=10 upd_rate_stat=10 label=DW5722\r\n"
            "[000007.950 INF] enc: off\r\n"
            "[000007.960 INF] ble: addr=F8:8E:79:F2:CF:DA\r\n";
      } else if (line_ == "lec" || line_ == "les") {
        stream_ = line_;
      } else if (line_ == "quit") {
        shell_ = false;
      }
      line_.clear();
      if (shell_ && stream_.empty()) {
        reply += "dwm> ";
      }
    }
    return reply;
  }

  std::string periodic() {
    if (stream_.empty()) {
      return {};
    }
    const std::string line = stream_ == "lec" ? kLec : kLes;
    ++count_;
    if (count_ % 10 == 0) {
      return line.substr(0, line.size() / 2) + "\r\n";  // a cut line
    }
    return line + "\r\n";
  }

  bool shell_ = false;
  int returns_ = 0;
  std::string line_;
  std::string stream_;
  unsigned count_ = 0;
};

}  // namespace radio_follow::test
