#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Builds radio_follow in a catkin workspace at $RF_WS (see scripts/workspace.sh; printed
# at the end) whose src/ links to this clone. Extra arguments go to catkin_make.
# RF_UNITY=OFF (or ON) sets the unity build the workspace keeps (CMakeLists.txt: on unless
# set; off rebuilds one changed file quicker).
set -euo pipefail
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
RF_REPO="$repo"
# shellcheck source=workspace.sh
source "$repo/scripts/workspace.sh"
ws="$RF_WS"

# catkin runs its Python helpers with the first python3 on PATH; Debian's python3 has
# catkin's modules, a pyenv shim does not. Put /usr/bin first and name it explicitly.
export PATH="/usr/bin:$PATH"

mkdir -p "$ws/src"
ln -sfn "$repo" "$ws/src/radio_follow"
cd "$ws"
catkin_make -j"${RF_JOBS:-$(nproc)}" \
  -DPYTHON_EXECUTABLE=/usr/bin/python3 \
  -DCMAKE_BUILD_TYPE="${RF_BUILD_TYPE:-Release}" \
  -DCMAKE_EXPORT_COMPILE_COMMANDS=ON ${RF_UNITY:+-DCMAKE_UNITY_BUILD="$RF_UNITY"} \
  -DRADIO_FOLLOW_WERROR=ON -DRADIO_FOLLOW_BUILD_BENCHMARKS=ON \
  "$@"
echo "build: workspace $ws"
