// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

namespace radio_follow::drivers {

/// One u-connectLocate angle-of-arrival event, in the device's own conventions except
/// that angles are converted to radians.
struct UudfEvent {
  std::string tag_id;        ///< 12 hex digits, upper case
  std::string anchor_id;     ///< quoted anchor field, may be empty
  std::string user_string;   ///< quoted user-defined field, may be empty or hold commas
  double rssi = 0.0;         ///< first polarisation, dBm
  double azimuth = 0.0;      ///< rad, the device's sign convention (clockwise positive)
  double elevation = 0.0;    ///< rad
  double rssi_second = 0.0;  ///< second polarisation, dBm; NaN when the field is reserved
  std::uint8_t channel = 0;
  std::uint32_t timestamp_ms = 0;
  std::int64_t event_counter = -1;  ///< -1 when the firmware does not send it
};

/// What a line turned out to be.
enum class UudfLineStatus {
  kEvent,        ///< `out` holds a decoded event
  kIgnored,      ///< blank, `OK`, AT echo, `+UUDFP:` advertising data, other URCs
  kMalformed,    ///< starts like `+UUDF:` but does not decode (cut, merged, bad field)
  kImplausible,  ///< decodes, but an RSSI or angle is outside what the board can report
                 ///< (plausibility.hpp): a corrupted line or a faulty device
};

/// Short name of a status, for logs and diagnostics.
const char* toString(UudfLineStatus status);

/// Decodes `+UUDF:<tag>,<rssi>,<azimuth>,<elevation>,<rssi2 or reserved>,<channel>,
/// "<anchor>","<user string>",<timestamp_ms>[,<event counter>]` (degrees in, radians
/// out). Quoted fields end at the next quote, so they may contain commas. RSSI must be
/// in [-127, 0] dBm (the second one may be the reserved 0), azimuth and elevation in
/// [-90, 90] deg, else kImplausible. A rejected line leaves `out` unspecified. `out` is
/// reused to avoid allocations.
UudfLineStatus decodeUudfLine(std::string_view line, UudfEvent& out);

}  // namespace radio_follow::drivers
