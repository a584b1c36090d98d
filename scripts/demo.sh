#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# README command 1: install, build and run the simulated follow-me demo headless, then
# draw its report. `bash scripts/demo.sh --help` says what it takes and reads.
set -euo pipefail
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"

shipped() { # the names of config/<dir>/*.yaml, on one line
  local f names=()
  for f in "$repo/config/$1"/*.yaml; do
    names+=("$(basename "$f" .yaml)")
  done
  echo "${names[*]}"
}

usage() {
  cat <<EOF
Usage: bash scripts/demo.sh [-h|--help] [NAME:=VALUE ...]

Installs missing Debian packages (scripts/setup.sh), builds the workspace
(scripts/build.sh), then runs launch/demo.launch headless on a private master: the
simulator, the locator, a controller and the follow evaluator in closed loop on
simulated time. When the scenario ends it draws report.png and prints metrics.json.

Exit status: 0 when the evaluator's verdict is "closed loop OK"; 1 when the verdict is
CLOSED LOOP FAILED, when any node dies (the launch is stopped at once, although it would
respawn the locator and the controller; the node's name and its last FATAL/ERROR lines
are printed), when the run outlasts its time bound (RF_DEMO_TIMEOUT), or when an
argument names a missing layout, layout file or scenario (checked before set-up and
build); 130 on Ctrl-C, which stops the launch too.

Arguments, passed on to roslaunch (every one: roslaunch --ros-args radio_follow demo.launch):
  layout:=NAME        a shipped layout, config/layouts/NAME.yaml (default spot):
                      $(shipped layouts)
                      A value with a '/' or ending in .yaml is taken as layout_file.
  layout_file:=PATH   your own robot's layout YAML (doc/deployment.md); wins over layout.
                      Relative and ~ paths are made absolute here: the nodes run in
                      ROS_HOME, where a relative path means nothing.
  scenario:=NAME      config/scenarios/NAME.yaml (default outdoor_loop):
                      $(shipped scenarios)
  controller:=NAME    velocity_controller (default) or path_follower
  seed:=N             random seed of the simulated noise (default: config/simulator.yaml's)
  time_factor:=F      simulated seconds per wall second (default 4.0)
  serial:=true        the real serial drivers on simulated pseudo-terminals
  rviz:=true          open rviz with config/demo.rviz (needs Debian's rviz)
  report_dir:=DIR     the same as RF_REPORT_DIR=DIR

Environment:
  RF_DEMO_PORT     the private master's port (default 11411), so the demo never joins
                   or disturbs a robot's running master
  RF_REPORT_DIR    write the report into this directory, replacing the files of an
                   earlier run there. Default: a new report/demo/<UTC time>/ for every
                   run, with report/demo/latest pointing to the newest (nothing is
                   overwritten; delete old runs with rm -r report/demo)
  RF_DEMO_TIMEOUT  the wall-clock bound of the launch in seconds. Default: 120 + 4 x the
                   scenario's simulated length / time_factor, as the simulator announces
                   them at start (straight_walk, 39 s at x4: 159 s); 600 until it has
  ROS_HOME         where the nodes run and ROS writes its logs (default \$RF_WS/ros_home)
  RF_WS            the catkin workspace (default
                   \${XDG_CACHE_HOME:-~/.cache}/radio_follow/ws-<clone>-<hash>)
  RF_JOBS, RF_BUILD_TYPE  for scripts/build.sh: make jobs (default nproc), CMake build
                   type (default Release)

Report files: metrics.json and trajectory.csv (the evaluator), report.png (the plot),
launch.log (everything roslaunch and the nodes printed).

Examples:
  bash scripts/demo.sh scenario:=straight_walk controller:=path_follower layout:=tracked
  bash scripts/demo.sh layout_file:=~/my_robot.yaml scenario:=straight_walk
  RF_REPORT_DIR=/tmp/run1 RF_DEMO_PORT=11611 bash scripts/demo.sh seed:=2
EOF
}

fail() {
  echo "demo: $*" >&2
  exit 1
}

absolute() { # ~, ~/x, ~user/x and relative paths made absolute (symlinks kept)
  local path="$1" user home
  case "$path" in
    \~ | \~/*) path="$HOME${path:1}" ;;
    \~*)
      user="${path%%/*}"
      user="${user#"~"}"
      home="$(getent passwd "$user" | cut -d: -f6 || true)"
      [ -n "$home" ] && path="$home${path#"~$user"}"
      ;;
  esac
  case "$path" in /*) ;; *) path="$PWD/$path" ;; esac
  realpath -m -s -- "$path"
}

# Arguments are checked before set-up and build, so that a typo fails at once.
for arg in "$@"; do
  case "$arg" in -h | --help) usage; exit 0 ;; esac
done
layout="" layout_file="" scenario="outdoor_loop" report="${RF_REPORT_DIR:-}"
launch_args=()
for arg in "$@"; do
  case "$arg" in
    layout:=*) layout="${arg#layout:=}" ;;
    layout_file:=*) layout_file="${arg#layout_file:=}" ;;
    report_dir:=*) report="${arg#report_dir:=}" ;;
    scenario:=*) scenario="${arg#scenario:=}"; launch_args+=("$arg") ;;
    *) launch_args+=("$arg") ;;
  esac
done
if [[ "$layout" == */* || "$layout" == *.yaml || "$layout" == "~"* ]]; then
  [ -z "$layout_file" ] || fail "layout:=$layout looks like a file and layout_file:= is given too; give one"
  echo "demo: note: layout:= takes a name under config/layouts/; using layout_file:=$layout" >&2
  layout_file="$layout" layout=""
