#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Release check (doc/packaging.md): from a copy of this clone, with no dev workspace in
# sight and no network,
#   1. rosdep against the offline database rosdep/debian.yaml: rosdep check and
#      rosdep install --simulate, catkin_lint with that database;
#   2. bloom-generate rosdebian (ROS distro name "debian", Debian 12 bookworm);
#   3. the .deb (dpkg-buildpackage -b, tests and benchmarks off, no -Werror);
#   4. dpkg -x into a clean prefix, source its setup.bash and run the demo from it on its
#      own master port; checks metrics.json was written and the robot moved.
# Usage: scripts/package.sh [work dir, default: a new temp dir, removed on success]
# Environment: RF_JOBS (build jobs, default 2), RF_PACKAGE_PORT (demo master, 11431),
# RF_PACKAGE_KEEP=1 keeps the work dir.
set -euo pipefail
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"

# Start again in a clean environment: nothing of a sourced dev workspace
# (CMAKE_PREFIX_PATH, ROS_PACKAGE_PATH, LD_LIBRARY_PATH, PYTHONPATH) reaches the build.
if [ -z "${RF_PACKAGE_CLEAN_ENV:-}" ]; then
  exec env -i HOME="$HOME" PATH=/usr/bin:/bin:/usr/sbin:/sbin LANG=C.UTF-8 \
    RF_PACKAGE_CLEAN_ENV=1 RF_JOBS="${RF_JOBS:-2}" RF_PACKAGE_PORT="${RF_PACKAGE_PORT:-11431}" \
    RF_PACKAGE_KEEP="${RF_PACKAGE_KEEP:-0}" bash "${BASH_SOURCE[0]}" "$@"
fi

distro=debian      # the ROS distro name bloom and rosdep use (doc/packaging.md)
os_version=bookworm
work="${1:-$(mktemp -d /tmp/rf-package.XXXXXX)}"
mkdir -p "$work"
work="$(cd "$work" && pwd)"
step() { echo "package: $*"; }
fail() { echo "package: FAILED: $*" >&2; exit 1; }
t0=$SECONDS

# --- 1. rosdep, offline --------------------------------------------------------------
# A one-distro rosdistro index (no repositories: every key resolves through rosdep) and a
# sources list naming only the shipped rosdep/debian.yaml; `rosdep update` caches both
# under a private ROS_HOME.
mkdir -p "$work/rosdistro/$distro" "$work/sources.list.d" "$work/ros_home"
cat >"$work/rosdistro/index-v4.yaml" <<EOF
%YAML 1.1
---
distributions:
  $distro:
    distribution: [$distro/distribution.yaml]
    distribution_status: active
    distribution_type: ros1
    python_version: 3
type: index
version: 4
EOF
cat >"$work/rosdistro/$distro/distribution.yaml" <<EOF
%YAML 1.1
---
release_platforms:
  debian: [$os_version]
repositories: {}
type: distribution
version: 2
EOF
echo "yaml file://$repo/rosdep/debian.yaml" >"$work/sources.list.d/10-radio-follow.list"
export ROSDEP_SOURCE_PATH="$work/sources.list.d"
export ROSDISTRO_INDEX_URL="file://$work/rosdistro/index-v4.yaml"
# ROS_DISTRO stays unset (Debian's env hook sets it to "Debian" and warns when it differs):
# the distro name goes on each command line instead.
export ROS_HOME="$work/ros_home" ROS_PYTHON_VERSION=3

step "rosdep update (offline database rosdep/debian.yaml)"
rosdep update --rosdistro "$distro" >"$work/rosdep_update.log" 2>&1 ||
  { cat "$work/rosdep_update.log" >&2; fail "rosdep update"; }

step "rosdep check --from-paths $repo --ignore-src"
rosdep check --rosdistro "$distro" --from-paths "$repo" --ignore-src || fail "rosdep check"
step "rosdep install --simulate (what a fresh machine would install)"
rosdep install --rosdistro "$distro" --simulate --reinstall --default-yes \
  --from-paths "$repo" --ignore-src >"$work/rosdep_install.log" 2>&1 ||
  { cat "$work/rosdep_install.log" >&2; fail "rosdep install --simulate"; }
grep -c '^  apt-get install' "$work/rosdep_install.log" |
  xargs -I{} echo "package: rosdep install --simulate: {} apt packages, no errors"
step "catkin_lint -W0 with the rosdep database (unknown keys are errors)"
ROS_DISTRO="$distro" catkin_lint -W0 "$repo" || fail "catkin_lint"

# --- 2. bloom-generate rosdebian on a copy of the clone ------------------------------
# The copy holds the files git knows (tracked and new, not ignored): no build tree, no
# report/, nothing of a dev workspace.
src="$work/src/radio_follow"
rm -rf "$work/src"
mkdir -p "$src"
git -C "$repo" ls-files -co --exclude-standard -z | (cd "$repo" && tar --null -T - -cf -) |
  tar -xf - -C "$src"
step "bloom-generate rosdebian --ros-distro $distro --os-name debian --os-version $os_version"
bloom_args=(--os-name debian --os-version "$os_version" --ros-distro "$distro")
(cd "$src" && bloom-generate rosdebian "${bloom_args[@]}" --place-template-files) \
  >"$work/bloom.log" 2>&1 || { cat "$work/bloom.log" >&2; fail "bloom (templates)"; }
