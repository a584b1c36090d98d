#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""Message fuzzer for every subscriber of one running node (issue 34, item 2).

Asks the master which topics the node subscribes to and publishes, builds messages of
each subscribed type by walking the genpy classes (extreme values of every field, then
random combinations with --seed), and checks that the node stays alive, that nothing it
publishes is non-finite (outside the documented allow-list below), and, for a controller
(a node publishing geometry_msgs/Twist on cmd_vel), that cmd_vel is zero once no
trustworthy input remains. Exit status 0 only when all three hold.

    scripts/fuzz_messages.py --node velocity_controller --count 2000 --seed 1

Under rostest (a `--gtest_output=xml:...` argument) it runs as a unittest and writes the
result file; scripts/fuzz_nodes.sh runs the full count on every node type.
"""

import argparse
import json
import sys
import unittest
import warnings

import rospy

from fuzz_watch import FuzzRun, format_summary

DEFAULT_RATE = 1000.0


def parse_args(argv):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--node", required=True, help="node name, e.g. velocity_controller")
    p.add_argument("--count", type=int, default=2000,
                   help="fuzzed messages in total, spread over the node's topics")
    p.add_argument("--seed", type=int, default=1)
    p.add_argument("--rate", type=float, default=DEFAULT_RATE,
                   help="upper bound on messages per second (all topics)")
    p.add_argument("--mode", choices=["extremes", "random", "both"], default="both",
                   help="extremes: sweep every field through its extreme values; random: "
                        "random combinations; both: one sweep, then random")
    p.add_argument("--startup-timeout", type=float, default=60.0,
                   help="seconds to wait for the node and its subscriptions")
    p.add_argument("--drive-timeout", type=float, default=60.0,
                   help="controllers: seconds to wait for motion on the valid stream")
    p.add_argument("--margin", type=float, default=2.0,
                   help="controllers: seconds added to the documented stop bound (load)")
    p.add_argument("--skip-topic", action="append", default=[],
                   help="a subscribed topic not to fuzz (repeatable)")
    p.add_argument("--late-topic", action="append", default=[],
                   help="a subscribed topic whose messages end the node's work: fuzzed only "
                        "in the last 5 %% of the count (repeatable)")
    p.add_argument("--label", default="", help="name of the run in the summary (default: node)")
    p.add_argument("--summary-file", default="",
                   help="append a JSON summary of the run to this file")
    return p.parse_args(argv)


def run(args):
    # The fuzzer publishes synchronously on purpose (fuzz_watch.FuzzRun.publisher).
    warnings.filterwarnings("ignore", message=".*explicit keyword argument 'queue_size'")
    rospy.init_node("message_fuzzer_" + args.node.strip("/").replace("/", "_"),
                    anonymous=True, disable_signals=True)
    result = FuzzRun(args).run()
    line = format_summary(args.node, result)
    print(line, flush=True)
    for finding in result.findings + result.harness_errors:
        print("  " + finding, flush=True)
    if args.summary_file:  # one JSON object a line: scripts/fuzz_nodes.sh makes the table
        with open(args.summary_file, "a", encoding="utf-8") as f:
            f.write(json.dumps(summary_record(args, result, line)) + "\n")
    return result


def summary_record(args, r, line):
    return {"label": args.label or args.node, "node": args.node, "count": args.count, "seed": args.seed,
            "sent": sum(r.sent.values()),
            "topics": {t: [r.subscriptions[t], n] for t, n in sorted(r.sent.items())},
            "alive": r.alive, "outputs": sum(r.outputs.values()), "non_finite": r.non_finite,
            "motion": r.motion, "error_logs": r.error_logs, "exceptions": r.exceptions, "controller": r.controller, "ok": r.ok(),
            "findings": r.findings, "harness_errors": r.harness_errors, "line": line}


class MessageFuzzTest(unittest.TestCase):
    """The rostest face: one test, the whole run; its failures name the finding."""

    args = None

    def test_fuzz(self):
        result = run(self.args)
        report = "\n".join(result.findings)
        self.assertTrue(result.subscriptions, "the node subscribes to nothing")
        self.assertTrue(result.alive, "node died or hung:\n" + report)
        self.assertEqual(result.non_finite, 0, "non-finite outputs:\n" + report)
        self.assertEqual(result.motion, 0, "motion while inputs untrusted:\n" + report)
        self.assertFalse(result.harness_errors, "\n".join(result.harness_errors))


def main():
    argv = rospy.myargv(argv=sys.argv)[1:]
    under_rostest = any(a.startswith("--gtest_output") for a in argv)
    args = parse_args([a for a in argv if not a.startswith("--gtest_output") and a != "--text"])
    if under_rostest:
        import rostest  # pylint: disable=import-outside-toplevel
        MessageFuzzTest.args = args
        rostest.rosrun("radio_follow", "message_fuzz_" + args.node.strip("/"), MessageFuzzTest)
        return 0
    result = run(args)
    return 0 if result.ok() else 1


if __name__ == "__main__":
    sys.exit(main())
