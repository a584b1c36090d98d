#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Runs every shell command the README and doc/ show, so a documented command that fails
is a failed test (README, "Tests": documented commands).

Every ```bash block is run, from the repository root, with scripts/env.sh sourced. The
line right before the fence may say how (an HTML comment, invisible on GitHub):

  (nothing)                               run the block as one script (set -e); it must exit 0
  <!-- docs-test: demo -->                run it while the simulated demo runs on a private
                                          master (operator commands: rosservice, rostopic,
                                          dynparam); it must exit 0
  <!-- docs-test: demo, until-stopped --> each command runs against the demo for a few
                                          seconds and is then stopped (rostopic hz, a
                                          recording): it must not fail before that
  <!-- docs-test: skip: REASON -->        not run (hardware, root, a placeholder); the reason
                                          is printed, so skipping is never silent

It also checks what `roslaunch --ros-args` shows for every launch file: every argument
documented, and none listed as required unless it is (REQUIRED_ARGS); and that every row of
the results table in doc/results.md that quotes a figure names the command that produces
it (`bash scripts/<script>.sh ...`, the script present; for scripts/results.sh, a section
it has).

Usage: docs_test.py [--list | --results-table]
  --list           prints the blocks and what would happen
  --results-table  only the results-table check (no ROS, a fraction of a second)
Exit status 1 if any block or launch file failed.
"""
import os
import re
import signal
import subprocess
import sys
import tempfile
import time
from pathlib import Path

REPO = Path(__file__).resolve().parent.parent
DIRECTIVE = re.compile(r"<!--\s*docs-test:\s*(.*?)\s*-->")
BLOCK_TIMEOUT = 600  # s, a whole block (scripts/demo.sh builds, then runs a 60 s scenario)
UNTIL_STOPPED = 8  # s a long-running command runs before it is stopped
DEMO_PORT = int(os.environ.get("RF_DOCS_PORT", "11671"))
# Launch arguments a user must give: everything else has a default.
REQUIRED_ARGS = {
    "replay.launch": {"bag", "layout_file"},
    "follower.launch": {"layout_file"},
    "robot.launch": {"layout_file"},
    "layout.launch": {"layout_file"},
    "layout_drivers.launch": {"layout_file"},
}


def blocks():
    """(file, line, mode, reason, text) of every bash block in README.md and doc/."""
    files = [REPO / "README.md"] + sorted((REPO / "doc").rglob("*.md"))
    for path in files:
        lines = path.read_text().splitlines()
        i = 0
        while i < len(lines):
            if lines[i].strip() == "```bash":
                start = i
                body = []
                i += 1
                while i < len(lines) and lines[i].strip() != "```":
                    body.append(lines[i])
                    i += 1
                directive = DIRECTIVE.search(lines[start - 1]) if start > 0 else None
                mode, reason = "run", ""
                if directive:
                    words = directive.group(1)
                    if words.startswith("skip"):
                        mode, reason = "skip", words.partition(":")[2].strip()
                        if not reason:
                            raise SystemExit(f"{path}:{start + 1}: a skip needs a reason")
                    elif words == "demo":
                        mode = "demo"
                    elif words == "demo, until-stopped":
                        mode = "until-stopped"
                    else:
                        raise SystemExit(f"{path}:{start + 1}: unknown directive '{words}'")
                yield path.relative_to(REPO), start + 1, mode, reason, "\n".join(body)
            i += 1


def commands(text):
    """The block's commands: comment lines dropped, backslash continuations joined."""
    out, current = [], ""
    for line in text.splitlines():
        stripped = line.strip()
        if not current and (not stripped or stripped.startswith("#")):
            continue
        if stripped.endswith("\\"):
            current += stripped[:-1] + " "
            continue
        out.append(current + stripped)
        current = ""
    return out


def environment(scratch):
    env = dict(os.environ)
    env["PATH"] = "/usr/bin:" + env.get("PATH", "")
    env["ROS_HOME"] = str(scratch / "ros_home")
    env["ROS_MASTER_URI"] = f"http://localhost:{DEMO_PORT}"
    env["RF_DEMO_PORT"] = str(DEMO_PORT + 1)  # scripts/demo.sh's own master
    return env


