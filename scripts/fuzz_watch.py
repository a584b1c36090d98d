# SPDX-License-Identifier: BSD-3-Clause
"""The run of scripts/fuzz_messages.py: discovery, publishing, and the three watches
(alive, finite outputs, no motion while inputs are untrusted)."""

import collections
import http.client
import math
import os
import random
import re
import threading
import time
import xmlrpc.client

import rosgraph.masterapi
import roslib.message
import rospy
import yaml

import fuzz_gen
from fuzz_valid import ValidStream

# Topics never fuzzed: /clock is the ROS time itself (roscpp's, under /use_sim_time), not
# an input of the node's code; the simulator owns it.
SKIPPED_TOPICS = {"/clock"}

# Output fields where a non-finite value is a documented meaning, by message type:
ALLOWED_NON_FINITE = {
    # msg/TargetEstimate.msg: solver_cost "NaN when no solve ran" (particle estimator),
    # odom_velocity "NaN while unknown".
    "radio_follow/TargetEstimate": {"solver_cost", "odom_velocity"},
    # msg/AoaBearing.msg: rssi_second "NaN when not reported".
    "radio_follow/AoaBearing": {"rssi_second"},
    # msg/UwbRange.msg: anchor_position "NaN when the line did not report it".
    "radio_follow/UwbRange": {"anchor_position"},
    # REP 117: +inf no return within range_max, -inf closer than range_min, NaN error.
    "sensor_msgs/LaserScan": {"ranges"},
    # Live tuning's parameter bounds: dynamic_reconfigure writes +/-inf for a double
    # parameter declared without a bound (cfg/*.cfg). The defaults (dflt) must be finite.
    "dynamic_reconfigure/ConfigDescription": {"max", "min"},
}
# Strings that are JSON (the evaluator's report) are checked for NaN/inf tokens too.
NON_FINITE_TOKEN = re.compile(r"(?<![A-Za-z_])-?(nan|inf|infinity|NaN|Infinity)(?![A-Za-z_])")
# src/ros/common/callback_barrier.cpp: "callback X threw and was cut short (...); N so far".
CAUGHT = re.compile(r"threw and was cut short .*; (\d+) so far")
FINDING_DETAILS = 5  # details kept per kind of finding; all are counted
# Controllers: seconds of cmd_vel each motion check covers at least, after its bound: a
# small --count is spread over this time rather than sent before the check begins.
CHECKED_SECONDS = 5.0
# Ranges no UWB module measures that could still pass for "the person is far away". The
# other extremes (NaN, negative, -0, 5e-324) are below safe_distance and stop the robot by
# the too-close rule; the untrusted and final phases send them.
IMPLAUSIBLY_FAR = [math.inf, 1e300, 1.7976931348623157e308]


class Result:
    def __init__(self):
        self.subscriptions = {}  # topic -> type
        self.publications = {}
        self.sent = collections.Counter()
        self.valid_sent = 0
        self.outputs = collections.Counter()
        self.alive = True
        self.non_finite = 0
        self.motion = 0
        self.error_logs = 0  # ERROR/FATAL lines the node logged
        self.exceptions = 0  # exceptions its callback barrier caught
        self.controller = None  # dict of the controller checks, or None
        self.findings = []
        self.harness_errors = []

    def ok(self):
        return (bool(self.subscriptions) and self.alive and self.non_finite == 0
                and self.motion == 0 and not self.harness_errors)


def format_summary(node, r):
    sent = ", ".join("%s %s %d" % (t, r.subscriptions[t], n) for t, n in sorted(r.sent.items()))
    line = ("fuzz %s: sent %d (%s); node alive %s; outputs checked %d; non-finite %d; "
            "motion %d" % (node, sum(r.sent.values()), sent, "yes" if r.alive else "NO",
                           sum(r.outputs.values()), r.non_finite, r.motion))
    if r.controller:
        c = r.controller
        line += ("; controller: moved on the valid stream %s, bound %.2f s + margin %.1f s, "
                 "cmd_vel checked %d, longest cmd_vel gap %.2f s"
                 % ("yes" if c["drove"] else "NO", c["bound"], c["margin"], c["checked"],
                    c["max_gap"]))
    line += "; errors logged %d (callback exceptions caught %d)" % (r.error_logs, r.exceptions)
    if r.harness_errors:
        line += "; harness errors %d" % len(r.harness_errors)
    return line + ("; PASS" if r.ok() else "; FAIL")


