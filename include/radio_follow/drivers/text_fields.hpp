// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <charconv>
#include <cmath>
#include <cstdint>
#include <string>
#include <string_view>

namespace radio_follow::drivers {

/// Small strict parsers shared by the line decoders. Each one consumes the whole
/// field or fails: "6.48x" is not a number, so a merged or cut line is never half-read.
/// Locale-independent (std::from_chars), no allocation.

/// Parses a finite decimal number (optional leading '-'); rejects "nan", "inf", "", "+1".
inline bool parseFiniteDouble(std::string_view field, double& out) {
  if (field.empty()) {
    return false;
  }
  const char* end = field.data() + field.size();
  const auto result = std::from_chars(field.data(), end, out, std::chars_format::fixed);
  return result.ec == std::errc() && result.ptr == end && std::isfinite(out);
}

/// Parses a base-10 integer; the whole field must be digits (with an optional '-').
template <typename Int>
bool parseInteger(std::string_view field, Int& out) {
  if (field.empty()) {
    return false;
  }
  const char* end = field.data() + field.size();
  const auto result = std::from_chars(field.data(), end, out);
  return result.ec == std::errc() && result.ptr == end;
}

inline bool isHexDigit(char c) {
  return (c >= '0' && c <= '9') || (c >= 'A' && c <= 'F') || (c >= 'a' && c <= 'f');
}

/// True when `field` is exactly `digits` hexadecimal characters.
inline bool isHexId(std::string_view field, std::size_t digits) {
  if (field.size() != digits) {
    return false;
  }
  for (char c : field) {
    if (!isHexDigit(c)) {
      return false;
    }
  }
  return true;
}

/// Upper-cases a hexadecimal ID into `out` (reusing its capacity).
inline void assignUpperHex(std::string_view id, std::string& out) {
  out.assign(id.data(), id.size());
  for (char& c : out) {
    if (c >= 'a' && c <= 'f') {
      c = static_cast<char>(c - 'a' + 'A');
    }
  }
}

inline bool startsWith(std::string_view text, std::string_view prefix) {
  return text.substr(0, prefix.size()) == prefix;
}

/// Walks the `separator`-separated fields of a line. Unlike repeated find() it tells a
/// trailing empty field ("a,b,") from the end of the line, so such lines are rejected.
class FieldCursor {
 public:
  FieldCursor(std::string_view text, char separator) : rest_(text), separator_(separator) {}

  /// Stores the next field in `field`; false once every field has been returned.
  bool next(std::string_view& field) {
    if (done_) {
      return false;
    }
    const std::size_t pos = rest_.find(separator_);
    if (pos == std::string_view::npos) {
      field = rest_;
      done_ = true;
    } else {
      field = rest_.substr(0, pos);
      rest_ = rest_.substr(pos + 1);
    }
    return true;
  }

  /// True when every field has been returned.
  bool done() const { return done_; }

 private:
  std::string_view rest_;
  char separator_;
  bool done_ = false;
};

}  // namespace radio_follow::drivers
