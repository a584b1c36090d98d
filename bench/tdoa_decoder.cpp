// SPDX-License-Identifier: BSD-3-Clause
// Throughput of the TDoA anchor-report decoder and of the whole receive pipeline
// (decode + group + differences), in packets per second. Goal: >= 1e6 packets/s decoded.
//   "$RF_WS"/devel/lib/radio_follow/bench_tdoa_decoder
#include <benchmark/benchmark.h>

#include <cstdint>
#include <vector>

#include "radio_follow/drivers/tdoa_packet.hpp"
#include "radio_follow/drivers/tdoa_packet_builder.hpp"
#include "radio_follow/drivers/tdoa_receiver.hpp"

namespace {

using radio_follow::drivers::TdoaPacketBuilder;

std::vector<std::vector<std::uint8_t>> typicalPackets() {
  // What an anchor sends per blink: MAC, timestamp, quality and radio TLVs.
  std::vector<std::vector<std::uint8_t>> packets;
  const std::uint64_t addresses[] = {0x2000, 0x2002, 0x2001};
  for (int seq = 0; seq < 64; ++seq) {
    for (std::uint64_t address : addresses) {
      packets.push_back(
          radio_follow::drivers::TdoaPacketBuilder(address, static_cast<std::uint8_t>(seq))
              .mac(0x5A84)
              .timestamp(1000000000ULL * seq + address, 40)
              .quality(-80.5, -88.25, 2, 35.5)
              .radio(1234, 5678, 5, 2, 6)
              .build());
    }
  }
  return packets;
}

void BM_DecodeTdoaPacket(benchmark::State& state) {
  const auto packets = typicalPackets();
  radio_follow::drivers::TdoaReport report;
  std::size_t i = 0;
  for (auto _ : state) {
    const auto& p = packets[i];
    benchmark::DoNotOptimize(radio_follow::drivers::decodeTdoaPacket(p.data(), p.size(), &report));
    benchmark::DoNotOptimize(report);
    i = (i + 1) % packets.size();
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["packets/s"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_DecodeTdoaPacket);

void BM_ReceivePipeline(benchmark::State& state) {
  const auto packets = typicalPackets();
  radio_follow::drivers::TdoaDifferenceConfig config;
  config.anchors = {{"05", 0x2000, {0.29, 0.165, 0.135}},
                    {"49", 0x2002, {0.29, -0.165, 0.135}},
                    {"17", 0x2001, {-0.37, 0.0, 0.135}}};
  config.plausibility_margin = 1e9;  // the synthetic timestamps are not geometric
  radio_follow::drivers::TdoaReceiver receiver(config, 0.05);
  std::vector<radio_follow::drivers::TdoaBlink> blinks;
  std::size_t i = 0;
  double now = 0.0;
  for (auto _ : state) {
    const auto& p = packets[i];
    receiver.onDatagram(p.data(), p.size(), now, &blinks);
    if (blinks.size() > 1024) {
      blinks.clear();
    }
    i = (i + 1) % packets.size();
    now += 1e-4;
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["packets/s"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  state.counters["blinks"] = static_cast<double>(receiver.stats().blinks);
}
BENCHMARK(BM_ReceivePipeline);

}  // namespace

BENCHMARK_MAIN();
