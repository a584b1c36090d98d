#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# The closed-loop experiments of doc/experiments.md (test/experiments.yaml: the thesis's
# Experiment 3 analogues and the fault runs).
#   bash scripts/experiments.sh [--seeds N] [--sensor-profile ideal|realistic] [name ...]
#       the lockstep runs (`lab experiments`): deterministic, seeds 1..N (default 8), a
#       few seconds; prints the table and every broken threshold. The sensor profile is
#       test/experiments.yaml's unless given (realistic: each seed calibrates its own
#       simulated robot first, doc/experiments.md).
#   bash scripts/experiments.sh --ros [--seed N] [name ...]
#       the ROS smoke runs (test/ros/experiments/*.test: the real nodes, demo.launch) at
#       noise seed N (default 1), then the table of their reports. Each also checks that it
#       agrees with the lockstep run of the same seed.
# The test command runs both (the lockstep runs in the closed_loop gtest).
set -euo pipefail
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$repo/scripts/setup.sh"
bash "$repo/scripts/build.sh" tests
# shellcheck disable=SC1091
source "$repo/scripts/env.sh"
if [ "${1:-}" != "--ros" ]; then
  exec "$RF_WS/devel/lib/radio_follow/lab" experiments "$@"
fi
shift
export ROS_HOME="${ROS_HOME:-$RF_WS/ros_home}"
root="$ROS_HOME/radio_follow_experiments"
if [ "${1:-}" = "--seed" ]; then
  export RF_SEED="$2"
  shift 2
fi
names=("$@")
if [ ${#names[@]} -eq 0 ]; then
  for f in "$repo"/test/ros/experiments/*.test; do names+=("$(basename "$f" .test)"); done
fi
failed=0
for name in "${names[@]}"; do
  rm -rf "${root:?}/$name"
  if rostest "$repo/test/ros/experiments/$name.test" >"$ROS_HOME/experiment_$name.log" 2>&1; then
    echo "$name: passed"
  else
    echo "$name: FAILED (log: $ROS_HOME/experiment_$name.log)"
    failed=1
  fi
done
/usr/bin/python3 "$repo/scripts/experiment_table.py" "$root"
exit $failed
