// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>
#include <vector>

#include "radio_follow/sim/protocol_lines.hpp"

namespace radio_follow {
namespace sim {

/// The UART side of a DWM1001 module in tag mode, as far as a driver sees it: it starts
/// in (binary) API mode and ignores text; two carriage returns within a second open the
/// shell (banner and `dwm> ` prompt); the shell echoes what it receives; `si` prints the
/// system information `[INF]` lines including `label=DW<id>`; `lec`, `les`, `lep` start
/// the position stream in that format and the same command (or a bare Enter) stops it;
/// `quit` returns to API mode. Pure: bytes in, bytes out; the caller moves them.
class DwmShellEmulator {
 public:
  enum class Mode { kApi, kShell, kStreaming };
  enum class Stream { kNone, kLec, kLes, kLep };

  /// `module_id`: 4 hex digits reported in the `si` label (e.g. "5722").
  explicit DwmShellEmulator(std::string module_id);

  /// Consumes bytes the host wrote at time `t` (s) and returns the module's answer.
  std::string receive(const std::string& bytes, double t);

  /// One measurement epoch at time `t`: returns the stream line (with "\r\n") while
  /// streaming, otherwise nothing.
  std::string epoch(const std::vector<DwmAnchorRange>& ranges,
                    const std::optional<DwmPosition>& position, double t);

  Mode mode() const { return mode_; }
  Stream stream() const { return stream_; }

 private:
  std::string command(const std::string& line, double t);
  std::string infoLines(double t) const;

  std::string module_id_;
  Mode mode_ = Mode::kApi;
  Stream stream_ = Stream::kNone;
  std::string input_;          ///< shell input up to the next carriage return
  double last_api_cr_ = -1e9;  ///< time of the last CR received in API mode
};

}  // namespace sim
}  // namespace radio_follow
