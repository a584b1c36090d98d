// SPDX-License-Identifier: BSD-3-Clause
// libFuzzer target: arbitrary bytes through the line framer (split at a fuzzer-chosen
// point) into the DWM1001 decoder. Besides crashes and sanitizer reports it checks the
// decoder's contract: a measurement holds finite values and quality <= 100.
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "radio_follow/drivers/dwm1001_decoder.hpp"
#include "radio_follow/drivers/line_framer.hpp"

using radio_follow::drivers::decodeDwmLine;
using radio_follow::drivers::DwmLineStatus;
using radio_follow::drivers::DwmMeasurement;
using radio_follow::drivers::LineFramer;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size == 0) {
    return 0;
  }
  const char* bytes = reinterpret_cast<const char*>(data);
  const size_t cut = data[0] % size;
  LineFramer framer(256);
  DwmMeasurement m;
  auto sink = [&](std::string_view line, double) {
    if (decodeDwmLine(line, m) != DwmLineStatus::kMeasurement) {
      return;
    }
    if (m.ranges.empty() && !m.has_position) {
      std::abort();
    }
    for (const auto& a : m.ranges) {
      if (!std::isfinite(a.x) || !std::isfinite(a.range) || a.range < 0.0 || a.id.size() != 4) {
        std::abort();
      }
    }
    if (m.has_position && (m.position.quality > 100 || !std::isfinite(m.position.x))) {
      std::abort();
    }
  };
  framer.feed(bytes + 1, cut, 0.0, sink);
  framer.feed(bytes + 1 + cut, size - 1 - cut, 1.0, sink);
  return 0;
}
