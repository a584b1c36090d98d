#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# The full message fuzz (issue 34, item 2): every node type that subscribes to anything,
# started as its rostest test/ros/message_fuzz_<name>.test starts it (shipped parameter
# files), each on its own fresh master, fuzzed by scripts/fuzz_messages.py with COUNT
# messages. Prints each run's summary and a table; exits 1 when any run failed.
#   bash scripts/fuzz_nodes.sh [count] [name...]   default 100000, every message_fuzz_*.test
# RF_FUZZ_PORT: the master port (default 11511); RF_FUZZ_SEED: the seed (default 1).
set -euo pipefail
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
export PATH="/usr/bin:$PATH"
# shellcheck disable=SC1091
source "$repo/scripts/env.sh" >/dev/null
count="${1:-100000}"
shift || true
port="${RF_FUZZ_PORT:-11511}"
seed="${RF_FUZZ_SEED:-1}"
export ROS_MASTER_URI="http://localhost:$port"
export ROS_HOME="${ROS_HOME:-$RF_WS/ros_home}"
mkdir -p "$ROS_HOME"
if [ $# -gt 0 ]; then
  names=("$@")
else
  names=()
  for f in "$repo"/test/ros/message_fuzz_*.test; do
    n="$(basename "$f" .test)"
    names+=("${n#message_fuzz_}")
  done
fi
summary="$ROS_HOME/message_fuzz_summary.jsonl"
: >"$summary"
# Generous: the fuzzer is bounded at 1000 messages/s; a loaded machine may manage 50.
time_limit=$((300 + count / 50))
core=""
cleanup() { if [ -n "$core" ]; then kill "$core" 2>/dev/null || true; wait "$core" 2>/dev/null || true; fi; }
trap cleanup EXIT
status=0
for name in "${names[@]}"; do
  roscore -p "$port" >"$ROS_HOME/message_fuzz_roscore.log" 2>&1 &
  core=$!
  for _ in $(seq 100); do rosparam list >/dev/null 2>&1 && break; sleep 0.3; done
  start=$(date +%s)
  rostest --reuse-master radio_follow "message_fuzz_$name.test" count:="$count" seed:="$seed" \
    time_limit:="$time_limit" summary_file:="$summary" >"$ROS_HOME/message_fuzz_$name.log" 2>&1 ||
    status=1
  echo "message_fuzz_$name: $(($(date +%s) - start)) s, log $ROS_HOME/message_fuzz_$name.log"
  kill "$core"
  wait "$core" 2>/dev/null || true
  core=""
done
python3 - "$summary" "${names[@]}" <<'PY' || status=1
import json, sys
runs = [json.loads(line) for line in open(sys.argv[1], encoding="utf-8")]
for r in runs:
    print(r["line"])
    for f in r["findings"] + r["harness_errors"]:
        print("  " + f[:400])
print()
print("| node | messages | types fuzzed | alive | outputs checked | non-finite | motion while untrusted |")
print("| --- | --- | --- | --- | --- | --- | --- |")
for r in runs:
    types = sorted({t for t, _ in r["topics"].values()})
    motion = r["motion"] if r["controller"] else "-"
    print("| %s | %d | %s | %s | %d | %d | %s |" % (
        r["label"], r["sent"], ", ".join(types), "yes" if r["alive"] else "NO", r["outputs"],
        r["non_finite"], motion))
if len(runs) < len(sys.argv) - 2:
    print("%d of %d runs wrote no summary (see the logs)" % (len(sys.argv) - 2 - len(runs),
                                                           len(sys.argv) - 2))
    sys.exit(1)
sys.exit(0 if all(r["ok"] for r in runs) else 1)
PY
exit "$status"
