#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Turns a real UWB recording with motion-capture ground truth into a bag the offline
tools read (doc/real_recordings.md): the LIAS planar dataset shipped in
test/data/real/lias_planar/ (three DWM1000-class tags on a trolley, eight anchors on
the walls, 100 Hz, a motion-capture pose of the trolley).

Our system has the modules on the robot and one tag on the person. Here the trolley is
the robot, its three tags are our three modules (IDs T0-T2, at the dataset's coordinates
in the trolley's frame), and each of the eight anchors (IDs A0-A7) is a person standing
still while the robot drives: a layout whose `target.uwb_anchor_id` is A<k> tracks anchor
k. The bag holds
  uwb/T<i>/ranges            radio_follow/UwbRanges, one per tag per epoch, the ranges as
                             recorded (no correction), a missing range left out;
  /tf                        odom -> base_link from the motion capture (position on the
                             floor, yaw only: the trolley is level within 2 deg);
  ground_truth/anchor_A<k>   geometry_msgs/PointStamped, anchor k in base_link.
Stamps are the recording's own clock (the UWB and motion-capture rows share it; the
range residuals are smallest at zero offset, doc/real_recordings.md). The message
stamp is also the bag's receive time.

Usage: real_recording_bag.py RUN OUT.bag [--data DIR] [--layout OUT.yaml]
  RUN: fast or mid (the dataset's trolley speeds, 0.49 and 0.23 m/s), or
       static_pos<P>_deg<D> (P 1-5, D 0 or 180: the trolley parked at the pose the
       dataset's static README gives, 2022-08-14; no motion capture: the pose is
       published at 20 Hz).
  --layout: also write the trolley's layout (target anchor A0; change
            target.uwb_anchor_id to track another).
"""
import argparse
import csv
import datetime
import io
import lzma
import math
import sys
from pathlib import Path

REPO = Path(__file__).resolve().parent.parent
DATA = REPO / "test" / "data" / "real" / "lias_planar"

# The dataset's README (Planar_Dataset/Dynamic): tag coordinates in the trolley's frame
# and anchor coordinates in the motion-capture frame, metres.
TAGS = [(-0.0689, -0.1423, 0.0011), (-0.0750, 0.1402, 0.0016), (0.2034, 0.1451, -0.0008)]
ANCHORS = [(-3.4203, 3.0053, 1.0442), (0.0016, 3.0110, 1.0446), (3.6056, 2.9795, 1.0463),
           (3.6011, -0.0008, 1.0422), (3.5674, -3.0087, 1.0443), (-0.0072, -2.9652, 1.0444),
           (-3.4673, -2.9587, 1.0445), (-3.4858, -0.0098, 1.0457)]
# Height of the tags above the floor: the motion capture's mean body height in both
# drives (this script prints it: 0.971 fast, 0.972 mid) plus the tags' own z, m. The
# layout's modules sit there.
TAG_HEIGHT = 0.970
TAG_IDS = ["T%d" % i for i in range(len(TAGS))]
# The static runs' trolley poses (Planar_Dataset/Static/README.md, 2022/8/14): yaw in
# degrees, x, y in metres, for the headings near 0 and 180 deg.
STATIC_POSES = {
    (1, 0): (-0.019, -1.9298, -1.2368), (1, 180): (181.993, -1.7472, -1.2375),
    (2, 0): (0.0230, 1.7393, -1.2132), (2, 180): (181.798, 1.8838, -1.1936),
    (3, 0): (1.375, 1.7362, 1.2086), (3, 180): (180.125, 1.8451, 1.2942),
    (4, 0): (0.322, -1.8708, 1.1814), (4, 180): (180.987, -1.7564, 1.1908),
    (5, 0): (0.233, -0.0475, -0.0122), (5, 180): (180.886, 0.0625, 0.0558),
}
STATIC_RUNS = ["static_pos%d_deg%d" % key for key in sorted(STATIC_POSES)]
RUNS = ["fast", "mid"] + STATIC_RUNS
POSE_RATE = 20.0  # Hz, the static runs' published pose
ANCHOR_IDS = ["A%d" % k for k in range(len(ANCHORS))]


def stamp(text):
    """Seconds of the recording's wall-clock string (its zone does not matter: both
    files use the same one)."""
    t = datetime.datetime.strptime(text, "%Y-%m-%d %H:%M:%S.%f")
    return (t - datetime.datetime(1970, 1, 1)).total_seconds()


def rows(path):
    with lzma.open(path, "rt") as f:
        yield from csv.reader(io.StringIO(f.read()))


def read_uwb(path):
    """([(t, [[range or None per anchor] per tag])], malformed lines dropped); column
    1 + 3 k + i is anchor k, tag i."""
    out = []
    dropped = 0
    fields = 1 + len(ANCHORS) * len(TAGS)
    for row in rows(path):
        # Some static files end every line with empty fields: allowed. A line with more
        # values (a few in the static files: the logger ran two lines together) or fewer
        # is malformed: counted and dropped, the rest goes on.
        if len(row) < fields or any(cell.strip() for cell in row[fields:]):
            dropped += 1
            continue
        ranges = [[None] * len(ANCHORS) for _ in TAGS]
        try:
            for k in range(len(ANCHORS)):
                for i in range(len(TAGS)):
                    cell = row[1 + 3 * k + i].strip()
                    ranges[i][k] = float(cell) if cell else None
            t = stamp(row[0])
        except ValueError:
            dropped += 1  # a field that is not a number, or a bad stamp
            continue
        out.append((t, ranges))
    return out, dropped


def read_mocap(path):
    """([(t, x, y, yaw)], [z]), stamps strictly increasing: the body's position and the
    heading of its frame's x axis, and its height (columns: time, x, y, z, qw, qx, qy, qz;
    the body frame is upside down, so the tags' coordinates are in the heading-only frame:
    the yaw is the x axis's)."""
    out = []
    heights = []
    for line, row in enumerate(rows(path), 1):
        if line == 1:
            continue  # header
        t = stamp(row[0])
        if out and t <= out[-1][0]:
            continue  # a repeated (or backward) stamp: a second pose at one time
        x, y, z, qw, qx, qy, qz = (float(v) for v in row[1:8])
        # First column of the rotation matrix: the body x axis in the world.
        yaw = math.atan2(2.0 * (qx * qy + qz * qw), 1.0 - 2.0 * (qy * qy + qz * qz))
        out.append((t, x, y, yaw))
        heights.append(z)
    return out, heights