fi
if [ -n "$layout_file" ]; then
  [ -z "$layout" ] || echo "demo: note: layout_file:= wins; layout:=$layout is ignored" >&2
  path="$(absolute "$layout_file")"
  if [ ! -f "$path" ] || [ ! -r "$path" ]; then
    hint=""
    [ -f "$repo/config/layouts/$(basename "$path")" ] &&
      hint=" (the shipped layout is layout:=$(basename "$path" .yaml))"
    fail "layout file '$layout_file' does not exist or is not readable: $path$hint"
  fi
  launch_args+=("layout_file:=$path")
elif [ -n "$layout" ]; then
  [ -f "$repo/config/layouts/$layout.yaml" ] ||
    fail "no layout '$layout' in config/layouts/; shipped: $(shipped layouts) (your own robot's file: layout_file:=PATH)"
  launch_args+=("layout:=$layout")
fi
[ -f "$repo/config/scenarios/$scenario.yaml" ] ||
  fail "no scenario '$scenario' in config/scenarios/; shipped: $(shipped scenarios)"
[ -z "$report" ] || report="$(absolute "$report")"
port="${RF_DEMO_PORT:-11411}"
[[ "$port" =~ ^[0-9]+$ ]] || fail "RF_DEMO_PORT='$port': expected a port number"
fixed_bound="${RF_DEMO_TIMEOUT:-}"
[[ -z "$fixed_bound" || "$fixed_bound" =~ ^[1-9][0-9]*$ ]] ||
  fail "RF_DEMO_TIMEOUT='$fixed_bound': expected whole seconds > 0"

bash "$repo/scripts/setup.sh"
bash "$repo/scripts/build.sh"
# shellcheck disable=SC1091
source "$repo/scripts/env.sh"
export ROS_HOME="${ROS_HOME:-$RF_WS/ros_home}"

# The report directory: the user's (earlier files replaced) or a new one per run.
if [ -n "$report" ]; then
  mkdir -p "$report"
  rm -f "$report"/{metrics.json,trajectory.csv,report.png,launch.log}
else
  runs="$repo/report/demo"
  mkdir -p "$runs"
  rm -f "$runs"/{metrics.json,trajectory.csv,report.png} # written there before runs had folders
  stamp="$(date -u +%Y%m%dT%H%M%SZ)"
  report="$runs/$stamp"
  n=1
  until mkdir "$report" 2>/dev/null; do
    n=$((n + 1))
    report="$runs/$stamp-$n"
  done
  ln -sfn "$(basename "$report")" "$runs/latest"
