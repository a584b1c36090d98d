#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Builds and runs the core benchmarks (bench/<name>.cpp -> bench_<name>), by hand, never as
# tests. Extra arguments go to each Google Benchmark program, e.g.
#   bash scripts/bench.sh --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
# bench_thesis_accuracy is a harness that prints a table (no Google Benchmark flags); it and
# bench/ros/ (bench_stop_latency: scripts/bench_stop_latency.sh) run from scripts/results.sh.
set -euo pipefail
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
export PATH="/usr/bin:$PATH"
bash "$repo/scripts/build.sh" >/dev/null
# shellcheck disable=SC1091
source "$repo/scripts/env.sh"
for source in "$repo"/bench/*.cpp; do
  name="bench_$(basename "$source" .cpp)"
  [ "$name" = bench_thesis_accuracy ] && continue
  echo "== $name"
  "$RF_WS/devel/lib/radio_follow/$name" "$@"
done
