#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# README command 1: install, build and run the simulated follow-me demo headless.
# Extra arguments go to roslaunch (e.g. layout:=tracked).
set -euo pipefail
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$repo/scripts/setup.sh"
bash "$repo/scripts/build.sh"
# shellcheck disable=SC1091
source "$repo/scripts/env.sh"
export ROS_HOME="${ROS_HOME:-$RF_WS/ros_home}"
# A private master port, so the demo never joins (or disturbs) a robot's running master.
port="${RF_DEMO_PORT:-11411}"
exec roslaunch -p "$port" radio_follow demo.launch check:=true "$@"
