# SPDX-License-Identifier: BSD-3-Clause
# Sourced by the other scripts: sets RF_WS, the catkin workspace this clone builds in.
# Default: one workspace per clone under ~/.cache/radio_follow/ (outside the clone, so
# tools that walk the package directory, like rosrun, never meet the build tree).
# Set RF_WS to put it elsewhere.
if [ -z "${RF_WS:-}" ]; then
  _rf_key="$(printf '%s' "$RF_REPO" | md5sum | cut -c1-8)"
  RF_WS="${XDG_CACHE_HOME:-$HOME/.cache}/radio_follow/ws-$(basename "$RF_REPO")-$_rf_key"
  unset _rf_key
fi
export RF_WS
