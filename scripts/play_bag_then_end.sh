#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# The player node of launch/replay.launch: `rosbag play` with the given arguments, then
# ends the roslaunch that started it as Ctrl-C would. A replay thus ends when its bag
# does, without the red "REQUIRED process has died" that a required rosbag node prints
# (roslaunch has no other way for a node to end a launch cleanly).
# Usage: play_bag_then_end.sh true|false <rosbag play arguments>; false only plays (under
# rostest, whose test node ends the run and must not be interrupted).
set -u
end_launch="$1"
shift
rosbag play "$@"
status=$?
if [ "$end_launch" = true ]; then
  kill -INT "$PPID" 2>/dev/null || true
fi
exit "$status"
