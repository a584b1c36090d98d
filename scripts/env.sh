# SPDX-License-Identifier: BSD-3-Clause
# Source this to use the built workspace: `source scripts/env.sh`
# (sets PATH for Debian's python3 and sources the devel space).
RF_REPO="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
# shellcheck source=workspace.sh
source "$RF_REPO/scripts/workspace.sh"
export PATH="/usr/bin:$PATH"
# catkin's setup scripts read unset variables: relax `set -u` while sourcing them.
case $- in *u*) _rf_nounset=1; set +u ;; *) _rf_nounset=0 ;; esac
# shellcheck disable=SC1091
source "$RF_WS/devel/setup.bash"
[ "$_rf_nounset" = 1 ] && set -u
unset _rf_nounset