def motion_summary(poses, heights):
    """The drive's figures doc/real_recordings.md quotes: body height, speed, turn rate."""
    speeds, turns = [], []
    for (t0, x0, y0, a0), (t1, x1, y1, a1) in zip(poses, poses[1:]):
        dt = t1 - t0
        speeds.append(math.hypot(x1 - x0, y1 - y0) / dt)
        turns.append(abs(math.degrees(math.remainder(a1 - a0, 2.0 * math.pi))) / dt)
    turns.sort()
    return ("body height mean %.3f m, mean speed %.2f m/s, turn rate median %.0f deg/s, "
            "p90 %.0f deg/s" % (sum(heights) / len(heights), sum(speeds) / len(speeds),
                                turns[len(turns) // 2], turns[int(0.9 * (len(turns) - 1))]))


def write_layout(path):
    with open(path, "w") as f:
        f.write("# The LIAS planar dataset's trolley (scripts/real_recording_bag.py): three\n"
                "# DWM1000-class tags as the robot's modules, uncalibrated. The target is one\n"
                "# of the eight wall anchors: set uwb_anchor_id to A0-A7.\n"
                "fixed_frame: base_link\n"
                "target:\n"
                "  uwb_anchor_id: \"A0\"\n"
                "twr_modules:\n")
        for tag_id, (x, y, z) in zip(TAG_IDS, TAGS):
            f.write("  - {id: \"%s\", position: [%.4f, %.4f, %.4f]}\n" %
                    (tag_id, x, y, TAG_HEIGHT + z))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("run", choices=RUNS)
    parser.add_argument("out")
    parser.add_argument("--data", default=str(DATA))
    parser.add_argument("--layout")
    args = parser.parse_args()

    import rosbag
    import rospy
    from geometry_msgs.msg import PointStamped, TransformStamped
    from tf2_msgs.msg import TFMessage
    from radio_follow.msg import UwbRange, UwbRanges

    data = Path(args.data)
    uwb, dropped = read_uwb(data / ("uwb_%s.csv.xz" % args.run))
    if args.run in STATIC_RUNS:
        pos, deg = (int(v) for v in args.run[len("static_pos"):].split("_deg"))
        yaw, x, y = STATIC_POSES[(pos, deg)]
        count = int((uwb[-1][0] - uwb[0][0]) * POSE_RATE) + 2
        mocap = [(uwb[0][0] - 0.5 + k / POSE_RATE, x, y, math.radians(yaw))
                 for k in range(count + int(POSE_RATE))]
        motion = "parked at the dataset's pose"
    else:
        mocap, heights = read_mocap(data / ("mocap_%s.csv.xz" % args.run))
        motion = motion_summary(mocap, heights)
    messages = []  # (t, topic, message)
    for t, ranges in uwb:
        for tag_id, tag_ranges in zip(TAG_IDS, ranges):
            msg = UwbRanges()
            msg.header.stamp = rospy.Time.from_sec(t)
            msg.header.frame_id = "uwb_" + tag_id
            msg.tag_id = tag_id
            for anchor_id, (ax, ay, az), r in zip(ANCHOR_IDS, ANCHORS, tag_ranges):
                if r is None:
                    continue
                m = UwbRange()
                m.anchor_id = anchor_id
                m.anchor_position.x, m.anchor_position.y, m.anchor_position.z = ax, ay, az
                m.range = r
                msg.ranges.append(m)
            messages.append((t, "uwb/%s/ranges" % tag_id, msg))
    for t, x, y, yaw in mocap:
        tf = TransformStamped()
        tf.header.stamp = rospy.Time.from_sec(t)
        tf.header.frame_id = "odom"
        tf.child_frame_id = "base_link"
        tf.transform.translation.x, tf.transform.translation.y = x, y
        tf.transform.rotation.z = math.sin(0.5 * yaw)
        tf.transform.rotation.w = math.cos(0.5 * yaw)
        messages.append((t, "/tf", TFMessage(transforms=[tf])))
        c, s = math.cos(yaw), math.sin(yaw)
        for anchor_id, (ax, ay, az) in zip(ANCHOR_IDS, ANCHORS):
            p = PointStamped()
            p.header = tf.header.__class__()
            p.header.stamp = tf.header.stamp
            p.header.frame_id = "base_link"
            dx, dy = ax - x, ay - y
            p.point.x, p.point.y, p.point.z = c * dx + s * dy, -s * dx + c * dy, az
            messages.append((t, "ground_truth/anchor_" + anchor_id, p))
    messages.sort(key=lambda m: m[0])
    with rosbag.Bag(args.out, "w") as bag:
        for t, topic, msg in messages:
            bag.write(topic, msg, rospy.Time.from_sec(t))
    if args.layout:
        write_layout(args.layout)
    print("%s: %d UWB epochs (%d malformed lines dropped), %d poses, %.1f s; %s" %
          (args.out, len(uwb), dropped, len(mocap), uwb[-1][0] - uwb[0][0], motion))


if __name__ == "__main__":
    main()
