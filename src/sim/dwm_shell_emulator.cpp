// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/sim/dwm_shell_emulator.hpp"

#include <cstdio>

namespace radio_follow {
namespace sim {
namespace {

constexpr const char* kPrompt = "dwm> ";
/// Two CRs closer than this (s) open the shell, as the firmware requires.
constexpr double kDoubleCrWindow = 1.0;

std::string banner() {
  return "\r\nDWM1001 TWR Real Time Location System\r\n\r\n"
         "Copyright :  2016-2019 LEAPS and Decawave\r\n"
         "License   :  Please visit https://decawave.com/dwm1001_license\r\n"
         "Compiled  :  Mar 29 2019 09:16:31\r\n\r\n"
         "Help      :  ? or help\r\n\r\n";
}

}  // namespace

DwmShellEmulator::DwmShellEmulator(std::string module_id) : module_id_(std::move(module_id)) {}

std::string DwmShellEmulator::infoLines(double t) const {
  char stamp[32];
  std::snprintf(stamp, sizeof(stamp), "[%010.3f INF] ", t);
  const std::string s = stamp;
  return s + "sys: fw2 fw_ver=x01030001 cfg_ver=x00010700\r\n" + s +
         "uwb0: panid=x0001 addr=xDECA3A5A2A6B" + module_id_ + "\r\n" + s +
         "mode: tn (act,twr,np,nole)\r\n" + s + "uwbmac: connected prov (x0001)\r\n" + s +
         "cfg: sync=0 fwup=0 ble=1 leds=1 le=1 lp=0 stat_det=1 (sens=0) mode=0 upd_rate_norm=1 "
         "upd_rate_stat=120 label=DW" +
         module_id_ + "\r\n" + s + "enc: off\r\n";
}

std::string DwmShellEmulator::command(const std::string& line, double t) {
  if (mode_ == Mode::kStreaming) {
    // Any command line (the same one, or a bare Enter) stops the stream.
    mode_ = Mode::kShell;
    stream_ = Stream::kNone;
    return kPrompt;
  }
  if (line.empty()) {
    return kPrompt;
  }
  if (line == "si") {
    return infoLines(t) + kPrompt;
  }
  if (line == "lec" || line == "les" || line == "lep") {
    mode_ = Mode::kStreaming;
    stream_ = line == "lec" ? Stream::kLec : line == "les" ? Stream::kLes : Stream::kLep;
    return "";
  }
  if (line == "quit") {
    mode_ = Mode::kApi;
    return "";
  }
  return "Unknown command: " + line + "\r\n" + kPrompt;
}

std::string DwmShellEmulator::receive(const std::string& bytes, double t) {
  std::string out;
  for (char c : bytes) {
    if (mode_ == Mode::kApi) {
      if (c == '\r') {
        if (t - last_api_cr_ <= kDoubleCrWindow) {
          mode_ = Mode::kShell;
          input_.clear();
          out += banner() + kPrompt;
        }
        last_api_cr_ = t;
      }
      continue;  // API mode speaks TLV, not text: everything else is ignored here
    }
    if (c == '\r' || c == '\n') {
      if (c == '\n' && input_.empty()) {
        continue;  // the LF of a CRLF pair
      }
      out += "\r\n" + command(input_, t);
      input_.clear();
    } else {
      input_ += c;
      if (mode_ == Mode::kShell) {
        out += c;  // echo
      }
    }
  }
  return out;
}

std::string DwmShellEmulator::epoch(const std::vector<DwmAnchorRange>& ranges,
                                    const std::optional<DwmPosition>& position, double) {
  switch (stream_) {
    case Stream::kLec:
      return formatLecLine(ranges, position) + "\r\n";
    case Stream::kLes:
      return formatLesLine(ranges, position) + "\r\n";
    case Stream::kLep:
      if (position) {
        char buffer[96];
        std::snprintf(buffer, sizeof(buffer), "POS,%.2f,%.2f,%.2f,%d\r\n", position->position.x(),
                      position->position.y(), position->position.z(), position->quality);
        return buffer;
      }
      return "";
    case Stream::kNone:
      break;
  }
  return "";
}

}  // namespace sim
}  // namespace radio_follow
