#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# The README's test command on a fresh clone while every core is busy (issue 34: no test
# may depend on the machine being idle). Clones HEAD of this repository into a new
# directory, starts one busy loop per core at normal priority, runs what CI runs
# (`CI=true bash .ci/run`: the test command, then scripts/release_check.sh) in the clone
# RUNS times in a row (default 2; the first run builds its own workspace from nothing),
# stops the loops and prints each run's verdict and wall time. Exit 0 only when every run
# passed.
#   bash scripts/test_loaded.sh [RUNS]
set -euo pipefail
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
runs="${1:-2}"
clone="$(mktemp -d /tmp/rf_loaded.XXXXXX)/radio_follow"
git clone --quiet "$repo" "$clone"
echo "test_loaded: fresh clone of $(git -C "$clone" rev-parse --short HEAD) in $clone"

loops=()
stop_loops() {
  for pid in "${loops[@]}"; do
    kill "$pid" 2>/dev/null || true
  done
}
trap stop_loops EXIT
for _ in $(seq "$(nproc)"); do
  bash -c 'while :; do :; done' &
  loops+=("$!")
done
echo "test_loaded: ${#loops[@]} busy loops at normal priority"

status=0
for run in $(seq "$runs"); do
  start=$(date +%s)
  if (cd "$clone" && CI=true bash .ci/run >"$clone/../test_run_$run.log" 2>&1); then
    verdict=passed
  else
    verdict=FAILED
    status=1
  fi
  echo "test_loaded: run $run of $runs $verdict in $(( $(date +%s) - start )) s" \
       "(log $clone/../test_run_$run.log)"
  tail -n 6 "$clone/../test_run_$run.log" | sed 's/^/  /'
done
exit "$status"