def bash(script, env, timeout):
    prologue = "set -eo pipefail\nsource scripts/env.sh >/dev/null\n"
    return subprocess.run(["bash", "-c", prologue + script], cwd=REPO, env=env,
                          stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                          timeout=timeout)


def run_until_stopped(command, env):
    """Runs `command` for UNTIL_STOPPED s, then sends SIGINT (Ctrl-C). Failing before that
    is a failure; being stopped is the expected end. Bags it wrote to /tmp (a documented
    `record.launch prefix:=/tmp/...`) are removed, so test runs leave nothing behind."""
    bags_before = set(Path("/tmp").glob("*.bag*"))
    try:
        return _run_until_stopped(command, env)
    finally:
        for bag in set(Path("/tmp").glob("*.bag*")) - bags_before:
            bag.unlink(missing_ok=True)


def _run_until_stopped(command, env):
    prologue = "source scripts/env.sh >/dev/null\n"
    proc = subprocess.Popen(["bash", "-c", prologue + command], cwd=REPO, env=env,
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                            start_new_session=True)
    try:
        output, _ = proc.communicate(timeout=UNTIL_STOPPED)
        return proc.returncode == 0, output  # ended by itself: fine if it succeeded
    except subprocess.TimeoutExpired:
        os.killpg(proc.pid, signal.SIGINT)
        try:
            output, _ = proc.communicate(timeout=20)
        except subprocess.TimeoutExpired:
            os.killpg(proc.pid, signal.SIGKILL)
            output, _ = proc.communicate()
        return True, output


class Demo:
    """The simulated demo on a private master, for the operator commands."""

    def __init__(self, env, scratch):
        self.log = open(scratch / "demo.log", "w")
        self.proc = subprocess.Popen(
            ["roslaunch", "-p", str(DEMO_PORT), "radio_follow", "demo.launch", "required:=false",
             "scenario:=random_walk", "time_factor:=1", f"report_dir:={scratch}/demo_report"],
            cwd=REPO, env=env, stdout=self.log, stderr=subprocess.STDOUT,
            start_new_session=True)
        # rostopic gives up at once while the master is not up yet: ask again until then.
        ready = bash("for i in $(seq 90); do\n"
                     "  timeout 5 rostopic echo -n 1 /target >/dev/null 2>&1 && exit 0\n"
                     "  sleep 1\ndone\nexit 1", env, 600)
        if ready.returncode != 0:
            self.stop()
            raise SystemExit("docs_test: the demo never published /target "
                             f"(log: {scratch}/demo.log)\n{ready.stdout}")

    def stop(self):
        if self.proc.poll() is None:
            os.killpg(self.proc.pid, signal.SIGINT)
            try:
                self.proc.wait(timeout=30)
            except subprocess.TimeoutExpired:
                os.killpg(self.proc.pid, signal.SIGKILL)
        self.log.close()


def clone_state():
    """What `git status` says of the clone: a documented command must not write into it."""
    result = subprocess.run(["git", "status", "--porcelain", "--untracked-files=all"],
                            cwd=REPO, stdout=subprocess.PIPE, text=True)
    return set(result.stdout.splitlines()) if result.returncode == 0 else set()


