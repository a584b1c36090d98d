// SPDX-License-Identifier: BSD-3-Clause
// libFuzzer target: arbitrary bytes through the line framer into the +UUDF decoder,
// checking the contract of a decoded event (angles within +-pi, channel <= 39, 12-digit
// tag ID) besides crashes and sanitizer reports.
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "radio_follow/drivers/line_framer.hpp"
#include "radio_follow/drivers/uudf_decoder.hpp"

using radio_follow::drivers::decodeUudfLine;
using radio_follow::drivers::LineFramer;
using radio_follow::drivers::UudfEvent;
using radio_follow::drivers::UudfLineStatus;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size == 0) {
    return 0;
  }
  const char* bytes = reinterpret_cast<const char*>(data);
  const size_t cut = data[0] % size;
  LineFramer framer(256);
  UudfEvent e;
  auto sink = [&](std::string_view line, double) {
    if (decodeUudfLine(line, e) != UudfLineStatus::kEvent) {
      return;
    }
    if (e.tag_id.size() != 12 || e.channel > 39 || !(std::fabs(e.azimuth) <= M_PI) ||
        !(std::fabs(e.elevation) <= M_PI) || !std::isfinite(e.rssi)) {
      std::abort();
    }
  };
  framer.feed(bytes + 1, cut, 0.0, sink);
  framer.feed(bytes + 1 + cut, size - 1 - cut, 1.0, sink);
  return 0;
}
