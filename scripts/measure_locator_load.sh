#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Measures the locator node's CPU use and resident memory at its default 20 Hz on the Spot
# layout, fed like the real drivers (three UWB modules at 10 Hz, four AoA boards at 20 Hz)
# by a small rospy publisher. Baseline in the same run and window: bench_idle_subscriber, a
# roscpp node subscribed to the same topics that does nothing (what receiving the messages
# costs). Uses its own ROS master on a free port. Needs a built workspace (benchmarks on).
#   bash scripts/measure_locator_load.sh [seconds]
set -euo pipefail
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
seconds="${1:-60}"
export PATH="/usr/bin:$PATH"
set +u
# shellcheck disable=SC1091
source "$repo/scripts/env.sh"
set -u
port=$((20000 + RANDOM % 20000))
export ROS_MASTER_URI="http://localhost:$port"
export ROS_HOME="${ROS_HOME:-$(mktemp -d)}"
pids=()
cleanup() { for p in "${pids[@]}"; do kill "$p" 2>/dev/null || true; done; }
trap cleanup EXIT

roscore -p "$port" >/dev/null 2>&1 &
pids+=($!)
sleep 3
# Lists through rosparam (YAML): a `_name:=[a, b]` argument reaches roscpp as a string,
# which the strict parameter reader refuses.
rosparam set /locator/layout_file "$repo/config/layouts/spot.yaml"
rosparam set /locator/uwb_topics "[uwb/ranges]"
rosparam set /locator/aoa_topics \
  "[aoa/front/bearing, aoa/left/bearing, aoa/back/bearing, aoa/right/bearing]"
# rosrun execs the node, so $! is the locator's own PID.
rosrun radio_follow locator >/dev/null 2>&1 &
pids+=($!)
pid=$!
"$RF_WS/devel/lib/radio_follow/bench_idle_subscriber" >/dev/null 2>&1 &
pids+=($!)
floor=$!
python3 - <<'PY' >/dev/null 2>&1 &
import math, random, rospy
from radio_follow.msg import UwbRanges, UwbRange, AoaBearing
rospy.init_node("locator_feed")
uwb = rospy.Publisher("uwb/ranges", UwbRanges, queue_size=10)
boards = {n: (rospy.Publisher("aoa/%s/bearing" % n, AoaBearing, queue_size=10), yaw, pos)
          for n, yaw, pos in (("front", 0.0, (0.065, 0.0)), ("left", math.pi / 2, (0.0, 0.065)),
                              ("back", math.pi, (-0.065, 0.0)), ("right", -math.pi / 2, (0.0, -0.065)))}
modules = {"5722": (0.175, 0.075, 0.115), "5A84": (-0.07, -0.04, 0.093), "C4B5": (-0.30, 0.08, 0.098)}
rate = rospy.Rate(20)
k = 0
while not rospy.is_shutdown():
    t = rospy.get_time()
    p = (4.0 * math.cos(0.2 * t), 4.0 * math.sin(0.2 * t), 1.0)
    if k % 2 == 0:
        for mid, m in modules.items():
            msg = UwbRanges(tag_id=mid)
            msg.header.stamp = rospy.Time.now()
            msg.header.frame_id = "uwb_" + mid
            msg.ranges = [UwbRange(anchor_id="DA12", range=math.dist(p, m) + random.gauss(0, 0.03))]
            uwb.publish(msg)
    for name, (pub, yaw, pos) in boards.items():
        az = math.atan2(p[1] - pos[1], p[0] - pos[0]) - yaw
        az = math.atan2(math.sin(az), math.cos(az))
        b = AoaBearing(azimuth=max(-1.2, min(1.2, az)) + random.gauss(0, 0.05), elevation=0.1,
                       rssi=-60.0)
        b.header.stamp = rospy.Time.now()
        b.header.frame_id = "aoa_" + name
        pub.publish(b)
    k += 1
    rate.sleep()
PY
pids+=($!)
sleep 5
for p in "$pid" "$floor"; do
  [ -d "/proc/$p" ] || { echo "measure_locator_load: a node exited at start (pid $p)" >&2; exit 1; }
done
hz="$(getconf CLK_TCK)"
read -r -a s0 < <(cut -d' ' -f14,15 "/proc/$pid/stat")
read -r -a f0 < <(cut -d' ' -f14,15 "/proc/$floor/stat")
sleep "$seconds"
read -r -a s1 < <(cut -d' ' -f14,15 "/proc/$pid/stat")
read -r -a f1 < <(cut -d' ' -f14,15 "/proc/$floor/stat")
ticks=$(( (s1[0] + s1[1]) - (s0[0] + s0[1]) ))
floor_ticks=$(( (f1[0] + f1[1]) - (f0[0] + f0[1]) ))
rss_kb="$(awk '/VmRSS/ {print $2}' "/proc/$pid/status")"
hwm_kb="$(awk '/VmHWM/ {print $2}' "/proc/$pid/status")"
floor_rss_kb="$(awk '/VmRSS/ {print $2}' "/proc/$floor/status")"
# Show that it was tracking, not idling on LOST (1 = OK, msg/TargetEstimate.msg).
echo "target status: $(timeout 10 rostopic echo -n 1 target/status 2>/dev/null | head -n 1)"
awk -v t="$ticks" -v ft="$floor_ticks" -v hz="$hz" -v s="$seconds" -v rss="$rss_kb" \
    -v hwm="$hwm_kb" -v frss="$floor_rss_kb" 'BEGIN {
  printf "locator over %d s: CPU %.2f %% of one core, RSS %.1f MB (peak %.1f MB)\n",
         s, 100.0 * t / hz / s, rss / 1024.0, hwm / 1024.0
  printf "idle subscriber (same topics, same window): CPU %.2f %% of one core, RSS %.1f MB\n",
         100.0 * ft / hz / s, frss / 1024.0
  printf "locator / idle subscriber: CPU %s, RSS %.1f x\n",
         (ft > 0 ? sprintf("%.1f x", t / ft) : "n/a (the subscriber used no tick)"), rss / frss }'