def check_launch_args(env):
    """Failures in `roslaunch --ros-args` of every launch file (required or undocumented)."""
    failures = []
    for launch in sorted((REPO / "launch").glob("*.launch")):
        result = subprocess.run(["roslaunch", "--ros-args", str(launch)], env=env,
                                stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        if result.returncode != 0:
            failures.append(f"{launch.name}: roslaunch --ros-args failed:\n{result.stdout}")
            continue
        section, required = None, set()
        for line in result.stdout.splitlines():
            if line.endswith("Arguments:"):
                section = line
            elif line.startswith("  ") and section == "Required Arguments:":
                required.add(line.strip().split(":")[0])
            if "undocumented" in line:
                failures.append(f"{launch.name}: undocumented argument: {line.strip()}")
        unexpected = required - REQUIRED_ARGS.get(launch.name, set())
        if unexpected:
            failures.append(f"{launch.name}: shown as required but optional (or an empty "
                            f"computed value): {', '.join(sorted(unexpected))}")
    return failures


def results_table_failures():
    """Rows of doc/results.md's table with a figure but no command that produces it."""
    lines = (REPO / "doc" / "results.md").read_text().splitlines()
    start = next((i for i, line in enumerate(lines) if line.startswith("|")), None)
    if start is None:
        return ["doc/results.md: no results table"]
    end = start
    while end < len(lines) and lines[end].startswith("|"):
        end += 1
    table = "\n".join(lines[start:end])
    results_sh = (REPO / "scripts" / "results.sh").read_text()
    sections = set(re.search(r"^all=\((.*)\)$", results_sh, re.M).group(1).split())
    failures = []
    for row in table.splitlines()[2:]:
        cells = [c.strip() for c in row.strip().strip("|").split("|")]
        if len(cells) < 3 or not re.search(r"\d", cells[1]):
            continue
        named = re.findall(r"`bash scripts/([\w.]+\.sh)([^`]*)`", row)
        good = [(script, args) for script, args in named if (REPO / "scripts" / script).is_file()
                and (script != "results.sh" or set(args.split()) <= sections)]
        if not good:
            failures.append(f"doc/results.md row '{cells[0]}': no `bash scripts/<script>.sh` "
                            "command that exists (results.sh sections: "
                            f"{' '.join(sorted(sections))})")
    return failures


def main():
    listing = "--list" in sys.argv
    if "--results-table" in sys.argv:
        problems = results_table_failures()
        for problem in problems:
            print(f"docs_test: FAIL {problem}")
        print(f"docs_test: results table: {len(problems)} rows without a command")
        return 1 if problems else 0
    found = list(blocks())
    if listing:
        for path, line, mode, reason, _ in found:
            print(f"{path}:{line}: {mode}{' (' + reason + ')' if reason else ''}")
        return 0
    scratch = Path(tempfile.mkdtemp(prefix="radio_follow_docs_"))
    env = environment(scratch)
    failures, ran, skipped = [], 0, 0
    before = clone_state()
    for problem in check_launch_args(env):
        print(f"docs_test: FAIL {problem}")
        failures.append("launch arguments")
    for problem in results_table_failures():
        print(f"docs_test: FAIL {problem}")
        failures.append("results table")
    demo = None
    try:
        # Plain blocks first, then the ones that need the demo (started once).
        for path, line, mode, reason, text in sorted(found, key=lambda b: b[2] != "run"):
            where = f"{path}:{line}"
            if mode == "skip":
                print(f"docs_test: SKIP {where}: {reason}")
                skipped += 1
                continue
            if mode in ("demo", "until-stopped") and demo is None:
                demo = Demo(env, scratch)
            started = time.monotonic()
            if mode == "until-stopped":
                ok, output = True, ""
                for command in commands(text):
                    good, out = run_until_stopped(command, env)
                    output += f"$ {command}\n{out}"
                    ok = ok and good
            else:
                try:
                    result = bash(text, env, BLOCK_TIMEOUT)
                    ok, output = result.returncode == 0, result.stdout
                except subprocess.TimeoutExpired as e:
                    ok, output = False, f"timed out after {BLOCK_TIMEOUT} s\n{e.stdout or ''}"
            ran += 1
            verdict = "ok  " if ok else "FAIL"
            print(f"docs_test: {verdict} {where} ({mode}, {time.monotonic() - started:.0f} s)")
            if not ok:
                failures.append(where)
                print("\n".join("    " + l for l in output.splitlines()[-40:]))
    finally:
        if demo is not None:
            demo.stop()
    for change in sorted(clone_state() - before):
        print(f"docs_test: FAIL a documented command changed the clone: {change}")
        failures.append("clone written")
    print(f"docs_test: {ran} blocks run, {skipped} skipped, {len(failures)} failed"
          + (": " + ", ".join(failures) if failures else ""))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
