// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/drivers/dwm1001_decoder.hpp"

#include "radio_follow/drivers/text_fields.hpp"

namespace radio_follow::drivers {
namespace {

constexpr std::string_view kPrompt = "dwm>";

bool parseQuality(std::string_view field, std::uint8_t& out) {
  unsigned value = 0;
  if (!parseInteger(field, value) || value > 100) {
    return false;
  }
  out = static_cast<std::uint8_t>(value);
  return true;
}

// Parses "x,y,z" (or "x,y,z,q" when `quality` is given) as found inside les brackets.
bool parseBracketNumbers(std::string_view inner, double& x, double& y, double& z,
                         std::uint8_t* quality) {
  FieldCursor cursor(inner, ',');
  std::string_view f;
  if (!cursor.next(f) || !parseFiniteDouble(f, x) || !cursor.next(f) || !parseFiniteDouble(f, y) ||
      !cursor.next(f) || !parseFiniteDouble(f, z)) {
    return false;
  }
  if (quality != nullptr && (!cursor.next(f) || !parseQuality(f, *quality))) {
    return false;
  }
  return cursor.done();
}

// "ID[x,y,z]=range"
bool parseLesAnchor(std::string_view token, DwmAnchorRange& anchor) {
  const std::size_t open = token.find('[');
  const std::size_t close = token.find("]=");
  if (open != 4 || close == std::string_view::npos || close < open ||
      !isHexId(token.substr(0, 4), 4)) {
    return false;
  }
  assignUpperHex(token.substr(0, 4), anchor.id);
  return parseBracketNumbers(token.substr(open + 1, close - open - 1), anchor.x, anchor.y, anchor.z,
                             nullptr) &&
         parseFiniteDouble(token.substr(close + 2), anchor.range) && anchor.range >= 0.0;
}

DwmLineStatus decodeLes(std::string_view line, DwmMeasurement& out) {
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
                               out.position.z, &out.position.quality)) {
        return DwmLineStatus::kMalformed;
      }
      out.has_position = true;
    } else {
      if (seen_le_us) {
        return DwmLineStatus::kMalformed;  // anchors come first
      }
      out.ranges.emplace_back();
      if (!parseLesAnchor(token, out.ranges.back())) {
        return DwmLineStatus::kMalformed;
      }
    }
  }
  if (out.ranges.empty() && !out.has_position) {
    return DwmLineStatus::kMalformed;
  }
  return DwmLineStatus::kMeasurement;
}

bool parsePosFields(FieldCursor& cursor, DwmPosition& position) {
  std::string_view f;
  return cursor.next(f) && parseFiniteDouble(f, position.x) && cursor.next(f) &&
         parseFiniteDouble(f, position.y) && cursor.next(f) && parseFiniteDouble(f, position.z) &&
         cursor.next(f) && parseQuality(f, position.quality) && cursor.done();
}

// "AN<k>" with k == expected index.
bool isAnchorLabel(std::string_view field, std::size_t index) {
  std::size_t k = 0;
  return startsWith(field, "AN") && parseInteger(field.substr(2), k) && k == index;
}

DwmLineStatus decodeLec(std::string_view line, DwmMeasurement& out) {
  FieldCursor cursor(line, ',');
  std::string_view f;
  cursor.next(f);  // "DIST"
  std::size_t count = 0;
  if (!cursor.next(f) || !parseInteger(f, count)) {
    return DwmLineStatus::kMalformed;
  }
  while (cursor.next(f)) {
    if (f == "POS") {
      if (!parsePosFields(cursor, out.position)) {
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
        !parseFiniteDouble(f, a.z) || !cursor.next(f) || !parseFiniteDouble(f, a.range) ||
        a.range < 0.0) {
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
  }
  return "unknown";
}

DwmLineStatus decodeDwmLine(std::string_view line, DwmMeasurement& out) {
  out.clear();
  line = trimSpaces(line);
  if (startsWith(line, kPrompt)) {
    // "dwm> les" is the echo of a command we (or a user) typed: never data.
    return DwmLineStatus::kIgnored;
  }
  if (line.empty() || line.front() == '[') {
    return DwmLineStatus::kIgnored;  // blank or "[000123.450 INF] ..." log line
  }
  if (startsWith(line, "DIST,")) {
    return decodeLec(line, out);
  }
  if (startsWith(line, "POS,")) {
    FieldCursor cursor(line.substr(4), ',');
    if (!parsePosFields(cursor, out.position)) {
      return DwmLineStatus::kMalformed;
    }
    out.has_position = true;
    return DwmLineStatus::kMeasurement;
  }
  const bool les_start = (line.size() > 4 && line[4] == '[' && isHexId(line.substr(0, 4), 4)) ||
                         startsWith(line, "le_us=") || startsWith(line, "est[");
  if (les_start) {
    return decodeLes(line, out);
  }
  if (line == "les" || line == "lec" || line == "lep" || line == "si" || line == "quit") {
    return DwmLineStatus::kIgnored;  // command echo without its prompt
  }
  return looksLikeData(line) ? DwmLineStatus::kMalformed : DwmLineStatus::kIgnored;
}

}  // namespace radio_follow::drivers
