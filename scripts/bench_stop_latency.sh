#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Stop latency of velocity_controller with the shipped parameter files: a range below
# safe_distance in -> the first zero cmd_vel out, while estimates arrive at 50 Hz and 10 Hz
# on the main queue. Baseline in the same run: the round trip through a trivial roscpp
# relay. Usage: bash scripts/bench_stop_latency.sh [trials]
set -euo pipefail
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
export PATH="/usr/bin:$PATH"
# shellcheck disable=SC1091
source "$repo/scripts/env.sh" >/dev/null
trials="${1:-40}"
port="${RF_BENCH_PORT:-11711}"  # RF_BENCH_PORT: another free master port
export ROS_MASTER_URI="http://localhost:$port"
export ROS_HOME="${ROS_HOME:-$RF_WS/ros_home}"
bin="$RF_WS/devel/lib/radio_follow"
# RF_CONTROLLER=/path/to/velocity_controller measures another build (e.g. an older commit).
controller_bin="${RF_CONTROLLER:-$bin/velocity_controller}"
pids=()
cleanup() { kill "${pids[@]}" 2>/dev/null || true; wait 2>/dev/null || true; }
trap cleanup EXIT
roscore -p "$port" >/dev/null 2>&1 & pids+=($!)
sleep 3
for rate in 50 10; do
  rosparam delete /velocity_controller >/dev/null 2>&1 || true
  rosparam load "$repo/config/controller_common.yaml" /velocity_controller
  rosparam load "$repo/config/velocity_controller.yaml" /velocity_controller
  rosparam set /velocity_controller/range_topics '[uwb_ranges]'
  rosparam set /velocity_controller/target_anchor_id ABCD
  rosparam set /velocity_controller/start_enabled true
  # Another build's binary must load its own libraries, not this workspace's.
  LD_LIBRARY_PATH="$(dirname "$(dirname "$controller_bin")"):${LD_LIBRARY_PATH:-}" \
    "$controller_bin" >/dev/null 2>&1 & controller=$!
  "$bin/bench_stop_latency" --echo >/dev/null 2>&1 & relay=$!
  sleep 2
  "$bin/bench_stop_latency" "$trials" "$rate"
  kill "$controller" "$relay"; wait "$controller" "$relay" 2>/dev/null || true
done