class TimeoutTransport(xmlrpc.client.Transport):
    def __init__(self, timeout):
        super().__init__()
        self.timeout = timeout

    def make_connection(self, host):
        conn = super().make_connection(host)
        conn.timeout = self.timeout
        return conn


class Liveness(threading.Thread):
    """Alive = the process exists (not a zombie) and its XML-RPC getPid answers; three
    unanswered calls in a row (10 s each, generous for a loaded machine) mean hung."""

    def __init__(self, node, uri, on_death):
        super().__init__(daemon=True)
        self.node, self.uri, self.on_death = node, uri, on_death
        self.pid = None
        self.dead = threading.Event()
        self.stop = threading.Event()

    def get_pid(self):
        proxy = xmlrpc.client.ServerProxy(self.uri, transport=TimeoutTransport(10.0))
        code, _, pid = proxy.getPid(rospy.get_name())
        return pid if code == 1 else None

    def process_exists(self):
        try:
            with open("/proc/%d/stat" % self.pid, encoding="utf-8") as f:
                return f.read().rsplit(")", 1)[1].split()[0] != "Z"
        except OSError:
            return False

    def check(self):
        if self.pid is not None and not self.process_exists():
            return "process %d is gone" % self.pid
        for _ in range(3):
            try:
                if self.get_pid() is not None:
                    return None
            except (OSError, http.client.HTTPException, xmlrpc.client.Error):
                if self.pid is not None and not self.process_exists():
                    return "process %d is gone" % self.pid
        return "XML-RPC getPid unanswered 3 times"

    def run(self):
        self.pid = self.get_pid()
        while not self.stop.wait(0.5):
            why = self.check()
            if why:
                self.dead.set()
                self.on_death(why)
                return


def walk_non_finite(msg, path=""):
    """Yields (field path, value) of every non-finite float outside the allow-list."""
    allowed = ALLOWED_NON_FINITE.get(getattr(msg, "_type", ""), set())
    for slot, slot_type in zip(msg.__slots__, msg._slot_types):
        if slot in allowed:
            continue
        value = getattr(msg, slot)
        name = path + slot
        base, is_array, _ = fuzz_gen.parse_type(slot_type)
        items = list(value) if is_array and base not in fuzz_gen.BYTE_ARRAY_TYPES else None
        if fuzz_gen.is_message(base):
            for i, item in enumerate(items if is_array else [value]):
                yield from walk_non_finite(item, "%s%s." % (name, "[%d]" % i if is_array else ""))
        elif base in ("float64", "float32"):
            for i, v in enumerate(items if is_array else [value]):
                if not math.isfinite(v):
                    yield (name + ("[%d]" % i if is_array else ""), v)
        elif base == "string" and value[:1] in ("{", "[") and NON_FINITE_TOKEN.search(value):
            yield (name + " (JSON)", NON_FINITE_TOKEN.search(value).group(0))


def harvest_strings(params, found, depth=0):
    """Strings from the node's parameters, and from YAML files they name (layout ids)."""
    if isinstance(params, dict):
        for v in params.values():
            harvest_strings(v, found, depth)
    elif isinstance(params, list):
        for v in params:
            harvest_strings(v, found, depth)
    elif isinstance(params, str) and len(found) < 60:
        found.append(params)
        if depth == 0 and params.endswith(".yaml") and os.path.isfile(params):
            with open(params, encoding="utf-8") as f:
                harvest_strings(yaml.safe_load(f), found, 1)


