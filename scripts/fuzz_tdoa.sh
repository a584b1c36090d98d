#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Builds the TDoA packet fuzzer (fuzz/tdoa_packet_fuzz.cpp + the TDoA core sources) with
# clang's libFuzzer, ASan and UBSan, outside catkin, and runs it.
#   scripts/fuzz_tdoa.sh [seconds]      default 60
# Seeds: valid and broken packets from the test packet builder (written by a small seed
# generator built from the same sources). The corpus lives in fuzz/corpus-tdoa/ (ignored
# by git); crashes are written to .fuzz/tdoa/artifacts/ and make the script fail.
set -euo pipefail
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
seconds="${1:-60}"
out="$repo/.fuzz/tdoa"
corpus="$repo/fuzz/corpus-tdoa"
artifacts="$out/artifacts"
mkdir -p "$out" "$corpus" "$artifacts"

cxx="${CXX_FUZZ:-clang++}"
eigen_flags="$(pkg-config --cflags eigen3)"
core=(
  "$repo/src/drivers/tdoa_packet.cpp"
  "$repo/src/drivers/tdoa_grouper.cpp"
  "$repo/src/drivers/tdoa_differences.cpp"
  "$repo/src/drivers/tdoa_receiver.cpp"
)
common_flags=(-std=c++17 -O1 -g -I"$repo/include" $eigen_flags)

# shellcheck disable=SC2068
"$cxx" ${common_flags[@]} -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=undefined \
  "${core[@]}" "$repo/fuzz/tdoa_packet_fuzz.cpp" -o "$out/tdoa_packet_fuzz"

# Seed corpus from the packet builder.
cat >"$out/seeds.cpp" <<'CPP'
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>
#include "radio_follow/drivers/tdoa_packet_builder.hpp"
using radio_follow::TdoaPacketBuilder;
int main(int argc, char** argv) {
  if (argc != 2) return 2;
  std::vector<std::vector<std::uint8_t>> seeds{
      TdoaPacketBuilder(0x2000, 1).mac(0x5A84).timestamp(123456789).build(),
      TdoaPacketBuilder(0x2002, 1).mac(0x5A84).timestamp(123456999).build(),
      TdoaPacketBuilder(0x2001, 1).mac(0x5A84).timestamp(123457111).build(),
      TdoaPacketBuilder(0x2001, 2).mac(0x0CA8).payload({1, 2, 3}).timestamp(5, 6)
          .quality(-80.0, -90.0, 1, 30.0).radio(1, 2, 5, 2, 6).rawTlv(9, {7}).build(),
      TdoaPacketBuilder(0x2000, 3).rawTlv(3, {1, 2}, 4000).build(),
      TdoaPacketBuilder(0x2000, 3).timestamp(1).lengthField(300).build(),
  };
  for (std::size_t i = 0; i < seeds.size(); ++i) {
    std::ofstream(std::string(argv[1]) + "/seed" + std::to_string(i), std::ios::binary)
        .write(reinterpret_cast<const char*>(seeds[i].data()),
               static_cast<std::streamsize>(seeds[i].size()));
  }
  return 0;
}
CPP
# shellcheck disable=SC2068
"$cxx" ${common_flags[@]} "$repo/src/drivers/tdoa_packet_builder.cpp" "$out/seeds.cpp" \
  -o "$out/tdoa_seeds"
"$out/tdoa_seeds" "$corpus"

echo "fuzzing for ${seconds} s: $out/tdoa_packet_fuzz $corpus"
"$out/tdoa_packet_fuzz" -max_total_time="$seconds" -max_len=2048 -print_final_stats=1 \
  -artifact_prefix="$artifacts/" "$corpus"
