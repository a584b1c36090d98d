# SPDX-License-Identifier: BSD-3-Clause
"""The valid input stream scripts/fuzz_messages.py drives a controller with, chosen by
the types the controller subscribes to (as test/ros/safety_attacks.cpp and
homing_simulator.hpp feed them): a target 4 m straight ahead, stamped now."""

import math
import time

import genpy

import fuzz_gen

TARGET_DISTANCE = 4.0  # m, well beyond the follow distance (1.6 m) and safe_distance
ESTIMATE_PERIOD = 0.05  # s, 20 Hz like the locator
RANGE_PERIOD = 0.1  # s, 10 Hz like a DWM1001 module


class ValidStream:
    def __init__(self, run, subscriptions):
        self.run = run
        self.by_type = {}
        for topic, type_name in sorted(subscriptions.items()):
            self.by_type.setdefault(type_name, []).append(topic)
        self.estimate_topics = self.by_type.get("radio_follow/TargetEstimate", [])
        self.range_topics = self.by_type.get("radio_follow/UwbRanges", [])
        self.odom_topics = self.by_type.get("nav_msgs/Odometry", [])
        self.bearing_topics = self.by_type.get("radio_follow/AoaBearing", [])
        self.enable_topics = [t for t in self.by_type.get("std_msgs/Bool", [])
                              if t.endswith("/enable")]
        self.anchor = str(run.param("target_anchor_id", "") or "ABCD")
        self.tag = str(run.param("tag_id", "") or "CCF9578E0D8A")
        rssi_at_1m = float(run.param("rssi_at_1m", -55.0))
        exponent = float(run.param("rssi_exponent", 2.0))
        self.rssi = rssi_at_1m - 10.0 * exponent * math.log10(TARGET_DISTANCE)
        self.next_estimate = 0.0
        self.next_range = 0.0

    def cls(self, topic):
        return fuzz_gen.message_class(self.run.result.subscriptions[topic])

    def tick(self, everything):
        """Sends what is due. everything=False: estimates (and enable) only."""
        now = time.monotonic()
        if now >= self.next_estimate:
            self.next_estimate = now + ESTIMATE_PERIOD
            for topic in self.estimate_topics:
                self.run.send(topic, self.estimate(topic), "valid", fuzz=False)
            for topic in self.enable_topics:
                msg = self.cls(topic)()
                msg.data = True
                self.run.send(topic, msg, "valid", fuzz=False)
            if everything:
                for topic in self.odom_topics:
                    self.run.send(topic, self.odometry(topic), "valid", fuzz=False)
        if everything and now >= self.next_range:
            self.next_range = now + RANGE_PERIOD
            for topic in self.range_topics:
                msg = self.range_message(topic)
                msg.ranges[0].range = TARGET_DISTANCE
                self.run.send(topic, msg, "valid", fuzz=False)
            for topic in self.bearing_topics:
                self.run.send(topic, self.bearing(topic), "valid", fuzz=False)

    def estimate(self, topic):
        e = self.cls(topic)()
        e.header.stamp = genpy.Time.from_sec(time.time())
        e.header.frame_id = "base_link"
        e.position.x = TARGET_DISTANCE
        e.range = TARGET_DISTANCE
        e.status = e.STATUS_OK
        e.sources = e.SOURCE_TWR
        e.position_covariance = [0.01, 0, 0, 0, 0.01, 0, 0, 0, 0.01]
        e.solver_cost = math.nan
        e.hypotheses = 1
        e.hypothesis_weight = 1.0
        return e

    def range_message(self, topic):
        """A range line from module 5722 to the target anchor, stamped now (range unset)."""
        msg = self.cls(topic)()
        msg.header.stamp = genpy.Time.from_sec(time.time())
        msg.header.frame_id = "uwb_5722"
        msg.tag_id = "5722"
        r = fuzz_gen.message_class("radio_follow/UwbRange")()
        r.anchor_id = self.anchor.upper()
        r.anchor_position.x = r.anchor_position.y = r.anchor_position.z = math.nan
        msg.ranges = [r]
        return msg

    def odometry(self, topic):
        o = self.cls(topic)()
        o.header.stamp = genpy.Time.from_sec(time.time())
        o.header.frame_id = "odom"
        o.child_frame_id = "base_link"
        o.pose.pose.orientation.w = 1.0
        return o

    def bearing(self, topic):
        b = self.cls(topic)()
        b.header.stamp = genpy.Time.from_sec(time.time())
        b.header.frame_id = "aoa_front"
        b.tag_id = self.tag
        b.rssi = self.rssi
        b.rssi_second = math.nan
        b.channel = 37
        b.event_counter = -1
        return b