class FuzzRun:
    def __init__(self, args):
        self.args = args
        self.node = args.node if args.node.startswith("/") else "/" + args.node
        self.result = Result()
        self.rng = random.Random(args.seed)
        self.master = rosgraph.masterapi.Master(rospy.get_name())
        self.lock = threading.Lock()
        self.recent = collections.deque(maxlen=6)  # (topic, description) of the last sends
        self.publishers = {}
        self.lost = set()  # topics whose connection the node dropped
        self.walkers = {}
        self.output_subs = {}
        self.liveness = None
        self.next_send = time.monotonic()
        self.rate = args.rate
        # Controller watch: cmd_vel after motion_from (monotonic) must be zero.
        self.cmd_topics = set()
        self.motion_from = None
        self.motion_until = None
        self.cmd_times = []
        self.drove = False

    # ---- findings ----
    def finding(self, kind, text):
        with self.lock:
            same = sum(1 for f in self.result.findings if f.startswith(kind))
            if same < FINDING_DETAILS:
                last = "; ".join("%s %s" % (t, d) for t, d in self.recent)
                self.result.findings.append("%s: %s; last sent: %s" % (kind, text, last))

    def on_death(self, why):
        self.result.alive = False
        self.finding("DEAD", "%s %s" % (self.node, why))

    # ---- discovery ----
    def discover(self):
        deadline = time.monotonic() + self.args.startup_timeout
        uri, last, stable_since = None, None, time.monotonic()
        while time.monotonic() < deadline:
            try:
                uri = self.master.lookupNode(self.node)
            except rosgraph.masterapi.Error:
                time.sleep(0.2)
                continue
            pubs, subs, _ = self.master.getSystemState()
            now = ([t for t, nodes in subs if self.node in nodes],
                   [t for t, nodes in pubs if self.node in nodes])
            if now != last:
                last, stable_since = now, time.monotonic()
            elif now[0] and time.monotonic() - stable_since > 2.0:
                break
            time.sleep(0.2)
        if uri is None:
            self.result.harness_errors.append("%s never registered" % self.node)
            return None
        types = dict(self.master.getTopicTypes())
        for t in last[0]:
            if t not in SKIPPED_TOPICS and t not in self.args.skip_topic and types.get(t, "*") != "*":
                self.result.subscriptions[t] = types[t]
        self.watch_outputs(types, last[1])
        return uri

    def watch_outputs(self, types, topics):
        for t in topics:
            if t in self.output_subs:
                continue
            self.result.publications[t] = types.get(t, "?")
            if t.rsplit("/", 1)[-1] == "cmd_vel" and types.get(t) == "geometry_msgs/Twist":
                self.cmd_topics.add(t)
            self.output_subs[t] = rospy.Subscriber(t, rospy.AnyMsg, self.on_output,
                                                   callback_args=t, queue_size=1000)

    def refresh_outputs(self):
        pubs, _, _ = self.master.getSystemState()
        topics = [t for t, nodes in pubs if self.node in nodes]
        if any(t not in self.output_subs for t in topics):
            self.watch_outputs(dict(self.master.getTopicTypes()), topics)

    # ---- outputs ----
    def on_output(self, raw, topic):
        header = getattr(raw, "_connection_header", {}) or {}
        if header.get("callerid") != self.node:
            return  # our own fuzz on a topic the node both reads and writes
        cls = roslib.message.get_message_class(header.get("type", ""))
        if cls is None:
            self.result.harness_errors.append("cannot decode %s (%s)" % (topic, header.get("type")))
            return
        msg = cls()
        msg.deserialize(raw._buff)
        received = time.monotonic()
        with self.lock:
            self.result.outputs[topic] += 1
        bad = list(walk_non_finite(msg))
        if bad:
            with self.lock:
                self.result.non_finite += 1
            self.finding("NON-FINITE", "%s %s %s" % (topic, header.get("type"), ", ".join(
                "%s=%s" % b for b in bad[:4])))
        if topic in self.cmd_topics:
            self.on_cmd(msg, received)
        if header.get("type") == "rosgraph_msgs/Log" and msg.level >= msg.ERROR:
            self.on_error_log(msg.msg)

    def on_error_log(self, text):
        """Reported, not failed: an exception the node's callback barrier caught is no
        crash, but names a callback that gave up on a message."""
        caught = CAUGHT.search(text)
        with self.lock:
            self.result.error_logs += 1
            if caught:
                self.result.exceptions = max(self.result.exceptions, int(caught.group(1)))
        self.finding("ERROR-LOG", text[:300])

    def on_cmd(self, twist, received):
        moving = any(v != 0.0 for v in (twist.linear.x, twist.linear.y, twist.linear.z,
                                         twist.angular.x, twist.angular.y, twist.angular.z))
        with self.lock:
            if moving and self.motion_from is None and self.motion_until is None:
                self.drove = True
            checking = (self.motion_from is not None and received >= self.motion_from
                        and (self.motion_until is None or received <= self.motion_until))
            if checking:
                self.cmd_times.append(received)
                if moving:
                    self.result.motion += 1
        if checking and moving:
            self.finding("MOTION", "cmd_vel linear.x=%g angular.z=%g" % (
                twist.linear.x, twist.angular.z))

    # ---- sending ----
    def publisher(self, topic, cls):
        if topic not in self.publishers:
            # queue_size=None: synchronous, so a counted message was written to the node.
            self.publishers[topic] = rospy.Publisher(topic, cls, queue_size=None)
        return self.publishers[topic]

    def wait_connections(self, topics, timeout=20.0):
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            if all(self.publishers[t].get_num_connections() > 0 for t in topics) and all(
                    s.get_num_connections() > 0 for s in self.output_subs.values()):
                return True
            time.sleep(0.1)
        missing = [t for t in topics if self.publishers[t].get_num_connections() == 0]
        if missing:
            self.result.harness_errors.append("no connection to %s on %s" % (self.node, missing))
        return not missing

    def pace(self):
        self.next_send = max(self.next_send + 1.0 / self.rate, time.monotonic() - 0.1)
        delay = self.next_send - time.monotonic()
        if delay > 0:
            time.sleep(delay)

    def send(self, topic, msg, description, fuzz=True):
        if fuzz:  # the valid stream keeps its own rate
            self.pace()
        try:
            self.publishers[topic].publish(msg)
        except (rospy.ROSSerializationException, rospy.ROSException) as e:
            self.result.harness_errors.append("%s: %s (%s)" % (topic, e, description))
            return
        if fuzz:
            self.recent.append((topic, description))
            self.result.sent[topic] += 1
        else:
            self.result.valid_sent += 1

    # ---- message streams ----
    def messages(self, topic, stamps, strings):
        """Extremes sweep of every leaf (mode extremes/both), then random combinations."""
        walker = self.walkers.setdefault(topic, fuzz_gen.Walker(self.result.subscriptions[topic]))
        if self.args.mode in ("extremes", "both"):
            probe = fuzz_gen.Picker(self.rng, strings, stamps)
            sweep = [(path, v) for path, values in walker.leaves() for v in probe.extremes(values)]
            while True:
                for path, value in sweep:
                    picker = fuzz_gen.ExtremePicker(self.rng, strings, stamps, path, value)
                    yield walker.build(picker), "extreme " + fuzz_gen.describe(path, value)
                if self.args.mode == "extremes":
                    continue
                break
        index = 0
        while True:
            picker = fuzz_gen.RandomPicker(self.rng, strings, stamps, walker)
            msg = walker.build(picker)
            index += 1
            chosen = ", ".join(fuzz_gen.describe(p, v, 30) for p, v in picker.chosen[:6])
            yield msg, "random #%d (seed %d) %s" % (index, self.args.seed, chosen or "-")

    def spread(self, count, seconds):
        """Sends the next `count` messages over at least `seconds`."""
        self.rate = min(self.args.rate, count / seconds) if count > 0 else self.args.rate

    def fuzz(self, count, topics, stamps, strings, between=None):
        if not topics or count <= 0:
            return
        streams = {t: self.messages(t, stamps, strings) for t in topics}
        last_refresh = time.monotonic()
        for i in range(count):
            if self.liveness.dead.is_set():
                return
            topic = topics[i % len(topics)]
            msg, description = next(streams[topic])
            self.send(topic, msg, description)
            if between:
                between()
            if time.monotonic() - last_refresh > 5.0:
                last_refresh = time.monotonic()
                self.refresh_outputs()
                self.check_connections(topics)

    def check_connections(self, topics):
        """A connection the node dropped (roscpp does on a message it cannot take) would
        make the rest of the count go nowhere: a harness error, unless the node died."""
        for topic in topics:
            if self.publishers[topic].get_num_connections() == 0 and \
                    not self.liveness.dead.is_set() and topic not in self.lost:
                self.lost.add(topic)
                self.result.harness_errors.append(
                    "%s dropped its connection on %s after %d messages; last sent: %s" % (
                        self.node, topic, self.result.sent[topic],
                        "; ".join("%s %s" % (t, d) for t, d in self.recent)))

    # ---- the run ----
    def strings(self):
        found = []
        try:
            harvest_strings(self.master.getParam(self.node), found)
        except rosgraph.masterapi.Error:
            pass
        pool = ["base_link", "odom", "ABCD", "5722", "CCF9578E0D8A", "uwb_5722", "map"]
        return list(dict.fromkeys(pool + [s for s in found if len(s) < 200]))

    def run(self):
        uri = self.discover()
        if uri is None or not self.result.subscriptions:
            return self.result
        for topic, type_name in self.result.subscriptions.items():
            self.publisher(topic, fuzz_gen.message_class(type_name))
        self.liveness = Liveness(self.node, uri, self.on_death)
        self.liveness.start()
        topics = sorted(self.result.subscriptions)
        self.wait_connections(topics)
        strings = self.strings()
        if self.cmd_topics:
            self.run_controller(topics, strings)
        else:
            # A --late-topic ends the node's work (the evaluator's ground_truth/finished):
            # sent only in the last 5 % of the count, so the rest meets a working node.
            early = [t for t in topics if t not in self.late_topics()]
            first = int(self.args.count * 0.95) if len(early) < len(topics) else self.args.count
            self.fuzz(first, early, "any", strings)
            self.fuzz(self.args.count - first, topics, "any", strings)
        time.sleep(1.0)  # the last messages reach the node
        self.check_connections(topics)
        if not self.liveness.dead.is_set():
            why = self.liveness.check()
            if why:
                self.on_death(why)
        self.liveness.stop.set()
        return self.result

    def late_topics(self):
        return {t if t.startswith("/") else "/" + t for t in self.args.late_topic}

    def param(self, name, default):
        try:
            return self.master.getParam(self.node + "/" + name)
        except rosgraph.masterapi.Error:
            return default

    def run_controller(self, topics, strings):
        """Valid stream until it moves; then untrusted fuzz (stamps never near now) and
        implausible ranges next to valid estimates, cmd_vel zero after the bound; last a
        fuzz of every stamp, checked for life and finiteness only."""
        rate = float(self.param("rate", 20.0))
        bound = float(self.param("estimate_timeout", 0.5)) + 1.0 / rate
        info = {"drove": False, "bound": bound, "margin": self.args.margin, "checked": 0,
                "max_gap": 0.0}
        self.result.controller = info
        valid = ValidStream(self, self.result.subscriptions)
        deadline = time.monotonic() + self.args.drive_timeout
        while not self.drove and time.monotonic() < deadline and not self.liveness.dead.is_set():
            valid.tick(everything=True)
            time.sleep(0.01)
        info["drove"] = self.drove
        if not self.drove:
            self.result.harness_errors.append(
                "the valid stream never made %s move: the motion check would prove nothing"
                % self.node)
            return
        with self.lock:
            self.motion_from = time.monotonic() + bound + self.args.margin
        range_topics = valid.range_topics if valid.estimate_topics else []
        # Over half of the count goes to the final phase: stamps near now reach the laws
        # (the untrusted phase stops them at the safety layer).
        untrusted = int(self.args.count * (0.35 if range_topics else 0.45))
        implausible = int(self.args.count * 0.1) if range_topics else 0
        self.spread(untrusted, bound + self.args.margin + CHECKED_SECONDS)
        self.fuzz(untrusted, topics, "untrusted", strings)
        if implausible:
            hold = float(self.param("hold_time", 1.0)) + float(self.param("range_timeout", 1.0))
            self.spread(implausible, hold + self.args.margin + CHECKED_SECONDS)
            # Estimates stay valid; the ranges claim "far away" with values no module
            # measures: the range watch must not count them as fresh.
            self.fuzz_implausible_ranges(implausible, range_topics, valid, strings)
        if not self.liveness.dead.is_set():
            self.wait_for_cmd(10.0)
        with self.lock:
            self.motion_until = time.monotonic()
            times = list(self.cmd_times)
        info["checked"] = len(times)
        gaps = [b - a for a, b in zip(times, times[1:])]
        info["max_gap"] = max(gaps) if gaps else math.inf
        if not times and not self.liveness.dead.is_set():
            self.finding("DEAD", "no cmd_vel while the inputs were untrusted")
            self.result.alive = False
        self.rate = self.args.rate
        self.fuzz(self.args.count - untrusted - implausible, topics, "any", strings)

    def wait_for_cmd(self, timeout):
        """cmd_vel keeps arriving: a controller that stopped publishing is dead."""
        mark = time.monotonic()
        deadline = mark + timeout
        while time.monotonic() < deadline:
            with self.lock:
                if self.cmd_times and self.cmd_times[-1] >= mark:
                    return True
            time.sleep(0.05)
        self.finding("DEAD", "no cmd_vel for %.0f s after the fuzz" % timeout)
        self.result.alive = False
        return False

    def fuzz_implausible_ranges(self, count, range_topics, valid, strings):
        for i in range(count):
            if self.liveness.dead.is_set():
                return
            valid.tick(everything=False)
            topic = range_topics[i % len(range_topics)]
            value = self.rng.choice(IMPLAUSIBLY_FAR)
            msg = valid.range_message(topic)
            msg.ranges[0].range = value
            if self.rng.random() < 0.3:  # more ranges in the line, all implausible
                for _ in range(self.rng.randint(1, 4)):
                    extra = type(msg.ranges[0])()
                    extra.anchor_id = self.rng.choice(strings)
                    extra.range = self.rng.choice(IMPLAUSIBLY_FAR)
                    msg.ranges.append(extra)
            self.send(topic, msg, "implausible range %r stamped now, anchor %s" % (
                value, msg.ranges[0].anchor_id))