fi
log="$report/launch.log"

# Every process of the launch carries RF_DEMO_RUN in its environment: roslaunch starts
# each node in a session of its own, and a roslaunch that crashes leaves them running
# (a master among them), so neither its process group nor its children find them all.
run_tag="RF_DEMO_RUN=$$-$(date +%s%N)"
launch_pid="" tee_pid=""

launch_processes() { # pids of the processes that carry this run's tag
  grep -lsxzF "$run_tag" /proc/[0-9]*/environ | cut -d/ -f3 || true
}

process_names() { # a node's __name:=, else the command's name
  local pid name
  for pid in "$@"; do
    name="$(tr '\0' '\n' <"/proc/$pid/cmdline" 2>/dev/null | sed -n 's/^__name:=//p' || true)"
    echo "${name:-$(ps -o comm= -p "$pid" || true)}"
  done | paste -sd' '
}

stop_launch() { # SIGINT to roslaunch as Ctrl-C sends, then an end to what it left
  [ -n "$launch_pid" ] || return 0
  kill -INT "$launch_pid" 2>/dev/null || true
  # roslaunch gives its nodes 15 s after SIGINT, then SIGTERM: 30 s is plenty.
  for _ in $(seq 60); do
    kill -0 "$launch_pid" 2>/dev/null || break
    sleep 0.5
  done
  kill -KILL "$launch_pid" 2>/dev/null && echo "demo: roslaunch ignored SIGINT for 30 s; killed it" >&2
  wait "$launch_pid" 2>/dev/null || true
  launch_pid=""
  local left
  left="$(launch_processes)"
  if [ -n "$left" ]; then
    # shellcheck disable=SC2086 # one pid a word
    echo "demo: roslaunch left these running; stopping them: $(process_names $left)" >&2
    # shellcheck disable=SC2086
    kill -TERM $left 2>/dev/null || true
    for _ in $(seq 10); do
      [ -n "$(launch_processes)" ] || break
      sleep 0.5
    done
    left="$(launch_processes)"
    # shellcheck disable=SC2086
    [ -z "$left" ] || kill -KILL $left 2>/dev/null || true
  fi
  wait_for_tee
}

wait_for_tee() { # so that the launch's last lines come before the verdict
  [ -n "$tee_pid" ] || return 0
  for _ in $(seq 50); do
    kill -0 "$tee_pid" 2>/dev/null || return 0
    sleep 0.1
  done
}

plain_log() { sed 's/\x1b\[[0-9;]*m//g' "$log"; }

