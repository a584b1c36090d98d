#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# The homing law's parameters one at a time on seed 000's Table 2 benchmark at the 0.3 m
# arrival radius: each row is the shipped config/homing_controller.yaml with one value
# changed (lab homing_experiment --params). Prints a Markdown table: the goal and final errors
# of configurations 1-4 (lowest-highest) and configuration 5's goal error, final error,
# success and time. Deterministic (fixed seed). Needs a built workspace.
#   bash scripts/homing_sweep.sh
set -euo pipefail
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
set +u
# shellcheck disable=SC1091
source "$repo/scripts/env.sh"
set -u
experiment=("$RF_WS/devel/lib/radio_follow/lab" homing_experiment)
overlay="$(mktemp)"
trap 'rm -f "$overlay"' EXIT

# The shipped values of the swept parameters, from the file itself (top-level keys only).
shipped="$(awk -F': *' '/^(goal_estimator|range_step|error_threshold|kohonen_k|agreement_distance|tau|window|linear_gain):/ {
  sub(/ *#.*/, "", $2); printf "%s%s %s", sep, $1, $2; sep = ", " }' "$repo/config/homing_controller.yaml")"
echo "| changed (shipped: $shipped) | goal err. 1-4 (m) | final err. 1-4 (m) | goal err. 5 (m) | final err. 5 (m) | success 5 (%) | time 5 (s) |"
echo "| --- | --- | --- | --- | --- | --- | --- |"
# The hybrid rule's own parameters (range_step, error_threshold, kohonen_k) only start the
# fit of all readings, so they are swept with the hybrid rule as the goal (seed000).
for change in "(none)" "agreement_distance: 0.1" "agreement_distance: 0.05" "tau: 40.0" \
  "linear_gain: 1.0" "linear_gain: 2.0" "goal_estimator: seed000" \
  "goal_estimator: seed000, range_step: 0.0" "goal_estimator: seed000, error_threshold: 1.0" \
  "goal_estimator: seed000, kohonen_k: 0.5" "goal_estimator: seed000, kohonen_k: 0.15"; do
  if [[ "$change" == "(none)" ]]; then : >"$overlay"; else sed 's/, /\n/g' <<<"$change" >"$overlay"; fi
  "${experiment[@]}" --params "$overlay" | awk -F' *[|] *' -v change="$change" '
    /^[|] [1-4]:/ {
      g = $6 + 0; f = $7 + 0
      if (n++ == 0) { lo = g; hi = g; flo = f; fhi = f }
      if (g < lo) lo = g; if (g > hi) hi = g; if (f < flo) flo = f; if (f > fhi) fhi = f
    }
    /^[|] 5:/ { success = $3; time = $4; goal = $6; final = $7 }
    END {
      printf "| %s | %.2f-%.2f | %.2f-%.2f | %s | %s | %s | %s |\n", change, lo, hi, flo, fhi, goal, final, success, time
    }'
done
