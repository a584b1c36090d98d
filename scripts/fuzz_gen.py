# SPDX-License-Identifier: BSD-3-Clause
"""Builds ROS messages of any genpy class for scripts/fuzz_messages.py.

A leaf is a field path, e.g. ('ranges', '[]', 'range'): '[]' stands for the elements of
an array, ('ranges', '#len') for its length. Every leaf has a list of extreme values; a
message is built by asking a picker for each leaf's value, so one walker serves the
extremes sweep (one leaf extreme, the others a plausible default) and the random mode.
"""

import math
import time

import genpy
import roslib.message

FLOAT64_EXTREMES = [math.nan, math.inf, -math.inf, 1e300, -1e300, -0.0, 5e-324,
                    1.7976931348623157e308]
# float32 cannot carry 1e300 (struct refuses it): its largest finite value stands in.
FLOAT32_EXTREMES = [math.nan, math.inf, -math.inf, 3.4028234663852886e38,
                    -3.4028234663852886e38, -0.0, 1e-45]
# Empty, huge, non-ASCII UTF-8, an embedded NUL. (Invalid UTF-8 cannot be sent: genpy
# encodes every str field itself.)
STRING_EXTREMES = ["", "x" * 100000, "\u03a9\u00df\u6f22\u5b57", "a\x00b"]
INT_RANGES = {
    "int8": (-2**7, 2**7 - 1), "byte": (-2**7, 2**7 - 1),
    "uint8": (0, 2**8 - 1), "char": (0, 2**8 - 1),
    "int16": (-2**15, 2**15 - 1), "uint16": (0, 2**16 - 1),
    "int32": (-2**31, 2**31 - 1), "uint32": (0, 2**32 - 1),
    "int64": (-2**63, 2**63 - 1), "uint64": (0, 2**64 - 1),
}
BYTE_ARRAY_TYPES = ("uint8", "char")
# Seconds of a stamp: 'now+' / 'now-' are resolved when the message is built.
STAMP_SECS = [0, 1, 2**31 - 1, 2**31, 2**32 - 1, "now+1e6", "now-1e6"]
STAMP_NSECS = [0, 999999999]
DURATION_SECS = [-2**31, -1, 0, 1, 2**31 - 1]
HUGE_ARRAY = 10000
# A stamp this close to now (either way) may be trusted by a node; untrusted stamps keep
# further away. 2 s: above estimate_timeout (0.5 s), range_timeout (1 s) and the 50 ms
# future tolerance (include/radio_follow/common/time_policy.hpp).
TRUST_WINDOW = 2.0


def parse_type(type_str):
    """'float64[9]' -> ('float64', True, 9); 'Header' -> ('std_msgs/Header', False, None)."""
    base, is_array, size = type_str, False, None
    if type_str.endswith("]"):
        base, _, dim = type_str[:-1].partition("[")
        is_array, size = True, (int(dim) if dim else None)
    if base == "Header":
        base = "std_msgs/Header"
    return base, is_array, size


def is_message(base):
    return "/" in base


def message_class(base):
    cls = roslib.message.get_message_class(base)
    if cls is None:
        raise RuntimeError("message type %s is not known here (package not built?)" % base)
    return cls


def uint8_constants(cls):
    return sorted(v for k, v in vars(cls).items()
                  if k.isupper() and isinstance(v, int) and not isinstance(v, bool))


def resolve_secs(spec, now):
    if spec == "now+1e6":
        return min(int(now + 1e6), 2**32 - 1)
    if spec == "now-1e6":
        return max(int(now - 1e6), 0)
    return spec


def primitive_extremes(base, cls):
    if base == "float64":
        return FLOAT64_EXTREMES
    if base == "float32":
        return FLOAT32_EXTREMES
    if base == "string":
        return STRING_EXTREMES
    if base == "bool":
        return [False, True, 2, 255]  # 2, 255: non-canonical bools on the wire
    if base == "time":
        return [("time", s, n) for s in STAMP_SECS for n in STAMP_NSECS]
    if base == "duration":
        return [("duration", s, n) for s in DURATION_SECS for n in STAMP_NSECS]
    lo, hi = INT_RANGES[base]
    values = {lo, hi, 0, 1}
    if lo < 0:
        values.add(-1)
    constants = uint8_constants(cls) if base in ("uint8", "char") else []
    if constants:
        values |= {max(constants) + 1, 255}  # unknown enum values
    return sorted(values)


class Walker:
    """Leaves and message construction for one root type."""

    def __init__(self, root_type):
        self.root_type = root_type
        self._leaves = None

    def leaves(self):
        if self._leaves is None:
            self._leaves = []
            self._collect(self.root_type, (), None)
        return self._leaves

    def _collect(self, type_str, path, parent_cls):
        base, is_array, size = parse_type(type_str)
        if is_array:
            if size is None:
                self._leaves.append((path + ("#len",), [0, HUGE_ARRAY]))
            self._collect(base, path + ("[]",), parent_cls)
        elif is_message(base):
            cls = message_class(base)
            for slot, slot_type in zip(cls.__slots__, cls._slot_types):
                self._collect(slot_type, path + (slot,), cls)
        else:
            self._leaves.append((path, primitive_extremes(base, parent_cls)))

    def build(self, picker):
        return self._make(self.root_type, (), None, picker)

    def _make(self, type_str, path, parent_cls, picker):
        base, is_array, size = parse_type(type_str)
        if is_array:
            length = size if size is not None else picker.length(path + ("#len",))
            elem_path = path + ("[]",)
            if length >= HUGE_ARRAY:  # one element repeated: cheap to build
                # ...and small: 10,000 copies of a 100,000-character string would pass
                # roscpp's 1 GB message limit, which drops the connection.
                picker.in_huge += 1
                values = [self._make(base, elem_path, parent_cls, picker)] * length
                picker.in_huge -= 1
            else:
                values = [self._make(base, elem_path, parent_cls, picker) for _ in range(length)]
            if base in BYTE_ARRAY_TYPES:
                return bytes(int(v) & 0xFF for v in values)
            return values
        if is_message(base):
            cls = message_class(base)
            msg = cls()
            for slot, slot_type in zip(cls.__slots__, cls._slot_types):
                setattr(msg, slot, self._make(slot_type, path + (slot,), cls, picker))
            return msg
        return to_value(picker.value(path, base, parent_cls), picker.now)