died_node() { # "name exit-code" of the first node that died, from roslaunch's lines
  # (no early exit in awk: with pipefail, sed's SIGPIPE would end the script)
  plain_log | awk '
    found != "" { next }
    /REQUIRED process \[/ { required = $0; sub(/.*REQUIRED process \[/, "", required)
                            sub(/\].*/, "", required); next }
    /\] process has died \[/ { found = $0; sub(/\] process has died \[.*/, "", found)
                               sub(/.*\[/, "", found) }
    /^process has died \[/ && required != "" { found = required }
    found != "" { code = $0; sub(/.*exit code /, "", code); sub(/[^-0-9].*/, "", code) }
    { required = "" }
    END { if (found != "") { sub(/-[0-9]+$/, "", found); print found, code } }'
}

reasons() { # what the node said before it died: its FATAL/ERROR lines and other output
  # naming it (a loader's "symbol lookup error"), else any node's last FATAL/ERROR lines
  local before lines
  before="$(plain_log | awk '/process has died \[/ { dead = 1 } !dead')"
  lines="$(grep -E "[ /]$1:" <<<"$before" | grep -vE '^\[ *(INFO|WARN|DEBUG)\]' |
    sed 's/^\[ *\([A-Z]*\)\] \[[0-9., ]*\]: /\1 /' | tail -n 3 || true)"
  if [ -z "$lines" ]; then
    lines="$(grep -E '^\[ *(FATAL|ERROR)\]' <<<"$before" | tail -n 3 || true)"
    [ -z "$lines" ] || echo "(nothing of its own; the last errors of any node:)"
  fi
  echo "${lines:-(nothing on the screen; its own log is under $ROS_HOME/log/latest/)}"
}

announced_bound() { # 120 s + 4 x the scenario's length / time_factor, from the simulator
  plain_log | sed -n "s/.*simulator: scenario '[^']*' (\([0-9.]*\) s),.* time x\([0-9.]*\),.*/\1 \2/p" |
    awk 'NR == 1 && $2 > 0 { printf "%d\n", 120 + 4 * $1 / $2 + 0.999 }'
}

fail_if_died() { # after the launch is stopped: the first dead node and what it said
  local died
  died="$(died_node)"
  [ -n "$died" ] || return 0
  echo "demo: node '${died% *}' died (exit code ${died#* }), so the demo ended (log: $log). It said:" >&2
  reasons "${died% *}" | sed 's/^/  /' >&2
  exit 1
}

trap 'stop_launch' EXIT
trap 'echo "demo: interrupted; stopping the launch" >&2; stop_launch; exit 130' INT
trap 'stop_launch; exit 143' TERM

# roslaunch runs in a session of its own, so that only the demo sends it Ctrl-C's SIGINT;
# its output goes to the terminal and to the log through tee, which ignores Ctrl-C to
# show the launch's shutdown. Unbuffered, so that a death is seen when it is printed.
export PYTHONUNBUFFERED=1 ROSCONSOLE_STDOUT_LINE_BUFFERED=1
exec 3> >(trap '' INT; exec tee "$log")
tee_pid=$!
# A private master port, so the demo never joins (or disturbs) a robot's running master.
env "$run_tag" setsid roslaunch -p "$port" radio_follow demo.launch report_dir:="$report" \
  "${launch_args[@]}" >&3 2>&1 &
launch_pid=$!
exec 3>&-

# The time bound: RF_DEMO_TIMEOUT, else derived from the scenario once the simulator
# has announced it (600 s until then).
start=$SECONDS
bound="${fixed_bound:-600}"
awaiting_scenario=true
[ -z "$fixed_bound" ] || awaiting_scenario=false
while kill -0 "$launch_pid" 2>/dev/null; do
  if [ -n "$(died_node)" ]; then
    stop_launch
    fail_if_died
  fi
  if $awaiting_scenario; then
    announced="$(announced_bound)"
    if [ -n "$announced" ]; then
      bound="$announced" awaiting_scenario=false
      echo "demo: the launch must end within $bound s of its start (120 s + 4 x the scenario's length / time_factor; RF_DEMO_TIMEOUT sets the bound)"
    fi
  fi
  if ((SECONDS - start > bound)); then
    stop_launch
    fail "the launch ran longer than its bound of $bound s (RF_DEMO_TIMEOUT sets it), so the demo stopped it (log: $log)"
  fi
  sleep 0.5
done
status=0
wait "$launch_pid" || status=$?
stop_launch # whatever of the launch is left, and tee's last lines
fail_if_died
[ "$status" -eq 0 ] || fail "roslaunch exited with status $status (log: $log)"

if [ ! -s "$report/metrics.json" ]; then
  fail "no report was written to $report (log: $log)"
fi
/usr/bin/python3 "$repo/scripts/plot_report.py" "$report"
echo "demo: report in $report (metrics.json, trajectory.csv, report.png, launch.log)"
cat "$report/metrics.json"
# roslaunch exits 0 whatever its nodes did; the verdict is the evaluator's (doc/simulator.md).
if ! /usr/bin/python3 -c 'import json, sys; sys.exit(0 if json.load(open(sys.argv[1]))["passed"] else 1)' \
    "$report/metrics.json"; then
  echo "demo: CLOSED LOOP FAILED: $(/usr/bin/python3 -c 'import json, sys; print("; ".join(json.load(open(sys.argv[1]))["failures"]))' "$report/metrics.json")" >&2
  exit 1
fi
