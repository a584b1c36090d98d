// SPDX-License-Identifier: BSD-3-Clause
// Decoder throughput, lines per second (items_per_second), for the serial drivers'
// line formats, and the byte throughput of the framer, and of the drivers' LineDriver
// around it, on a realistic stream.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <string>
#include <vector>

#include "radio_follow/drivers/dwm1001_decoder.hpp"
#include "radio_follow/drivers/line_driver.hpp"
#include "radio_follow/drivers/line_framer.hpp"
#include "radio_follow/drivers/uudf_decoder.hpp"

namespace {

using namespace radio_follow::drivers;

const std::vector<std::string> kDwmLines = {
    "1151[5.00,8.00,2.25]=6.48 0CA8[0.00,8.00,2.25]=6.51 111C[5.00,0.00,2.25]=3.18 "
    "1150[0.00,0.00,2.25]=3.16 le_us=2576 est[2.57,1.98,1.68,100]",
    "DIST,4,AN0,1151,5.00,8.00,2.25,6.48,AN1,0CA8,0.00,8.00,2.25,6.51,AN2,111C,5.00,0.00,"
    "2.25,3.18,AN3,1150,0.00,0.00,2.25,3.16,POS,2.57,1.98,1.68,100",
    "POS,2.57,1.98,1.68,100",
    "[000007.930 INF] sys: fw2 fw_ver=x01030001 cfg_ver=x00010700",
};

const std::vector<std::string> kUudfLines = {
    "+UUDF:CCF9578E0D8A,-42,20,0,-43,37,\"CCF9578E0D89\",\",\",15869,23",
    "+UUDF:6C1DEBA5F60C,-53,8,2,0,37,\"6C1DEBA09862\",\"\",1437347",
    "+UUDFP:CCF9578E0D8A,\"0201060303AAFE\"",
    "+UUDF:CCF9578E0D8A,-42,20,0,-4",
};

template <typename Decode, typename Out>
void runDecoder(benchmark::State& state, const std::vector<std::string>& lines, Decode decode) {
  Out out;
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(decode(lines[i], out));
    i = (i + 1) % lines.size();
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations()));
}

void BM_DwmDecodeMix(benchmark::State& state) {
  runDecoder<decltype(&decodeDwmLine), DwmMeasurement>(state, kDwmLines, &decodeDwmLine);
}
BENCHMARK(BM_DwmDecodeMix);

void BM_DwmDecodeLes(benchmark::State& state) {
  runDecoder<decltype(&decodeDwmLine), DwmMeasurement>(state, {kDwmLines[0]}, &decodeDwmLine);
}
BENCHMARK(BM_DwmDecodeLes);

void BM_DwmDecodeLec(benchmark::State& state) {
  runDecoder<decltype(&decodeDwmLine), DwmMeasurement>(state, {kDwmLines[1]}, &decodeDwmLine);
}
BENCHMARK(BM_DwmDecodeLec);

void BM_UudfDecodeMix(benchmark::State& state) {
  runDecoder<decltype(&decodeUudfLine), UudfEvent>(state, kUudfLines, &decodeUudfLine);
}
BENCHMARK(BM_UudfDecodeMix);

void BM_UudfDecodeEvent(benchmark::State& state) {
  runDecoder<decltype(&decodeUudfLine), UudfEvent>(state, {kUudfLines[0]}, &decodeUudfLine);
}
BENCHMARK(BM_UudfDecodeEvent);

// Feeds `feed(data, size, lines)` a stream of the two DWM output formats cut into 64-byte
// chunks (USB CDC packet size); `lines` counts the lines decoded.
template <typename Feed>
void runDwmStream(benchmark::State& state, Feed feed) {
  std::string stream;
  for (int i = 0; i < 100; ++i) {
    stream += kDwmLines[i % 2] + "\r\n";
  }
  std::size_t lines = 0;
  for (auto _ : state) {
    for (std::size_t pos = 0; pos < stream.size(); pos += 64) {
      feed(stream.data() + pos, std::min<std::size_t>(64, stream.size() - pos), lines);
    }
  }
  state.SetItemsProcessed(static_cast<int64_t>(lines));
  state.SetBytesProcessed(static_cast<int64_t>(state.iterations() * stream.size()));
}

// Framer + decoder.
void BM_FramerAndDwmDecoder(benchmark::State& state) {
  LineFramer framer;
  DwmMeasurement out;
  runDwmStream(state, [&](const char* data, std::size_t size, std::size_t& lines) {
    framer.feed(data, size, 0.0, [&](std::string_view line, double) {
      benchmark::DoNotOptimize(decodeDwmLine(line, out));
      ++lines;
    });
  });
}
BENCHMARK(BM_FramerAndDwmDecoder);

// The drivers' own path: LineDriver (framer and the diagnostics' counters) + decoder +
// the verdict counted, as dwm1001_driver runs it on its I/O thread.
void BM_LineDriverAndDwmDecoder(benchmark::State& state) {
  LineDriver driver(1024);
  DwmMeasurement out;
  runDwmStream(state, [&](const char* data, std::size_t size, std::size_t& lines) {
    driver.onBytes(data, size, 0.0, [&](std::string_view line, double) {
      const DwmLineStatus status = decodeDwmLine(line, out);
      benchmark::DoNotOptimize(driver.count(verdictOf(status, DwmLineStatus::kMeasurement)));
      ++lines;
    });
  });
}
BENCHMARK(BM_LineDriverAndDwmDecoder);

}  // namespace

BENCHMARK_MAIN();