# Changes to bloom's rules template: catkin installs its setup.* files into the prefix
# (bloom leaves them to a ros-<distro>-catkin package, which Debian does not have);
# benchmarks and the lab's tools stay off (they are never installed) and -Werror too; no
# unity build (the one place CI compiles the runtime file by file: a missing include shows);
# dh builds in parallel (bloom's debhelper compat 9 does not by default).
# Tests are off through DEB_BUILD_OPTIONS=nocheck below.
sed -i -e 's/-DCATKIN_BUILD_BINARY_PACKAGE="1"/-DCATKIN_BUILD_BINARY_PACKAGE="0" -DRADIO_FOLLOW_BUILD_BENCHMARKS=OFF -DRADIO_FOLLOW_BUILD_LAB=OFF -DRADIO_FOLLOW_WERROR=OFF -DCMAKE_UNITY_BUILD=OFF/' \
  -e 's/^\(\tdh \$@@ -v\) /\1 --parallel /' "$src/debian/rules.em"
grep -q 'CATKIN_BUILD_BINARY_PACKAGE="0"' "$src/debian/rules.em" &&
  grep -q 'dh \$@@ -v --parallel' "$src/debian/rules.em" ||
  fail "bloom's rules template changed: $src/debian/rules.em"
(cd "$src" && bloom-generate rosdebian "${bloom_args[@]}" --process-template-files) \
  >>"$work/bloom.log" 2>&1 || { cat "$work/bloom.log" >&2; fail "bloom (processing)"; }
grep -E '^(Source|Build-Depends|Depends):' "$src/debian/control" | cut -c1-160

# --- 3. the .deb ----------------------------------------------------------------------
step "dpkg-buildpackage -b -us -uc (nocheck, $RF_JOBS jobs; log $work/deb_build.log)"
tb=$SECONDS
(cd "$src" && DEB_BUILD_OPTIONS="nocheck parallel=$RF_JOBS" MAKEFLAGS="-j$RF_JOBS" \
  dpkg-buildpackage -b -us -uc) >"$work/deb_build.log" 2>&1 ||
  { tail -n 40 "$work/deb_build.log" >&2; fail "dpkg-buildpackage"; }
deb="$(ls "$work"/src/ros-"$distro"-radio-follow_*.deb)"
step "built $(basename "$deb") ($(du -k "$deb" | cut -f1) kB) in $((SECONDS - tb)) s"
grep -qE -- '-Werror( |$)' "$work/deb_build.log" && fail "the release build used -Werror"

# --- 4. install into a clean prefix and run the demo from it --------------------------
root="$work/root"
rm -rf "$root"
dpkg -x "$deb" "$root"
prefix="$root/opt/ros/$distro"
[ -f "$prefix/setup.bash" ] || fail "no setup.bash in the installed prefix"
for f in lib/radio_follow/simulator lib/radio_follow/locator lib/radio_follow/plot_report.py \
  lib/radio_follow/udev_rule.sh share/radio_follow/launch/demo.launch \
  share/radio_follow/package.xml; do
  [ -e "$prefix/$f" ] || fail "the .deb lacks $f"
done
# The runtime only: every operator tool (src/tools/), not the lab program (src/lab/) and no
# library of the lab's evaluation layer.
for source in "$repo"/src/tools/*.cpp; do
  tool="$(basename "$source" .cpp)"
  [ -e "$prefix/lib/radio_follow/$tool" ] || fail "the .deb lacks the operator tool $tool"
done
[ ! -e "$prefix/lib/radio_follow/lab" ] || fail "the .deb installs the lab program"
if find "$prefix" -name 'libradio_follow_evaluation*' | grep -q .; then
  fail "the .deb installs the lab's evaluation library"
fi
(
  cd "$work"
  export ROS_HOME="$work/ros_home_demo"
  set +u
  # shellcheck disable=SC1091
  source "$prefix/setup.bash"
  set -u
  where="$(rospack find radio_follow)"
  [ "$where" = "$prefix/share/radio_follow" ] || fail "rospack finds radio_follow at $where"
  step "radio_follow from $where"
  # The installed scripts run from the prefix (rosrun finds them in lib/radio_follow).
  usage="$(rosrun radio_follow udev_rule.sh 2>&1 || true)"
  [[ "$usage" == usage:* ]] || fail "udev_rule.sh from the prefix: $usage"
  port="$RF_PACKAGE_PORT"
  export ROS_MASTER_URI="http://localhost:$port"
  report="$work/report"
  rm -rf "$report"
  step "roslaunch -p $port radio_follow demo.launch scenario:=straight_walk (log $work/demo.log)"
  timeout 300 roslaunch -p "$port" radio_follow demo.launch scenario:=straight_walk \
    report_dir:="$report" >"$work/demo.log" 2>&1 || { tail -n 30 "$work/demo.log" >&2; fail "demo"; }
  [ -s "$report/metrics.json" ] || fail "the demo wrote no metrics.json"
  python3 - "$report/metrics.json" <<'EOF' || fail "the robot did not move"
import json, sys
m = json.load(open(sys.argv[1]))
print(f"package: demo from the .deb: robot moved {m['robot_distance_m']:.2f} m, "
      f"min gap {m['min_gap_m']:.2f} m ({m.get('min_gap_while_moving_m') or float('nan'):.2f} m "
      f"while moving), "
      f"estimate available {m['estimate_availability']:.0%}")
sys.exit(0 if m["robot_distance_m"] > 1.0 else 1)
EOF
  rosrun radio_follow plot_report.py "$report" >/dev/null || fail "plot_report.py from the prefix"
  [ -s "$report/report.png" ] || fail "plot_report.py wrote no report.png"
)
step "OK in $((SECONDS - t0)) s: $(basename "$deb")"
if [ "$RF_PACKAGE_KEEP" = 1 ] || [ $# -ge 1 ]; then
  step "work dir kept: $work"
else
  rm -rf "$work"
fi
