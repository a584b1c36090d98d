#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Checks the include graph of the core's layers (doc/architecture.md); run at every build.

    check_layers.py REPO
    check_layers.py --self-test     (proves the check fails on each kind of violation)

Each folder under src/ and include/radio_follow/ that is a core layer may include only
its own headers and those of the layers it depends on; no core file may include a ROS
header (ros/, a message package, tf2_ros, ...) or the ROS wrappers (radio_follow/ros/).
Prints every violation as file:line and exits 1 when there is one. The linker checks
symbols (each layer is linked with --no-undefined); this checks what it cannot see:
headers used for types or inline code only."""
import os
import re
import sys

# Layer -> the layers it may include (itself included). The order of the issue:
# common <- config <- models <- {drivers, estimation, control} <- sim <- evaluation.
ALLOWED = {
    "common": {"common"},
    "config": {"common", "config"},
    "models": {"common", "config", "models"},
    "drivers": {"common", "drivers"},
    "estimation": {"common", "config", "models", "estimation"},
    "control": {"common", "config", "control"},
    "sim": {"common", "config", "models", "sim"},
    "evaluation": {"common", "config", "models", "estimation", "control", "sim", "evaluation"},
}
# Headers only a ROS build has: a core file including one does not belong in the core.
ROS_HEADER = re.compile(
    r"#\s*include\s*[<\"](ros|rosbag|tf2_ros|tf2_geometry_msgs|dynamic_reconfigure|"
    r"diagnostic_updater|[a-z_]+_msgs|std_srvs|xmlrpcpp|XmlRpc)[/.]")
# The lab's layers: built only with RADIO_FOLLOW_BUILD_LAB, never included by the runtime.
LAB_LAYERS = {"evaluation"}
OWN_HEADER = re.compile(r"#\s*include\s*\"radio_follow/([A-Za-z_]+)/")
# Generated message headers of this package: radio_follow/UwbRanges.h, ...
OWN_MESSAGE = re.compile(r"#\s*include\s*[<\"]radio_follow/[A-Z][A-Za-z]*\.h[>\"]")


def sources_under(*roots):
    for root in roots:
        for dirpath, _, names in os.walk(root):  # nothing for a missing root
            for name in sorted(names):
                if name.endswith((".cpp", ".hpp", ".h")):
                    yield os.path.join(dirpath, name)


def files_of(repo, layer):
    return sources_under(os.path.join(repo, "src", layer),
                         os.path.join(repo, "include", "radio_follow", layer))


def runtime_files(repo):
    """The ROS wrappers, the node mains and the operator tools (src/tools/)."""
    return sources_under(os.path.join(repo, "src", "ros"),
                         os.path.join(repo, "include", "radio_follow", "ros"),
                         os.path.join(repo, "src", "nodes"), os.path.join(repo, "src", "tools"))


def check(repo):
    problems = []
    for layer, allowed in ALLOWED.items():
        for path in files_of(repo, layer):
            relative = os.path.relpath(path, repo)
            with open(path, encoding="utf-8") as f:
                for number, line in enumerate(f, 1):
                    if ROS_HEADER.search(line) or OWN_MESSAGE.search(line):
                        problems.append("%s:%d: a ROS include in the core layer %s: %s"
                                        % (relative, number, layer, line.strip()))
                        continue
                    match = OWN_HEADER.search(line)
                    if match and match.group(1) not in allowed:
                        problems.append("%s:%d: layer %s includes %s/ (allowed: %s)"
                                        % (relative, number, layer, match.group(1),
                                           ", ".join(sorted(allowed))))
    # The runtime (the ROS wrappers, the nodes, the operator tools) includes none of the
    # lab's layers: what the .deb installs builds without RADIO_FOLLOW_BUILD_LAB.
    for path in runtime_files(repo):
        relative = os.path.relpath(path, repo)
        with open(path, encoding="utf-8") as f:
            for number, line in enumerate(f, 1):
                match = OWN_HEADER.search(line)
                if match and match.group(1) in LAB_LAYERS:
                    problems.append("%s:%d: the runtime includes the lab's layer %s/"
                                    % (relative, number, match.group(1)))
    # Every folder of the core is a known layer: a new folder needs its place in the order.
    for base in (os.path.join(repo, "src"), os.path.join(repo, "include", "radio_follow")):
        for name in sorted(os.listdir(base)):
            if os.path.isdir(os.path.join(base, name)) and name not in ALLOWED and name not in (
                    "ros", "nodes", "tools", "lab"):
                problems.append("%s/%s: a folder that is no layer (add it to scripts/check_layers.py "
                                "and CMakeLists.txt's RF_CORE_LAYERS)" % (os.path.relpath(base, repo), name))
    return problems


def self_test():
    """Copies the include lines of a few files into a scratch tree with four planted
    violations and checks that each is reported, and that the clean tree passes."""
    import shutil
    import tempfile
    repo = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    scratch = tempfile.mkdtemp(prefix="check_layers.")
    try:
        shutil.copytree(os.path.join(repo, "src"), os.path.join(scratch, "src"))
        shutil.copytree(os.path.join(repo, "include"), os.path.join(scratch, "include"))
        clean = check(scratch)
        planted = {
            "src/control/planted_ros.cpp": "#include <ros/ros.h>\n",
            "src/drivers/planted_message.cpp": "#include \"radio_follow/UwbRanges.h\"\n",
            "include/radio_follow/estimation/planted_up.hpp": "#include \"radio_follow/sim/world.hpp\"\n",
            "src/ros/sim/planted_lab.cpp": "#include \"radio_follow/evaluation/closed_loop.hpp\"\n",
        }
        for name, text in planted.items():
            with open(os.path.join(scratch, name), "w") as f:
                f.write(text)
        found = check(scratch)
        missed = [n for n in planted if not any(p.startswith(n + ":") for p in found)]
        if clean or missed or len(found) != len(planted):
            sys.exit("check_layers self-test FAILED: clean tree %s; missed %s; found %s"
                     % (clean, missed, found))
        print("check_layers self-test: clean tree passes, %d planted violations found" % len(found))
    finally:
        shutil.rmtree(scratch)


def main():
    if sys.argv[1:] == ["--self-test"]:
        self_test()
        return
    if len(sys.argv) != 2:
        sys.exit("usage: check_layers.py REPO | --self-test")
    problems = check(sys.argv[1])
    for p in problems:
        print(p, file=sys.stderr)
    if problems:
        print("check_layers: %d layer violation(s)" % len(problems), file=sys.stderr)
        sys.exit(1)


if __name__ == "__main__":
    main()
