#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Summarises the JUnit XML files catkin's run_tests wrote, one line per suite, and
closes with 'N passed, N failed'. Exit 1 when a test failed or errored, when a suite
produced no result file it should have, or when no test ran at all."""
import sys
import xml.etree.ElementTree as ET
from pathlib import Path


def print_slowest(files, count=12):
    """run_tests runs one suite at a time (-j1) and each writes its file when it ends, so
    the time between one file and the one before it is about that suite's wall time
    (build steps run_tests makes between suites included)."""
    if len(files) < 2:
        return
    ordered = sorted(files, key=lambda p: p.stat().st_mtime)
    spans = [(b.stat().st_mtime - a.stat().st_mtime, b.name) for a, b in zip(ordered, ordered[1:])]
    total = ordered[-1].stat().st_mtime - ordered[0].stat().st_mtime
    print(f"slowest suites (time since the previous result file; {total:.0f} s from the "
          f"first file to the last):")
    for seconds, name in sorted(spans, reverse=True)[:count]:
        print(f"  {seconds:6.0f} s  {name}")


def main(results_dir: str) -> int:
    root = Path(results_dir)
    files = sorted(root.glob("*.xml")) if root.is_dir() else []
    passed = failed = skipped = 0
    broken = []
    for path in files:
        try:
            tree = ET.parse(path)
        except ET.ParseError as e:
            broken.append(f"{path.name}: unreadable ({e})")
            continue
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
    print_slowest(files)
    print(f"test result files: {len(files)} in {results_dir}")
    total_failed = failed + len(broken)
    print(f"{passed} passed, {total_failed} failed, {skipped} skipped")
    if passed + total_failed == 0:
        print("no test ran", file=sys.stderr)
        return 1
    return 1 if total_failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1] if len(sys.argv) > 1 else "."))
