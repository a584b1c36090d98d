// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/drivers/uudf_decoder.hpp"

#include <limits>

#include "radio_follow/common/angles.hpp"
#include "radio_follow/common/plausibility.hpp"
#include "radio_follow/drivers/text_fields.hpp"

namespace radio_follow::drivers {
namespace {

constexpr std::string_view kEventPrefix = "+UUDF:";

// Reads `"text"` followed by ',' from the front of `rest` into `out`.
bool takeQuoted(std::string_view& rest, std::string& out) {
  if (rest.empty() || rest.front() != '"') {
    return false;
  }
  const std::size_t close = rest.find('"', 1);
  if (close == std::string_view::npos || close + 1 >= rest.size() || rest[close + 1] != ',') {
    return false;
  }
  out.assign(rest.data() + 1, close - 1);
  rest.remove_prefix(close + 2);
  return true;
}

bool takePlain(std::string_view& rest, std::string_view& field) {
  const std::size_t comma = rest.find(',');
  if (comma == std::string_view::npos) {
    return false;
  }
  field = rest.substr(0, comma);
  rest.remove_prefix(comma + 1);
  return true;
}

// Whether the decoded values that make a bearing are ones the board can report
// (plausibility.hpp): the angles, in degrees as sent, and the first RSSI. The fifth field
// decides nothing (secondRssi).
bool plausibleValues(const UudfEvent& e, double azimuth_deg, double elevation_deg) {
  return plausibleRssi(e.rssi) && plausibleAoaAngleDeg(azimuth_deg) &&
         plausibleAoaAngleDeg(elevation_deg);
}

// The fifth field: reserved (sent as 0) on older u-connectLocate firmware, the second
// polarisation's RSSI on newer. Real boards send small positive values in it too (6 has
// been seen), so it never decides whether the bearing is published: NaN unless it holds
// a plausible, negative RSSI.
double secondRssi(std::string_view field) {
  double value = 0.0;
  if (field.empty() || !parseFiniteDouble(field, value) || !(value < 0.0) ||
      !plausibleRssi(value)) {
    return std::numeric_limits<double>::quiet_NaN();
  }
  return value;
}

}  // namespace

const char* toString(UudfLineStatus status) {
  switch (status) {
    case UudfLineStatus::kEvent:
      return "event";
    case UudfLineStatus::kIgnored:
      return "ignored";
    case UudfLineStatus::kMalformed:
      return "malformed";
    case UudfLineStatus::kImplausible:
      return "implausible value";
  }
  return "unknown";
}

UudfLineStatus decodeUudfLine(std::string_view line, UudfEvent& out) {
  while (!line.empty() && line.back() == ' ') {
    line.remove_suffix(1);
  }
  if (!startsWith(line, "+UUDF")) {
    // OK, AT echoes, +STARTUP and other responses carry no measurement. A cut line
    // that lost its start cannot be told from noise either, so it lands here too.
    return UudfLineStatus::kIgnored;
  }
  if (startsWith(line, "+UUDFP:")) {
    return UudfLineStatus::kIgnored;  // periodic advertising payload, not an angle
  }
  if (!startsWith(line, kEventPrefix)) {
    return UudfLineStatus::kMalformed;
  }
  std::string_view rest = line.substr(kEventPrefix.size());
  std::string_view f;
  double azimuth_deg = 0.0;
  double elevation_deg = 0.0;
  unsigned channel = 0;
  if (!takePlain(rest, f) || !isHexId(f, 12)) {
    return UudfLineStatus::kMalformed;
  }
  assignUpperHex(f, out.tag_id);
  if (!takePlain(rest, f) || !parseFiniteDouble(f, out.rssi) || !takePlain(rest, f) ||
      !parseFiniteDouble(f, azimuth_deg) || !takePlain(rest, f) ||
      !parseFiniteDouble(f, elevation_deg) || !takePlain(rest, f)) {
    return UudfLineStatus::kMalformed;
  }
  out.rssi_second = secondRssi(f);
  if (!takePlain(rest, f) || !parseInteger(f, channel) || channel > 39 ||
      !takeQuoted(rest, out.anchor_id) || !takeQuoted(rest, out.user_string)) {
    return UudfLineStatus::kMalformed;
  }
  out.azimuth = deg2rad(azimuth_deg);
  out.elevation = deg2rad(elevation_deg);
  out.channel = static_cast<std::uint8_t>(channel);
  FieldCursor tail(rest, ',');
  if (!tail.next(f) || !parseInteger(f, out.timestamp_ms)) {
    return UudfLineStatus::kMalformed;
  }
  out.event_counter = -1;
  if (tail.next(f) && (!parseInteger(f, out.event_counter) || out.event_counter < 0)) {
    return UudfLineStatus::kMalformed;
  }
  if (!tail.done()) {
    return UudfLineStatus::kMalformed;
  }
  // Only a line that decoded whole is judged on its values: a cut line stays malformed.
  return plausibleValues(out, azimuth_deg, elevation_deg) ? UudfLineStatus::kEvent
                                                          : UudfLineStatus::kImplausible;
}

}  // namespace radio_follow::drivers
