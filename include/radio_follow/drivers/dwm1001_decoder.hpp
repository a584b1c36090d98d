// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace radio_follow::drivers {

/// The DWM1001 shell's prompt, at the start of a line.
constexpr std::string_view kDwmPrompt = "dwm>";

/// One anchor's entry in a DWM1001 tag output line.
struct DwmAnchorRange {
  std::string id;  ///< 4 hex digits, upper case, e.g. "0CA8"
  double x = 0.0;  ///< anchor position from the anchor's own configuration, m
  double y = 0.0;
  double z = 0.0;
  double range = 0.0;  ///< measured tag-anchor distance, m (uncorrected)
};

/// The position the module computed itself (`est[...]` / `POS,...`).
struct DwmPosition {
  double x = 0.0;  ///< m, UWB network frame
  double y = 0.0;
  double z = 0.0;
  std::uint8_t quality = 0;  ///< 0..100
};

/// Everything one output line reported.
struct DwmMeasurement {
  std::vector<DwmAnchorRange> ranges;
  bool has_position = false;
  DwmPosition position;
  std::uint32_t computation_time_us = 0;  ///< les `le_us`; 0 when absent

  void clear() {
    ranges.clear();
    has_position = false;
    computation_time_us = 0;
  }
};

/// What a line turned out to be.
enum class DwmLineStatus {
  kMeasurement,    ///< `out` holds ranges and/or a position
  kIgnored,        ///< blank, prompt/command echo, banner, `[INF]` log line, `DIST,0`
  kMalformed,      ///< looks like data but a field does not parse (cut or merged line)
  kCountMismatch,  ///< lec: DIST count differs from the anchors listed
  kImplausible,    ///< decodes, but a range, coordinate or quality is outside the physical
                   ///< limits of plausibility.hpp (a corrupted or faulty device)
};

/// Short name of a status, for logs and diagnostics.
const char* toString(DwmLineStatus status);

/// Decodes one line of DWM1001 UART shell output: `les`
/// (`1151[5.00,8.00,2.25]=6.48 ... le_us=2576 est[2.57,1.98,1.68,100]`), `lec`
/// (`DIST,4,AN0,1151,5.00,8.00,2.25,6.48,...,POS,2.57,1.98,1.68,100`) or `lep`
/// (`POS,2.57,1.98,1.68,100`). A leading shell prompt is skipped. A line that is
/// anything but fully consistent is rejected whole: `out` is then unspecified and must
/// not be published. So is a well-formed line with a value no device can report (a range
/// outside [0, 300] m, a coordinate beyond 10 km, a quality outside 0..100):
/// kImplausible. `out` is reused to avoid allocations at high line rates.
DwmLineStatus decodeDwmLine(std::string_view line, DwmMeasurement& out);

}  // namespace radio_follow::drivers
