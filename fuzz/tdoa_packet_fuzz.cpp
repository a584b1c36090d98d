// SPDX-License-Identifier: BSD-3-Clause
// libFuzzer target for the TDoA anchor-report decoder and the pipeline behind it.
// Built outside catkin by scripts/fuzz_tdoa.sh with ASan and UBSan: any read past the
// datagram, overflow or undefined shift is a crash.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "radio_follow/drivers/tdoa_packet.hpp"
#include "radio_follow/drivers/tdoa_receiver.hpp"

namespace {

radio_follow::TdoaReceiver& receiver() {
  static radio_follow::TdoaReceiver instance = [] {
    radio_follow::TdoaDifferenceConfig config;
    config.anchors = {{"a", 0x2000, {0.29, 0.165, 0.135}},
                      {"b", 0x2002, {0.29, -0.165, 0.135}},
                      {"c", 0x2001, {-0.37, 0.0, 0.135}}};
    return radio_follow::TdoaReceiver(config, 0.05);
  }();
  return instance;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  // The decoder must tolerate the datagram at exactly its size: copy it into a buffer
  // of that size so ASan flags even a one-byte over-read.
  const std::vector<std::uint8_t> datagram(data, data + size);
  radio_follow::TdoaReport report;
  const auto error = radio_follow::decodeTdoaPacket(datagram.data(), datagram.size(), &report);
  if (error == radio_follow::TdoaDecodeError::kOk && report.payload_size > 0 &&
      report.payload_offset + report.payload_size > datagram.size()) {
    __builtin_trap();  // a payload view outside the datagram
  }
  // Feed the grouper and difference calculator too, with a clock that advances so groups
  // complete, expire and wrap.
  static double now = 0.0;
  now += 0.01;
  std::vector<radio_follow::TdoaBlink> blinks;
  receiver().onDatagram(datagram.data(), datagram.size(), now, &blinks);
  receiver().onTimer(now, &blinks);
  return 0;
}
