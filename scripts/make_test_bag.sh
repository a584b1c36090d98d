#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Records the small simulator bag the offline tools are tested on
# (test/data/sim_spot_straight.bag): the Spot layout, the straight walk, seed 1, the
# velocity controller in the loop, through launch/record.launch. Run it again after
# changing the simulator or the message definitions.
# Arguments: an output path (default: the file above) and extra demo.launch arguments;
# RF_BAG_SCENARIO and RF_BAG_TIME_FACTOR choose another scenario and speed.
set -euo pipefail
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
out="${1:-$repo/test/data/sim_spot_straight.bag}"
shift || true
# shellcheck disable=SC1091
source "$repo/scripts/env.sh"
export ROS_HOME="${ROS_HOME:-$RF_WS/ros_home}"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
port="${RF_BAG_PORT:-11412}"
roscore -p "$port" >/dev/null 2>&1 &
core=$!
trap 'kill $core 2>/dev/null; rm -rf "$tmp"' EXIT
export ROS_MASTER_URI="http://localhost:$port"
sleep 2
rosparam set /use_sim_time true  # the recorder must stamp with the simulator's clock
roslaunch radio_follow record.launch prefix:="$tmp/sim" split_size:=0 >/dev/null 2>&1 &
record=$!
sleep 2
roslaunch radio_follow demo.launch scenario:="${RF_BAG_SCENARIO:-straight_walk}" \
  time_factor:="${RF_BAG_TIME_FACTOR:-2}" \
  report_dir:="$tmp/report" "$@" >/dev/null 2>&1
kill -INT $record
wait $record || true
bag="$(ls "$tmp"/sim_*.bag)"
mkdir -p "$(dirname "$out")"
cp "$bag" "$out"
# sed reads to the end: `head` would close the pipe early, and rosbag info's SIGPIPE
# fails the script under pipefail after a successful recording.
rosbag info "$out" | sed -n 1,30p
