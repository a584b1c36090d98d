#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Runs the closed-loop experiments (test/ros/experiments/*.test: the thesis's Experiment 3
# analogues and the fault runs) one by one and prints the table of doc/experiments.md.
# Arguments: [--seed N] experiment names to run (default: all). --seed sets the simulated
# noise seed of every run (default 1, what the test command runs; the .test files read it
# from RF_SEED). The test command runs the same experiments as part of every test run.
set -euo pipefail
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$repo/scripts/setup.sh"
bash "$repo/scripts/build.sh" tests
# shellcheck disable=SC1091
source "$repo/scripts/env.sh"
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
