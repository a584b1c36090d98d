#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# The calibration workflow of doc/deployment.md on the simulator: records a simulated
# run (scripts/make_test_bag.sh: the Spot layout, the follower in the loop, the
# simulator's ground_truth/target_relative in the bag) and calibrates the layout from it
# with calibrate_layout, printing the tool's table.
# Arguments: an output directory (default: a temporary one, removed at the end) and
# extra calibrate_layout flags. RF_BAG_SCENARIO (default random_walk: the person walks
# 1-6 m from the robot in every direction the follower lets them) and
# RF_BAG_TIME_FACTOR as for make_test_bag.sh.
set -euo pipefail
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
if [ -n "${1:-}" ]; then
  out="$1"
  mkdir -p "$out"
else
  out="$(mktemp -d)"
  trap 'rm -rf "$out"' EXIT
fi
shift || true
# shellcheck disable=SC1091
source "$repo/scripts/env.sh"
rm -f "$out/calibration.bag"
if ! RF_BAG_SCENARIO="${RF_BAG_SCENARIO:-random_walk}" RF_BAG_PORT="${RF_BAG_PORT:-11413}" \
  bash "$repo/scripts/make_test_bag.sh" "$out/calibration.bag" >/dev/null 2>&1 ||
  [ ! -s "$out/calibration.bag" ]; then
  echo "calibration_demo: the simulated recording failed (no $out/calibration.bag)" >&2
  exit 1
fi
"$RF_WS/devel/lib/radio_follow/calibrate_layout" --bag "$out/calibration.bag" \
  --layout "$repo/config/layouts/spot.yaml" --out "$out/spot_calibrated.yaml" \
  --truth-topic ground_truth/target_relative "$@"
