#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Installs everything radio_follow needs from Debian 12's own archive. Idempotent: when
# every package is already installed it only checks and exits (no apt-get call at all).
# Needs root; when not root it uses sudo if present (see README, "Not root?").
set -euo pipefail

packages=(
  # build
  build-essential cmake catkin python3-catkin-pkg ros-message-generation ros-message-runtime
  # ROS 1 (Debian's own packages)
  ros-base-dev libroscpp-dev librosbag-dev python3-rosbag python3-roslaunch python3-rostopic
  python3-rosnode rosbash python3-std-msgs python3-geometry-msgs python3-sensor-msgs
  python3-nav-msgs python3-visualization-msgs
  # Python message and tool packages the docs' operator commands need (rosservice call
  # .../set_enabled, rostopic echo /diagnostics, rosparam, rosmsg, dynparam)
  python3-std-srvs python3-diagnostic-msgs python3-rosservice python3-rosparam python3-rosmsg
  python3-tf2-msgs python3-rosgraph-msgs libdiagnostic-msgs-dev libxmlrpcpp-dev
  libstd-msgs-dev libstd-srvs-dev libgeometry-msgs-dev libnav-msgs-dev libsensor-msgs-dev
  libvisualization-msgs-dev libtf2-ros-dev libtf2-msgs-dev libtf2-geometry-msgs-dev libdiagnostic-updater-dev
  libdynamic-reconfigure-config-init-mutex-dev python3-dynamic-reconfigure
  # tests
  librostest-dev python3-rostest libgtest-dev googletest catkin-lint
  # math, I/O, benchmarks (python3-scipy: the thesis's SciPy solve, bench/thesis_scipy.py;
  # benchmarks are never installed, so neither it nor Google Benchmark is in package.xml)
  libceres-dev libeigen3-dev libboost-system-dev libboost-program-options-dev libboost-dev libyaml-cpp-dev libbenchmark-dev
  python3-scipy
  # reports (demo plot)
  python3-matplotlib python3-numpy
  # packaging (scripts/package.sh: rosdep check, bloom-generate rosdebian, .deb build)
  python3-bloom python3-rosdep2 debhelper fakeroot dpkg-dev
)

missing=()
for p in "${packages[@]}"; do
  [[ "$p" == \#* ]] && continue
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q '^install ok installed$'; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#packages[@]} packages present"
  exit 0
fi

sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null 2>&1; then
    sudo_cmd=(sudo)
  else
    echo "setup: missing packages and not root (and no sudo): ${missing[*]}" >&2
    echo "setup: ask an administrator to run: apt-get install ${missing[*]}" >&2
    exit 1
  fi
fi

echo "setup: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
