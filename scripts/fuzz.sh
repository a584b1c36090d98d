#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Builds each libFuzzer target in fuzz/ with the core sources it needs (outside catkin,
# clang with -fsanitize=fuzzer,address,undefined) and runs it.
# Usage: scripts/fuzz.sh [seconds per target, default 60] [target ...]
#   targets: dwm1001 uudf (default: all). Output and crashes in $RF_FUZZ_DIR (default
#   .fuzz/ in the clone); each run starts from fuzz/corpus/<target> plus what earlier
#   runs found.
set -euo pipefail
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
seconds="${1:-60}"
shift || true
targets=("$@")
if [ ${#targets[@]} -eq 0 ]; then
  targets=(dwm1001 uudf)
fi
cxx="${CXX_FUZZ:-$(command -v clang++-14 || command -v clang++)}"
out="${RF_FUZZ_DIR:-$repo/.fuzz}"
mkdir -p "$out"

# The core sources each decoder needs (the framer is header-only).
declare -A sources=(
  [dwm1001]="src/drivers/dwm1001_decoder.cpp"
  [uudf]="src/drivers/uudf_decoder.cpp"
)

for target in "${targets[@]}"; do
  if [ -z "${sources[$target]:-}" ]; then
    echo "unknown target '$target' (known: ${!sources[*]})" >&2
    exit 2
  fi
  binary="$out/${target}_fuzz"
  echo "== building $binary"
  # shellcheck disable=SC2086
  (cd "$repo" && "$cxx" -std=c++17 -O1 -g -I include \
    -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=undefined \
    "fuzz/${target}_fuzz.cpp" ${sources[$target]} -o "$binary")
  corpus="$out/corpus_$target"
  mkdir -p "$corpus" "$out/crashes_$target"
  echo "== running $target for ${seconds}s"
  "$binary" "$corpus" "$repo/fuzz/corpus/$target" -max_total_time="$seconds" \
    -max_len=512 -artifact_prefix="$out/crashes_$target/" -print_final_stats=1 \
    2>&1 | tee "$out/$target.log" | grep -E '^#[0-9]+ +DONE|stat::number_of_executed_units|ERROR|SUMMARY' || true
  if ls "$out/crashes_$target"/* >/dev/null 2>&1; then
    echo "!! $target: crash inputs in $out/crashes_$target" >&2
    exit 1
  fi
done
