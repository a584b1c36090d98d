#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Regenerates every figure of doc/results.md and of doc/ from what
# the repo ships (config/, test/data/sim_spot_straight.bag) and prints them as Markdown:
# one section per figure group, each with the command that produced it. Figures that are
# not timings are deterministic (fixed seeds, lockstep loops); every timing is printed
# with a baseline measured in the same run and the ratio to it.
#   bash scripts/results.sh [section ...]
# Sections, in order (default: all; 387 s in one run on a shared 2-core machine, built):
#   accuracy latency scipy pcrb coldstarts load experiments homing placement offline stop demo
#   standing rssi real
# Not part of scripts/test.sh: too slow, and timings vary with the machine's load.
# Masters: RF_RESULTS_PORT (default 11751) for the stop-latency benchmark and the demo;
# rostest and measure_locator_load.sh pick their own.
set -euo pipefail
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
export PATH="/usr/bin:$PATH"
all=(accuracy latency scipy pcrb coldstarts load experiments homing placement offline stop demo standing rssi real)
sections=("$@")
[ ${#sections[@]} -eq 0 ] && sections=("${all[@]}")
for s in "${sections[@]}"; do
  [[ " ${all[*]} " == *" $s "* ]] || { echo "results.sh: unknown section '$s' (one of: ${all[*]})" >&2; exit 2; }
done
start_all=$(date +%s.%N)
bash "$repo/scripts/setup.sh" >/dev/null
bash "$repo/scripts/build.sh" all tests >/dev/null  # nodes, tools, benchmarks, experiment_check
# shellcheck disable=SC1091
source "$repo/scripts/env.sh"
cd "$repo"
bin="$RF_WS/devel/lib/radio_follow"
export ROS_HOME="${ROS_HOME:-$RF_WS/ros_home}"
port="${RF_RESULTS_PORT:-11751}"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
tables=(python3 "$repo/scripts/results_tables.py")

now() { date +%s.%N; }
elapsed() { awk -v a="$1" -v b="$(now)" 'BEGIN { printf "%.1f", b - a }'; }
heading() { printf '\n## %s\n\n' "$1"; }
# The command as a reader types it (from the clone, after `source scripts/env.sh`).
shown() { printf '    %s\n\n' "$*"; }
wanted() { [[ " ${sections[*]} " == *" $1 "* ]]; }

echo "# radio_follow results ($(date -u +%Y-%m-%d), commit $(git -C "$repo" rev-parse --short HEAD)$(git -C "$repo" diff --quiet || echo ', uncommitted changes'))"
echo
echo "$(nproc) CPUs, load average $(cut -d' ' -f1-3 /proc/loadavg) at the start. Regenerate: \`bash scripts/results.sh [section ...]\`."

if wanted accuracy; then
  heading "Locator accuracy against the Cramer-Rao bound (doc/locator_accuracy.md)"
  t0=$(now)
  shown '"$RF_WS"/devel/lib/radio_follow/lab locator_montecarlo --trials 200'
  "$bin/lab" locator_montecarlo --trials 200
  echo
  echo "The thesis's solve formulation (bench/thesis_solver.hpp) on the same measurements:"
  echo
  shown '"$RF_WS"/devel/lib/radio_follow/bench_thesis_accuracy --trials 200'
  "$bin/bench_thesis_accuracy" --trials 200
  echo
  echo "(accuracy: $(elapsed "$t0") s; the cold-solve times in the first table are timings, the rest is deterministic)"
fi

if wanted latency; then
  heading "Locator latency (doc/locator_accuracy.md#latency)"
  shown '"$RF_WS"/devel/lib/radio_follow/bench_locator_solve --benchmark_repetitions=5 --benchmark_report_aggregates_only=true'
  "$bin/bench_locator_solve" --benchmark_repetitions=5 --benchmark_report_aggregates_only=true \
    --benchmark_out="$tmp/bench.json" --benchmark_out_format=json >"$tmp/bench.txt" 2>&1
  "${tables[@]}" bench "$tmp/bench.json"
  echo
  echo "Baselines in the same run: the thesis's formulation (bench/thesis_solver.hpp) solved with"
  echo "the same Ceres options from the same warm starts (the locator's solve also computes the"
  echo "covariance its Kalman filter needs; the thesis's filter uses a fixed one); and"
  echo "Locator::update with the mirror test off (\`ambiguity_margin: 0\`)."
fi

if wanted scipy; then
  heading "Against the thesis's SciPy solve, same epochs (doc/locator_accuracy.md#against-the-thesiss-scipy-solve)"
  shown 'python3 bench/thesis_scipy.py "$RF_WS"/devel/lib/radio_follow/bench_scipy_baseline'
  python3 bench/thesis_scipy.py "$bin/bench_scipy_baseline"
fi

if wanted pcrb; then
  heading "Walking person against the posterior CRB (doc/locator_accuracy.md#walking-person-against-the-posterior-crb)"
  t0=$(now)
  shown '"$RF_WS"/devel/lib/radio_follow/lab locator_pcrb --runs 200'
  "$bin/lab" locator_pcrb --runs 200
  echo
  echo "(pcrb: $(elapsed "$t0") s; deterministic: fixed seed)"
fi

if wanted coldstarts; then
  heading "Locator cold starts and the reported covariance's consistency (doc/locator_accuracy.md#cold-starts)"
  t0=$(now)
  shown '(cd test && "$RF_WS"/devel/lib/radio_follow/lab locator_cold_starts --trials 10000)'
  (cd "$repo/test" && "$bin/lab" locator_cold_starts --trials 10000)
  echo
  shown '(cd test && "$RF_WS"/devel/lib/radio_follow/lab locator_cold_starts --trials 10000 --locator-overrides RSS.yaml)   # RSS.yaml: rss_direction: true'
  printf 'rss_direction: true\n' > "$tmp/rss.yaml"
  (cd "$repo/test" && "$bin/lab" locator_cold_starts --trials 10000 --locator-overrides "$tmp/rss.yaml")
  echo
  shown '(cd test && "$RF_WS"/devel/lib/radio_follow/lab locator_cold_starts --sensor-profile ideal --trials 2000)'
  (cd "$repo/test" && "$bin/lab" locator_cold_starts --sensor-profile ideal --trials 2000)
  echo
  echo "(coldstarts: $(elapsed "$t0") s; deterministic: fixed seeds)"
fi

if wanted load; then
  heading "Locator node load at 20 Hz, Spot layout (doc/locator_accuracy.md#node-load)"
  shown 'bash scripts/measure_locator_load.sh 30'
  bash scripts/measure_locator_load.sh 30
fi

if wanted experiments; then
  heading "Closed-loop experiments, lockstep (doc/experiments.md)"
  t0=$(now)
  shown 'bash scripts/experiments.sh'
  # Its own setup and build check print first: keep the table and what follows it.
  bash scripts/experiments.sh 2>&1 |
    grep -Ev '^(setup: |Base path: |(Source|Build|Devel|Install) space: |####|\[ *[0-9]+%\] |build: )'
  echo
  echo "(experiments: $(elapsed "$t0") s, build check included)"
fi

if wanted homing; then
  heading "Homing, seed 000 Tables 2-3 (doc/homing_experiment.md)"
  shown '"$RF_WS"/devel/lib/radio_follow/lab homing_experiment'
  "$bin/lab" homing_experiment
  echo
  shown '"$RF_WS"/devel/lib/radio_follow/lab homing_experiment --arrival 0.15'
  "$bin/lab" homing_experiment --arrival 0.15
  echo
  echo "Five target sets at the 0.3 m radius, the node's goal (all_readings) and the hybrid rule's (seed000):"
  echo
  printf 'goal_estimator: seed000\n' >"$tmp/seed000.yaml"
  shown "printf 'goal_estimator: seed000\\n' > /tmp/seed000.yaml; for s in 1 2 3 4 5; do \"\$RF_WS\"/devel/lib/radio_follow/lab homing_experiment --seed \$s [--params /tmp/seed000.yaml]; done"
  for estimator in all_readings seed000; do
    params=()
    [[ "$estimator" == seed000 ]] && params=(--params "$tmp/seed000.yaml")
    for s in 1 2 3 4 5; do "$bin/lab" homing_experiment --seed "$s" "${params[@]}" >"$tmp/homing5_$s.md"; done
    echo "$estimator:"
    echo
    "${tables[@]}" homing-range "$tmp"/homing5_{1,2,3,4,5}.md
    echo
  done
  echo "Ten target sets, range of the ten values:"
  echo
  shown 'for s in $(seq 1 10); do "$RF_WS"/devel/lib/radio_follow/lab homing_experiment --arrival 0.15 --seed $s; done'
  for s in $(seq 1 10); do "$bin/lab" homing_experiment --arrival 0.15 --seed "$s" >"$tmp/homing_$s.md"; done
  "${tables[@]}" homing-range "$tmp"/homing_{1,2,3,4,5,6,7,8,9,10}.md
  echo
  echo "Obstacle avoidance, seed 000 Table 4's analogue (configuration 5, 12 obstacles per run), five target sets:"
  echo
  shown 'for s in 1 2 3 4 5; do "$RF_WS"/devel/lib/radio_follow/lab homing_experiment --obstacles 12 --seed $s; done'
  for s in 1 2 3 4 5; do
    echo "target set $s:"
    echo
    "$bin/lab" homing_experiment --obstacles 12 --seed "$s"
    echo
  done
  echo "The same with a robot of radius 0.3 m (the paper's thresholds leave too little room):"
  echo
  shown '"$RF_WS"/devel/lib/radio_follow/lab homing_experiment --obstacles 12 --robot-radius 0.3'
  "$bin/lab" homing_experiment --obstacles 12 --robot-radius 0.3
  echo
  echo "Seed 000's law as published (the hybrid rule's goal, range_step 0: no step along the line of sight), on the benchmark:"
  echo
  printf 'goal_estimator: seed000\nrange_step: 0.0\n' >"$tmp/paper_law.yaml"
  shown "printf 'goal_estimator: seed000\\nrange_step: 0.0\\n' > /tmp/paper_law.yaml; \"\$RF_WS\"/devel/lib/radio_follow/lab homing_experiment --params /tmp/paper_law.yaml"
  "$bin/lab" homing_experiment --params "$tmp/paper_law.yaml"
  echo
  echo "A lower eq 14 threshold (doc/control/homing.md) instead of the range step, on the benchmark:"
  echo
  printf 'goal_estimator: seed000\nrange_step: 0.0\nerror_threshold: 0.1\n' >"$tmp/threshold.yaml"
  shown "printf 'goal_estimator: seed000\\nrange_step: 0.0\\nerror_threshold: 0.1\\n' > /tmp/threshold.yaml; \"\$RF_WS\"/devel/lib/radio_follow/lab homing_experiment --params /tmp/threshold.yaml"
  "$bin/lab" homing_experiment --params "$tmp/threshold.yaml"
  echo
  echo "The law's parameters one at a time (configuration 5's goal error against the paper's 0.11 m):"
  echo
  shown 'bash scripts/homing_sweep.sh'
  bash "$repo/scripts/homing_sweep.sh"
  echo
  echo "Through the ROS nodes against the simulator (4 x real time; ROS message timing varies),"
  echo "with the node's law (all_readings), the hybrid rule with the range step (seed000 0.5 0.3),"
  echo "the paper's law (seed000 0 0.3) and the paper's with error_threshold 0.1:"
  echo
  shown 'RF_SEED=N rostest --text radio_follow homing_static_beacon.test [goal_estimator:=seed000] [range_step:=0.0] [error_threshold:=0.1]   # N = 1, 2, 3'
  echo "| seed | goal_estimator | range_step | error_threshold | passed | first arrival logged (s, simulated) | final gap (m) | goal error (m) | wall (s) | simulated duration / 4 (s) | wall / ideal |"
  echo "|---|---|---|---|---|---|---|---|---|---|---|"
  for law in "all_readings 0.5 0.3" "seed000 0.5 0.3" "seed000 0.0 0.3" "seed000 0.0 0.1"; do
    read -r estimator step threshold <<<"$law"
    for seed in 1 2 3; do
      t0=$(now)
      passed=yes
      RF_SEED=$seed rostest --text radio_follow homing_static_beacon.test goal_estimator:=$estimator range_step:=$step error_threshold:=$threshold >"$tmp/homing_ros.log" 2>&1 || passed=no
      grep -q '^OK$' "$tmp/homing_ros.log" || passed=no
      wall=$(elapsed "$t0")
      metrics="$ROS_HOME/radio_follow_experiments/homing_static_beacon/metrics.json"
      # ROS_INFO on simulated time: "[ INFO] [wall, sim]: Arrived at the target."
      arrival=$(grep -m1 'Arrived at the target' "$tmp/homing_ros.log" | sed -n 's/^[^[]*\[[^]]*\] \[[0-9.]*, \([0-9]*\.[0-9]\{0,2\}\).*/\1/p')
      goal=$(grep -m1 '^goal error:' "$tmp/homing_ros.log" | awk '{printf "%.3f", $3}')
      read -r gap duration < <(python3 -c 'import json,sys; m=json.load(open(sys.argv[1])); print("%.3f %.1f" % (m["final_gap_m"], m["duration_s"]))' "$metrics")
      awk -v s="$seed" -v est="$estimator" -v k="$step" -v th="$threshold" -v p="$passed" -v a="${arrival:--}" -v g="$gap" -v e="${goal:--}" -v w="$wall" -v d="$duration" \
        'BEGIN { printf "| %s | %s | %s | %s | %s | %s | %s | %s | %s | %.1f | %.2f |\n", s, est, k, th, p, a, g, e, w, d / 4, w / (d / 4) }'
    done
  done
fi

if wanted placement; then
  heading "Placement advisor, position bound of the shipped layouts (doc/placement_advisor.md)"
  shown 'for layout in spot spot_twr tracked cube; do rosrun radio_follow placement_advisor config/layouts/$layout.yaml --out /tmp/advisor_$layout; rosrun radio_follow placement_advisor config/layouts/$layout.yaml --3d --out /tmp/advisor3d_$layout; done'
  for layout in spot spot_twr tracked cube; do
    "$bin/placement_advisor" "config/layouts/$layout.yaml" --out "$tmp/advisor" >/dev/null
    "$bin/placement_advisor" "config/layouts/$layout.yaml" --3d --out "$tmp/advisor3d" >/dev/null
  done
  echo "sqrt(trace CRLB), median / worst over the ring, metres; warnings: how many (the tool's output lists them):"
  echo
  "${tables[@]}" placement "$tmp/advisor" "$tmp/advisor3d"
  echo
  shown 'rosrun radio_follow placement_advisor config/layouts/spot_twr.yaml --compare config/layouts/spot.yaml --out /tmp/advisor'
  "$bin/placement_advisor" config/layouts/spot_twr.yaml --compare config/layouts/spot.yaml \
    --out "$tmp/compare" | grep 'median bound ratio'
  # The optimiser (doc/placement_advisor.md#optimisation): its Markdown tables, the ratio of
  # the reference's median bound to the optimised layout's, and the bound along a walk.
  optimise() {
    shown "rosrun radio_follow placement_advisor --optimise $* --out /tmp/opt"
    "$bin/placement_advisor" --optimise "$@" --out "$tmp/opt" 2>&1 | grep -E '^\||refused|median bound ratio|no run reached'
    echo
  }
  heading "Placement optimiser: the objective (seed 004 Table 5.1)"
  optimise config/placement/spot_region.yaml --boards 0 --method exhaustive --objective all --compare config/layouts/spot_twr.yaml
  heading "Placement optimiser: exhaustive, greedy and random search"
  optimise config/placement/tracked_region.yaml --boards 0 --method all --runs 3 --max-combinations 2e7 --compare config/layouts/tracked.yaml
  heading "Placement optimiser: fewest sensors for a limit (seed 004 Tables 5.2 and 5.3)"
  optimise config/placement/tracked_region.yaml --modules 3 --boards 0 --grow modules --limit 0.35 --method random --samples 500 --runs 5
  optimise config/placement/tracked_region.yaml --modules 0 --boards 1 --grow boards --limit 0.35 --method random --samples 500 --runs 5
  optimise config/placement/tracked_region.yaml --modules 1 --boards 1 --grow both --limit 0.15 --method random --samples 500 --runs 10
  heading "Placement optimiser: the shipped robots' regions against their layouts"
  for robot in spot tracked; do
    optimise "config/placement/${robot}_region.yaml" --method all --compare "config/layouts/$robot.yaml"
    cp "$tmp/opt/${robot}_optimised.yaml" "$tmp/${robot}_optimised.yaml"
  done
  shown '"$RF_WS"/devel/lib/radio_follow/lab locator_pcrb --layouts spot,/tmp/opt/spot_optimised.yaml,tracked,/tmp/opt/tracked_optimised.yaml --paths straight,arc --runs 20'
  "$bin/lab" locator_pcrb --layouts "spot,$tmp/spot_optimised.yaml,tracked,$tmp/tracked_optimised.yaml" \
    --paths straight,arc --runs 20
fi

if wanted offline; then
  heading "Offline evaluation on the shipped bag (doc/offline_evaluation.md#measured)"
  bag=test/data/sim_spot_straight.bag
  shown "\"\$RF_WS\"/devel/lib/radio_follow/locator_offline $bag --layout config/layouts/spot.yaml --params config/locator.yaml --out /tmp/eval"
  runs=()
  for i in 1 2 3 4 5; do
    t0=$(now)
    "$bin/locator_offline" "$bag" --layout config/layouts/spot.yaml --params config/locator.yaml \
      --out "$tmp/eval" >"$tmp/offline_$i.log"
    runs+=("$(elapsed "$t0")")
  done
  cat "$tmp/offline_1.log" | grep -v '^wrote'
  echo
  echo 'The same replay in the robot frame (`odom_frame: ""` on top: the TF in the bag is not used):'
  echo
  printf 'odom_frame: ""\n' >"$tmp/robot_frame.yaml"
  shown "\"\$RF_WS\"/devel/lib/radio_follow/locator_offline $bag --layout config/layouts/spot.yaml --params config/locator.yaml --params ROBOT_FRAME.yaml   # ROBOT_FRAME.yaml: odom_frame: \"\""
  "$bin/locator_offline" "$bag" --layout config/layouts/spot.yaml --params config/locator.yaml \
    --params "$tmp/robot_frame.yaml" | grep -E '^(tracking|updates|error)'
  read -r replay speed speed_lo speed_hi < <("${tables[@]}" offline-speed "$tmp"/offline_?.log)
  whole=$("${tables[@]}" median "${runs[@]}")
  length=$(sed -n 's/^bag [^:]*: \([0-9.]*\) s,.*/\1/p' "$tmp/offline_1.log")
  cat >"$tmp/grid.yaml" <<'YAML'
range_sigma: [0.03, 0.05, 0.07, 0.1]
azimuth_sigma_deg: [2.0, 5.0, 10.0]
bearing_loss: [huber, cauchy]
YAML
  echo
  echo "The sweep of the page (24 settings, the grid file of doc/offline_evaluation.md):"
  echo
  shown "\"\$RF_WS\"/devel/lib/radio_follow/locator_offline $bag --layout config/layouts/spot.yaml --params config/locator.yaml --sweep GRID.yaml"
  t0=$(now)
  "$bin/locator_offline" "$bag" --layout config/layouts/spot.yaml --params config/locator.yaml \
    --sweep "$tmp/grid.yaml" >"$tmp/sweep.csv"
  sweep=$(elapsed "$t0")
  head -n 4 "$tmp/sweep.csv"
  echo "..."
  tail -n 2 "$tmp/sweep.csv"
  echo
  echo "The shipped defaults' row (config/locator.yaml: range_sigma 0.07, azimuth_sigma_deg 5, bearing_loss huber):"
  echo
  grep '"range_sigma=0.07 azimuth_sigma_deg=5.0 bearing_loss=huber"' "$tmp/sweep.csv"
  echo
  echo "The bag (\`rosbag info $bag\`):"
  echo
  rosbag info "$bag" | grep -E '^(duration|size|messages|compression|uncompressed|compressed):' | sed 's/^/    /'
  echo
  echo "Speed, five runs of the single replay (median; bag length ${length} s):"
  echo
  echo "| | wall time (s) | x real time | ratio |"
  echo "|---|---|---|---|"
  awk -v r="$replay" -v s="$speed" -v lo="$speed_lo" -v hi="$speed_hi" -v w="$whole" -v l="$length" -v sw="$sweep" 'BEGIN {
    printf "| locator replay alone (printed by the tool) | %.4f | %d (%d-%d) | 1 (baseline) |\n", r, s, lo, hi
    printf "| whole command, bag reading and process start included | %.2f | %d | %.1f x the replay |\n", w, l / w, w / r
    printf "| the 24-setting sweep, bag read once | %.2f | %d per setting | %.2f x one whole command per setting |\n", sw, 24 * l / sw, sw / 24 / w
  }'
fi

if wanted stop; then
  heading "Safety stop latency (doc/time.md#the-safety-path-never-waits)"
  shown 'bash scripts/bench_stop_latency.sh 40'
  RF_BENCH_PORT="$port" bash scripts/bench_stop_latency.sh 40
fi

if wanted demo; then
  heading "Demo run, wall time (doc/results.md)"
  shown "roslaunch -p $port radio_follow demo.launch report_dir:=/tmp/demo   # what scripts/demo.sh runs after setup and build"
  t0=$(now)
  roslaunch -p "$port" radio_follow demo.launch report_dir:="$tmp/demo" >"$tmp/demo.log" 2>&1
  wall=$(elapsed "$t0")
  python3 - "$tmp/demo/metrics.json" "$wall" <<'PY'
import json, sys
m = json.load(open(sys.argv[1]))
wall = float(sys.argv[2])
ideal = m["duration_s"] / 4.0
print("| closed loop passed | simulated duration (s) | ideal wall at 4 x (s) | wall, roslaunch start to end (s) | wall / ideal |")
print("|---|---|---|---|---|")
print("| %s | %.1f | %.1f | %.1f | %.2f |" % (m["passed"], m["duration_s"], ideal, wall, wall / ideal))
PY
fi

if wanted standing; then
  heading "Thesis Experiments 1-2, the robot standing (doc/standing_experiments.md)"
  t0=$(now)
  for experiment in static walk; do
    for layout in spot tracked cube spot_tdoa; do
      shown "\"\$RF_WS\"/devel/lib/radio_follow/lab standing_experiments --experiment $experiment --layout $layout"
      "$bin/lab" standing_experiments --experiment "$experiment" --layout "$layout"
      echo
    done
  done
  # The TDoA heading mode on eight simulated robots: the whole-walk line of each.
  for robot in 2 3 4 5 6 7 8; do
    shown "\"\$RF_WS\"/devel/lib/radio_follow/lab standing_experiments --experiment walk --layout spot_tdoa --robot $robot | tail -1"
    "$bin/lab" standing_experiments --experiment walk --layout spot_tdoa --robot "$robot" | tail -1
  done
  # Issue 35's bench: one board alone, the person walking and standing in front of it.
  echo
  shown "\"\$RF_WS\"/devel/lib/radio_follow/lab standing_experiments --experiment heading --walks 1000"
  "$bin/lab" standing_experiments --experiment heading --walks 1000
  echo
  shown "\"\$RF_WS\"/devel/lib/radio_follow/lab standing_experiments --experiment heading --walks 1000 --layout xplr_kit"
  "$bin/lab" standing_experiments --experiment heading --walks 1000 --layout xplr_kit
  echo "(standing: $(elapsed "$t0") s; deterministic)"
fi

if wanted rssi; then
  heading "RSSI filters and seed 002's trilateration (doc/rssi_filters.md)"
  shown '"$RF_WS"/devel/lib/radio_follow/lab rssi_filter_compare'
  "$bin/lab" rssi_filter_compare
  echo
  shown '"$RF_WS"/devel/lib/radio_follow/lab trilateration_compare'
  "$bin/lab" trilateration_compare
  echo
  echo "(rssi: deterministic but for the trilateration timings, which are ratios measured in the same run)"
fi

if wanted real; then
  heading "Real UWB recordings (doc/real_recordings.md)"
  t0=$(now)
  printf 'range_decorrelation_time: 0.5\n' > "$tmp/decorrelation.yaml"
  echo "(DECORRELATION.yaml below: \`range_decorrelation_time: 0.5\`)"
  for args in "" "--calibrate" "--params config/locator_standing.yaml" \
    "--params config/locator_standing.yaml --calibrate" \
    "--params config/locator_standing.yaml --params DECORRELATION.yaml" \
    "--runs static" "--runs static --params config/locator_standing.yaml"; do
    shown "python3 scripts/real_recordings.py $args"
    # shellcheck disable=SC2086
    python3 scripts/real_recordings.py --work "$tmp/real" ${args//DECORRELATION.yaml/$tmp/decorrelation.yaml}
    echo
  done
  echo "The standing mode's cold starts (the robot and the person standing: doc/locator_accuracy.md#cold-starts), with its file and with the shipped covariance floor (SHIPPED_FLOOR.yaml: the file with range_bias_sigma: 0.05 and azimuth_bias_sigma_deg: 2.0):"
  shown '(cd test && "$RF_WS"/devel/lib/radio_follow/lab locator_cold_starts --trials 10000 --locator-overrides ../config/locator_standing.yaml)'
  (cd "$repo/test" && "$bin/lab" locator_cold_starts --trials 10000 --locator-overrides ../config/locator_standing.yaml)
  sed -e 's/^range_bias_sigma:.*/range_bias_sigma: 0.05/' \
    -e 's/^azimuth_bias_sigma_deg:.*/azimuth_bias_sigma_deg: 2.0/' config/locator_standing.yaml >"$tmp/shipped_floor.yaml"
  shown '(cd test && "$RF_WS"/devel/lib/radio_follow/lab locator_cold_starts --trials 10000 --locator-overrides SHIPPED_FLOOR.yaml)'
  (cd "$repo/test" && "$bin/lab" locator_cold_starts --trials 10000 --locator-overrides "$tmp/shipped_floor.yaml")
  echo
  echo "What the standing mode costs a walking person (the Gaussian walking-person benchmark):"
  shown '"$RF_WS"/devel/lib/radio_follow/lab locator_pcrb --runs 200 --locator-overrides config/locator_standing.yaml'
  "$bin/lab" locator_pcrb --runs 200 --locator-overrides config/locator_standing.yaml
  echo
  echo "... and with DECORRELATION.yaml on top (BEACON.yaml: both files' keys):"
  cat config/locator_standing.yaml "$tmp/decorrelation.yaml" > "$tmp/beacon.yaml"
  shown '"$RF_WS"/devel/lib/radio_follow/lab locator_pcrb --runs 200 --locator-overrides BEACON.yaml'
  "$bin/lab" locator_pcrb --runs 200 --locator-overrides "$tmp/beacon.yaml"
  echo
  echo "(real: $(elapsed "$t0") s; deterministic)"
fi

printf '\n(results.sh: %s s of wall time)\n' "$(elapsed "$start_all")"
