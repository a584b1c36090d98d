#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# The release checks (doc/packaging.md), each from nothing the development build made:
# radio_follow configures and builds next to a package with clashing target names
# (scripts/check_target_clash.sh), and the .deb builds, installs into a clean prefix and
# runs the demo from there (scripts/package.sh). Two more builds of the tree, so they are
# not in the test command (scripts/test.sh); CI runs both (.ci/run). First it builds the
# benchmarks, which the test command leaves out.
#   bash scripts/release_check.sh
# Exits non-zero when either check failed.
set -euo pipefail
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$repo/scripts/setup.sh"
export PATH="/usr/bin:$PATH"
status=0
# The benchmarks, which the test command does not build (in its workspace, when it ran
# there first: then only they are compiled).
log="$(mktemp)"
bash "$repo/scripts/build.sh" >"$log" 2>&1 || {
  tail -n 30 "$log" >&2
  echo "release_check: the build with the benchmarks failed (log $log)" >&2
  status=1
}
bash "$repo/scripts/check_target_clash.sh" || status=1
bash "$repo/scripts/package.sh" || status=1
if [ "$status" = 0 ]; then
  echo "release_check: target clash check and .deb check passed"
else
  echo "release_check: FAILED (see above)" >&2
fi
exit "$status"
