// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/drivers/dwm1001_decoder.hpp"

#include "radio_follow/common/plausibility.hpp"
#include "radio_follow/drivers/text_fields.hpp"

namespace radio_follow::drivers {
namespace {

// An integer is a well-formed quality field; one outside 0..100 is a device fault, which
// sets `implausible` (the line is then rejected as such, not as malformed).
bool parseQuality(std::string_view field, std::uint8_t& out, bool& implausible) {
  long value = 0;
  if (!parseInteger(field, value)) {
    return false;
  }
  if (!plausibleQuality(value)) {
    implausible = true;
    value = 0;
  }
  out = static_cast<std::uint8_t>(value);
  return true;
}

// Parses "x,y,z" (or "x,y,z,q" when `quality` is given) as found inside les brackets.
bool parseBracketNumbers(std::string_view inner, double& x, double& y, double& z,
                         std::uint8_t* quality, bool& implausible) {
  FieldCursor cursor(inner, ',');
  std::string_view f;
  if (!cursor.next(f) || !parseFiniteDouble(f, x) || !cursor.next(f) || !parseFiniteDouble(f, y) ||
      !cursor.next(f) || !parseFiniteDouble(f, z)) {
    return false;
  }
  if (quality != nullptr && (!cursor.next(f) || !parseQuality(f, *quality, implausible))) {
    return false;
  }
  return cursor.done();
}

// "ID[x,y,z]=range". A negative range is well-formed but implausible (checked later).
bool parseLesAnchor(std::string_view token, DwmAnchorRange& anchor, bool& implausible) {
  const std::size_t open = token.find('[');
  const std::size_t close = token.find("]=");
  if (open != 4 || close == std::string_view::npos || close < open ||
      !isHexId(token.substr(0, 4), 4)) {
    return false;
  }
  assignUpperHex(token.substr(0, 4), anchor.id);
  return parseBracketNumbers(token.substr(open + 1, close - open - 1), anchor.x, anchor.y, anchor.z,
                             nullptr, implausible) &&
         parseFiniteDouble(token.substr(close + 2), anchor.range);
}

DwmLineStatus decodeLes(std::string_view line, DwmMeasurement& out, bool& implausible) {
  FieldCursor tokens(line, ' ');
  std::string_view token;
  bool seen_le_us = false;
  while (tokens.next(token)) {
    if (token.empty()) {
      continue;  // the firmware pads with a trailing space
    }
    if (out.has_position) {
      return DwmLineStatus::kMalformed;  // nothing may follow est[...]
    }
    if (startsWith(token, "le_us=")) {
      if (seen_le_us || !parseInteger(token.substr(6), out.computation_time_us)) {
        return DwmLineStatus::kMalformed;
      }
      seen_le_us = true;
    } else if (startsWith(token, "est[")) {
      if (token.back() != ']' ||
          !parseBracketNumbers(token.substr(4, token.size() - 5), out.position.x, out.position.y,
                               out.position.z, &out.position.quality, implausible)) {
        return DwmLineStatus::kMalformed;
      }
      out.has_position = true;
    } else {
      if (seen_le_us) {
        return DwmLineStatus::kMalformed;  // anchors come first
      }
      out.ranges.emplace_back();
      if (!parseLesAnchor(token, out.ranges.back(), implausible)) {
        return DwmLineStatus::kMalformed;
      }
    }
  }
  if (out.ranges.empty() && !out.has_position) {
    return DwmLineStatus::kMalformed;
  }
  return DwmLineStatus::kMeasurement;
}

bool parsePosFields(FieldCursor& cursor, DwmPosition& position, bool& implausible) {
  std::string_view f;
  return cursor.next(f) && parseFiniteDouble(f, position.x) && cursor.next(f) &&
         parseFiniteDouble(f, position.y) && cursor.next(f) && parseFiniteDouble(f, position.z) &&
         cursor.next(f) && parseQuality(f, position.quality, implausible) && cursor.done();
}

// "AN<k>" with k == expected index.
bool isAnchorLabel(std::string_view field, std::size_t index) {
  std::size_t k = 0;
  return startsWith(field, "AN") && parseInteger(field.substr(2), k) && k == index;
}

DwmLineStatus decodeLec(std::string_view line, DwmMeasurement& out, bool& implausible) {
  FieldCursor cursor(line, ',');
  std::string_view f;
  cursor.next(f);  // "DIST"
  std::size_t count = 0;
  if (!cursor.next(f) || !parseInteger(f, count)) {
    return DwmLineStatus::kMalformed;
  }
  while (cursor.next(f)) {
    if (f == "POS") {
      if (!parsePosFields(cursor, out.position, implausible)) {
        return DwmLineStatus::kMalformed;
      }
      out.has_position = true;
      break;
    }
    if (!isAnchorLabel(f, out.ranges.size())) {
      // A label out of sequence: another line's fields ran into this one, or the
      // count itself was cut.
      return out.ranges.size() >= count ? DwmLineStatus::kCountMismatch : DwmLineStatus::kMalformed;
    }
    out.ranges.emplace_back();
    DwmAnchorRange& a = out.ranges.back();
    std::string_view id;
    if (!cursor.next(id) || !isHexId(id, 4) || !cursor.next(f) || !parseFiniteDouble(f, a.x) ||
        !cursor.next(f) || !parseFiniteDouble(f, a.y) || !cursor.next(f) ||
        !parseFiniteDouble(f, a.z) || !cursor.next(f) || !parseFiniteDouble(f, a.range)) {
      return DwmLineStatus::kMalformed;
    }
    assignUpperHex(id, a.id);
  }
  if (out.ranges.size() != count) {
    return DwmLineStatus::kCountMismatch;
  }
  // "DIST,0": consistent, but no anchor in range and no position: nothing to publish.
  // (Found by the fuzzer: it is not a measurement, and not an error either.)
  return out.ranges.empty() && !out.has_position ? DwmLineStatus::kIgnored
                                                 : DwmLineStatus::kMeasurement;
}

// Whether a line that is none of the known outputs still looks like a piece of one
// (a fragment after a dropout) rather than text such as the banner or `Help : ?`.
bool looksLikeData(std::string_view line) {
  const char c = line.front();
  return (c >= '0' && c <= '9') || c == '-' || c == '.' || c == ',' || c == '[' || c == ']' ||
         c == '=' || startsWith(line, "AN") || startsWith(line, "DIST") ||
         startsWith(line, "POS") || startsWith(line, "le_us") || startsWith(line, "est") ||
         line.find("]=") != std::string_view::npos ||
         (line.size() > 4 && line[4] == '[' && isHexId(line.substr(0, 4), 4));
}

// Every range and coordinate within the physical limits of plausibility.hpp.
bool plausibleValues(const DwmMeasurement& m) {
  for (const DwmAnchorRange& a : m.ranges) {
    if (!plausibleRange(a.range) || !plausibleCoordinate(a.x) || !plausibleCoordinate(a.y) ||
        !plausibleCoordinate(a.z)) {
      return false;
    }
  }
  return !m.has_position ||
         (plausibleCoordinate(m.position.x) && plausibleCoordinate(m.position.y) &&
          plausibleCoordinate(m.position.z));
}

// A line that decoded whole is still rejected when a value is physically impossible.
DwmLineStatus checkValues(DwmLineStatus status, const DwmMeasurement& m, bool implausible) {
  if (status != DwmLineStatus::kMeasurement) {
    return status;
  }
  return implausible || !plausibleValues(m) ? DwmLineStatus::kImplausible : status;
}

std::string_view trimSpaces(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) {
    s.remove_prefix(1);
  }
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) {
    s.remove_suffix(1);
  }
  return s;
}

}  // namespace

