#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Shared-workspace check: configures radio_follow next to test/packaging/rf_clash_dummy
# (targets named simulator, locator, pid_test, experiment_check, bench_locator_solve, ...)
# in one temporary catkin_make workspace, builds the dummy's targets and one small
# radio_follow executable, and checks both packages' binaries are where rosrun looks.
# Fails at configure time when a radio_follow target lacks the radio_follow_ prefix.
# Usage: scripts/check_target_clash.sh [workspace dir, default: a new temp dir]
set -euo pipefail
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
export PATH="/usr/bin:$PATH"
# Nothing from a dev workspace: only Debian's ROS in /usr.
unset CMAKE_PREFIX_PATH ROS_PACKAGE_PATH LD_LIBRARY_PATH PYTHONPATH PKG_CONFIG_PATH
ws="${1:-$(mktemp -d /tmp/rf-clash.XXXXXX)}"
mkdir -p "$ws/src"
ln -sfn "$repo" "$ws/src/radio_follow"
ln -sfn "$repo/test/packaging/rf_clash_dummy" "$ws/src/rf_clash_dummy"
cd "$ws"
start=$SECONDS
log="$ws/configure.log"
if ! catkin_make -DPYTHON_EXECUTABLE=/usr/bin/python3 -DCATKIN_ENABLE_TESTING=ON \
    cmake_check_build_system >"$log" 2>&1; then
  grep -E 'CMake Error|another target with the same name|already exists' "$log" | head -n 20 >&2
  echo "check_target_clash: FAILED: configure next to rf_clash_dummy failed (log: $log)" >&2
  exit 1
fi
# The dummy's executables and gtests, and radio_follow's placement_advisor (the dummy has
# one of that name too).
dummy_targets=(simulator locator velocity_controller placement_advisor bench_locator_solve
  bench_stop_latency experiment_check locator_rostest pid_test layout_test)
make -C build -j"${RF_JOBS:-2}" "${dummy_targets[@]}" radio_follow_placement_advisor \
  >"$ws/build.log" 2>&1 || {
  tail -n 30 "$ws/build.log" >&2
  echo "check_target_clash: FAILED: build (log: $ws/build.log)" >&2
  exit 1
}
fail=0
for name in simulator locator experiment_check bench_locator_solve; do
  out="$("$ws/devel/lib/rf_clash_dummy/$name")" || out=""
  [ "$out" = "$name" ] || { echo "dummy's $name did not run as itself: '$out'" >&2; fail=1; }
done
[ -x "$ws/devel/lib/radio_follow/placement_advisor" ] ||
  { echo "radio_follow's placement_advisor is not at devel/lib/radio_follow/" >&2; fail=1; }
[ "$fail" = 0 ] || { echo "check_target_clash: FAILED" >&2; exit 1; }
echo "check_target_clash: OK in $((SECONDS - start)) s (workspace $ws)"
[ $# -ge 1 ] || rm -rf "$ws"
