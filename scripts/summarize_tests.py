#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Summarises the JUnit XML files catkin's run_tests wrote, one line per suite, and
closes with 'N passed, N failed'. Exit 1 when a test failed or errored, when a suite
produced no result file it should have, or when no test ran at all."""
import sys
import xml.etree.ElementTree as ET
from pathlib import Path


def suite_seconds(path, tree):
    """The wall time a result file records for its whole suite: a gtest binary's
    (testsuites time) or a rostest's (launch, nodes and test node: testsuite time); None
    for a rostest's test-node file (rosunit-*), which its rostest file covers."""
    if path.name.startswith("rosunit-"):
        return None
    try:
        return float(tree.getroot().get("time", ""))
    except ValueError:
        return None


def print_slowest(times, count=12):
    """run_tests may run suites side by side: each suite's own recorded time, and their
    sum, which against run_tests' wall time shows what running them at once saves."""
    if not times:
        return
    print(f"slowest suites ({sum(s for s, _ in times):.0f} s of suite time in all):")
    for seconds, name in sorted(times, reverse=True)[:count]:
        print(f"  {seconds:6.0f} s  {name}")


def main(results_dir: str) -> int:
    root = Path(results_dir)
    files = sorted(root.glob("*.xml")) if root.is_dir() else []
    passed = failed = skipped = 0
    broken = []
    times = []
    for path in files:
        try:
            tree = ET.parse(path)
        except ET.ParseError as e:
            broken.append(f"{path.name}: unreadable ({e})")
            continue
        seconds = suite_seconds(path, tree)
        if seconds is not None:
            times.append((seconds, path.name))
        for case in tree.iter("testcase"):
            name = f"{case.get('classname', '')}.{case.get('name', '')}"
            if case.find("failure") is not None or case.find("error") is not None:
                failed += 1
                print(f"FAILED  {path.name}: {name}")
            elif case.find("skipped") is not None:
                skipped += 1
            else:
                passed += 1
        # rostest records a test node that never reported as an error at suite level.
        for suite in tree.iter("testsuite"):
            if suite.find("testcase") is None and int(suite.get("errors", "0")) > 0:
                broken.append(f"{path.name}: suite {suite.get('name')} errored before any test")
    for line in broken:
        print(f"ERROR   {line}")
    print_slowest(times)
    print(f"test result files: {len(files)} in {results_dir}")
    total_failed = failed + len(broken)
    print(f"{passed} passed, {total_failed} failed, {skipped} skipped")
    if passed + total_failed == 0:
        print("no test ran", file=sys.stderr)
        return 1
    return 1 if total_failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1] if len(sys.argv) > 1 else "."))