const char* toString(DwmLineStatus status) {
  switch (status) {
    case DwmLineStatus::kMeasurement:
      return "measurement";
    case DwmLineStatus::kIgnored:
      return "ignored";
    case DwmLineStatus::kMalformed:
      return "malformed";
    case DwmLineStatus::kCountMismatch:
      return "anchor count mismatch";
    case DwmLineStatus::kImplausible:
      return "implausible value";
  }
  return "unknown";
}

DwmLineStatus decodeDwmLine(std::string_view line, DwmMeasurement& out) {
  out.clear();
  line = trimSpaces(line);
  if (startsWith(line, kDwmPrompt)) {
    // "dwm> les" is the echo of a command we (or a user) typed: never data.
    return DwmLineStatus::kIgnored;
  }
  if (line.empty() || line.front() == '[') {
    return DwmLineStatus::kIgnored;  // blank or "[000123.450 INF] ..." log line
  }
  bool implausible = false;
  if (startsWith(line, "DIST,")) {
    const DwmLineStatus status = decodeLec(line, out, implausible);
    return checkValues(status, out, implausible);
  }
  if (startsWith(line, "POS,")) {
    FieldCursor cursor(line.substr(4), ',');
    if (!parsePosFields(cursor, out.position, implausible)) {
      return DwmLineStatus::kMalformed;
    }
    out.has_position = true;
    return checkValues(DwmLineStatus::kMeasurement, out, implausible);
  }
  const bool les_start = (line.size() > 4 && line[4] == '[' && isHexId(line.substr(0, 4), 4)) ||
                         startsWith(line, "le_us=") || startsWith(line, "est[");
  if (les_start) {
    const DwmLineStatus status = decodeLes(line, out, implausible);
    return checkValues(status, out, implausible);
  }
  if (line == "les" || line == "lec" || line == "lep" || line == "si" || line == "quit") {
    return DwmLineStatus::kIgnored;  // command echo without its prompt
  }
  return looksLikeData(line) ? DwmLineStatus::kMalformed : DwmLineStatus::kIgnored;
}

}  // namespace radio_follow::drivers