def to_value(v, now):
    if isinstance(v, tuple) and v and v[0] in ("time", "duration"):
        secs = resolve_secs(v[1], now)
        return genpy.Time(secs, v[2]) if v[0] == "time" else genpy.Duration(secs, v[2])
    return v


def untrusted_stamp(v, now):
    """A time extreme a node must not take as fresh (zero counts as 'now' in the nodes)."""
    t = to_value(v, now)
    return not t.is_zero() and abs(t.to_sec() - now) >= TRUST_WINDOW


class Picker:
    """Plausible defaults; `stamps` is 'any' or 'untrusted' (never near now, never 0)."""

    def __init__(self, rng, strings, stamps="any"):
        self.rng = rng
        self.strings = strings
        self.stamps = stamps
        self.now = time.time()
        self.in_huge = 0  # > 0 while building the element of a 10,000-element array

    def refresh(self):
        self.now = time.time()

    def length(self, path):
        return 1

    def value(self, path, base, cls):
        return self.default(path, base, cls)

    def default(self, path, base, cls):
        if base in ("float64", "float32"):
            # A quaternion's plausible default is the identity.
            return 1.0 if path[-1] == "w" and cls is not None and cls._type.endswith(
                "/Quaternion") else 0.0
        if base == "string":
            return "base_link" if path[-1] == "frame_id" else self.strings[0]
        if base == "bool":
            return True
        if base == "time":
            return self.stamp()
        if base == "duration":
            return genpy.Duration(0, 0)
        constants = uint8_constants(cls) if base in ("uint8", "char") and cls else []
        nonzero = [c for c in constants if c > 0]
        return min(nonzero) if nonzero else 0

    def stamp(self):
        if self.stamps == "untrusted":
            offset = self.rng.choice([-1.0, 1.0]) * self.rng.uniform(TRUST_WINDOW, 1000.0)
            return genpy.Time.from_sec(max(self.now + offset, 1.0))
        return genpy.Time.from_sec(self.now)

    def extremes(self, values):
        if self.stamps == "untrusted" and values and isinstance(values[0], tuple) \
                and values[0][0] == "time":
            return [v for v in values if untrusted_stamp(v, self.now)]
        return values


class ExtremePicker(Picker):
    """Every leaf at its default except `target`, which takes `target_value`."""

    def __init__(self, rng, strings, stamps, target, target_value):
        super().__init__(rng, strings, stamps)
        self.target = target
        self.target_value = target_value

    def length(self, path):
        if path == self.target:
            return self.target_value
        return 1

    def value(self, path, base, cls):
        if path == self.target:
            return self.target_value
        return self.default(path, base, cls)


class RandomPicker(Picker):
    """Each leaf an extreme with probability p_extreme, else a plausible random value.
    Records the extremes it chose (the repro of a finding)."""

    P_EXTREME = 0.15
    P_HUGE = 0.002  # keeps 10,000-element arrays rare: they cost ~0.1 s each

    def __init__(self, rng, strings, stamps, walker):
        super().__init__(rng, strings, stamps)
        self.extreme_of = dict(walker.leaves())
        self.chosen = []

    def length(self, path):
        r = self.rng.random()
        if r < self.P_HUGE and not self.in_huge:
            self.chosen.append((path, HUGE_ARRAY))
            return HUGE_ARRAY
        if r < 0.15:
            return 0
        return 1 if r < 0.75 else self.rng.randint(2, 5)

    def value(self, path, base, cls):
        values = self.extremes(self.extreme_of.get(path, []))
        if self.in_huge:
            values = [v for v in values if not (isinstance(v, str) and len(v) > 100)]
        if values and self.rng.random() < self.P_EXTREME:
            v = self.rng.choice(values)
            self.chosen.append((path, v))
            return v
        return self.plausible(path, base, cls)

    def plausible(self, path, base, cls):
        rng = self.rng
        if base in ("float64", "float32"):
            return rng.uniform(-20.0, 20.0)
        if base == "string":
            return rng.choice(self.strings)
        if base == "bool":
            return rng.random() < 0.5
        if base == "time":
            return self.stamp() if self.stamps == "untrusted" else genpy.Time.from_sec(
                self.now + rng.uniform(-0.5, 0.02))
        if base == "duration":
            return genpy.Duration.from_sec(rng.uniform(-5.0, 5.0))
        constants = uint8_constants(cls) if base in ("uint8", "char") and cls else []
        if constants and rng.random() < 0.8:
            return rng.choice(constants)
        lo, hi = INT_RANGES[base]
        return rng.randint(max(lo, -10), min(hi, 100))


def describe(path, value, limit=60):
    """'ranges[].range=inf' with long values shortened."""
    name = ".".join(path).replace(".[]", "[]").replace(".#len", ".length")
    if isinstance(value, tuple) and value and value[0] in ("time", "duration"):
        text = "%s(%s, %s)" % value
    elif isinstance(value, str) and len(value) > 20:
        text = "'%s...' (%d chars)" % (value[:8], len(value))
    else:
        text = repr(value)
    return "%s=%s" % (name, text[:limit])
