#!/usr/bin/env python3
"""Writes the seed corpora of the fuzz targets (tests/fuzz/corpus/*) from readable programs.

The byte layout follows byte_reader.hpp and the targets' decoders; run it again after changing
either. Usage: python3 tests/fuzz/make_seeds.py (from anywhere)."""
import json
import pathlib
import struct

HERE = pathlib.Path(__file__).resolve().parent
SCALES = [1e-3, 1e-2, 1.0, 10.0, 100.0, 1000.0, 1e4, 1e5]


def num(value):
    """ByteReader::number() bytes for a plausible value (or a special: 'nan', 'inf', '-inf', 0)."""
    if value == "nan":
        return bytes([0x01])
    if value == "inf":
        return bytes([0x02])
    if value == "-inf":
        return bytes([0x82])
    if value == "huge":
        return bytes([0x05, 0])
    if value == "denormal":
        return bytes([0x03, 0])
    if value == 0:
        return bytes([0x00])
    sign = 0x80 if value < 0 else 0
    mag = abs(value)
    for i, unit in enumerate(SCALES):
        if mag <= unit * 10.0:
            u = round(mag / (unit * 10.0) * 65535)
            return bytes([sign | (i << 4) | 0x08]) + struct.pack(">H", u)
    raise ValueError(value)


def blocks_program(cycle=0, variants=(0,), ops=()):
    out = bytes([cycle, len(variants) - 1]) + bytes(variants)
    for op in ops:
        out += op
    return out


def run(axis, k):
    return bytes([axis, 10, k - 1])


def absolute(axis, pos, v, a=0, d=0, j=0):
    return bytes([axis, 0, 1]) + num(pos) + num(v) + num(a) + num(d) + num(j) + bytes([1])


def relative(axis, dist, v):
    return bytes([axis, 0, 2]) + num(dist) + num(v) + num(0) + num(0) + num(0) + bytes([1])


def velocity(axis, v, direction=0):
    return bytes([axis, 0, 4]) + num(v) + num(0) + num(0) + num(0) + bytes([1, direction])


def execute(axis, kind):
    return bytes([axis, 0, kind])


def halt(axis, dec=0, jerk=0):
    return bytes([axis, 0, 5]) + num(dec) + num(jerk) + bytes([1])


def stop(axis, dec=0, jerk=0):
    return bytes([axis, 0, 6]) + num(dec) + num(jerk)


def new_pos(axis, pos):
    return bytes([axis, 0, 7]) + num(pos)


def new_pos_and_velo(axis, pos, velo, apos):
    return bytes([axis, 0, 8]) + num(pos) + num(velo) + num(apos)


def superimposed(axis, d, vk, ak, dk, vp, length):
    return bytes([axis, 0, 9]) + num(d) + num(vk) + num(ak) + num(dk) + num(vp) + num(length)


def ext_enable(axis, pos, relative_type=False):
    return bytes([axis, 0, 11]) + num(pos) + bytes([1 if relative_type else 0])


def feed(axis, p, v, a, direction):
    return bytes([axis, 6, 1]) + num(p) + num(v) + num(a) + bytes([direction + 1])


def override(axis, factor):
    return bytes([axis, 5, 1]) + num(factor)


def burst(axis, k, dist, v):
    return bytes([axis, 8, k - 1]) + num(dist) + num(v)


def fault(axis, which):
    return bytes([axis, 9, which])


def gear_in(slave, master, ratio, denominator=None):
    """Toggles the slave's MC_GearIn Execute (a rising edge when it was off): coupling programs."""
    den = bytes([0]) if denominator is None else bytes([1]) + struct.pack(">H", denominator)
    return bytes([slave, 12]) + num(ratio) + den + bytes([master])


def gear_out(slave):
    return bytes([slave, 13])


COUPLING = 0x80  # first byte: a coupling program (MC_GearIn / MC_GearOut operations)
FEATURES = 0x10  # first byte: a feature program (homing, two-speed, C6-C8; coupling ops too)


def features_program(cycle=0, axes=((0, bytes([0])),), ops=()):
    """A feature program: each axis is (variant, its feature byte and the values it reads)."""
    out = bytes([FEATURES | cycle, len(axes) - 1])
    for variant, feature in axes:
        out += bytes([variant]) + feature
    for op in ops:
        out += op
    return out


def homing_feature(homed=False, cam=100, width=10, to_cam=100, off_cam=10, pulse=5):
    """A homing axis (feature kind 1, or 3 homed at the start): cam search +, sync search -."""
    return (bytes([3 if homed else 1, 1, 0]) + num(to_cam) + num(off_cam) + num(pulse)
            + num(10000) + num(0) + num(cam) + num(width))


def two_speed_feature():
    """A two-speed axis with the defaults (rapid 500, creep 50, creep 100, braking 5 ...)."""
    return (bytes([2]) + num(500) + num(50) + num(100) + num(100) + num(5) + num(5) + num(20)
            + num(0.1) + num(30) + bytes([0]))


def delayed_feature(delay, actual_values=False):
    """DELAYED error propagation with `delay` s, optionally its slaves on its actual values."""
    return bytes([0x04 | (0x08 if actual_values else 0)]) + num(delay)


def home(axis, mode=0, position=None, cam_source=0):
    """Toggles MC_Home's Execute; cam_source 0: the kernel's cam, 1: off, 2: on."""
    pos = bytes([1]) if position is None else bytes([0]) + num(position)
    return bytes([axis, 14, mode]) + pos + bytes([1, cam_source])


def gear_in_dyn(slave, master, ratio, acc_bound=None, toggle=True):
    """MC_GearInDyn: GearRatio (every cycle), AccBound, Enable toggled towards `master`."""
    acc = bytes([0]) if acc_bound is None else bytes([1]) + num(acc_bound)
    return bytes([slave, 15]) + num(ratio) + acc + (bytes([1, master]) if toggle else bytes([0]))


def push(index, velocity):
    """Kernel::push_by_hand(index, velocity) between two cycles."""
    return bytes([0, 16, index]) + num(velocity)

HLI = 0x20  # first byte, with FEATURES: an HLI program (HLI_AxisCoupling, raw unit writes, queries)


def hli_program(cycle=0, axes=((0, bytes([0]), 0),), ops=()):
    """An HLI program: each axis is (variant, feature bytes, HLI byte: bits 0-5 its ax_nr is
    index + 1 + 4 x those, bit 6 P-AXIS-00436, bit 7 P-AXIS-00460)."""
    out = bytes([FEATURES | HLI | cycle, len(axes) - 1])
    for variant, feature, hli in axes:
        out += bytes([variant]) + feature + bytes([hli])
    for op in ops:
        out += op
    return out


def hli_entry(axis, mode, fract_num=0, fract_denom=1):
    """One list entry: `axis` an axis index (its ax_nr), or ('nr', n) for ax_nr n in -20 ... 19."""
    ax = bytes([n + 220]) if isinstance(axis, tuple) and (n := axis[1]) is not None else bytes([axis])
    out = ax + bytes([mode])
    if mode == 4:
        den = bytes([fract_denom + 4]) if -4 <= fract_denom <= 4 else bytes([200]) + struct.pack(
            ">h", fract_denom)
        out += struct.pack(">h", fract_num) + den
    return out


def hli_list(target, entries, end=True):
    """HLI_AxisCoupling on `target`: the entries, an INACTIVE end after them, Execute toggled."""
    out = bytes([target, 17, len(entries)]) + b"".join(entries)
    if len(entries) < 8:
        out += bytes([1 if end else 0])
    return out + bytes([1])  # a unit, not null


def hli_apply(target, entries, end=True):
    """hli_list, three cycles for the answer, then Execute back to FALSE (desc unchanged)."""
    return hli_list(target, entries, end) + run(0, 3) + bytes([target, 17, 0, 0, 1]) + run(0, 1)


def hli_raw(target, slot, entry, semaphore=True):
    """A raw write of one entry into the target's control unit, and its semaphore."""
    return bytes([target, 19, slot]) + entry + bytes([1 if semaphore else 0])


def command_position(axis):
    """Kernel::command_position_request of axis index `axis`'s ax_nr (or ('nr', n))."""
    return bytes([0, 20]) + (bytes([axis[1] + 220]) if isinstance(axis, tuple) else bytes([axis]))


BLOCKS = {
    "move_absolute": blocks_program(ops=[run(0, 3), absolute(0, 500, 1000), run(0, 64), run(0, 64)]),
    "move_and_new_pos": blocks_program(ops=[run(0, 3), absolute(0, 3000, 2000), run(0, 64),
                                           new_pos(0, 1000), run(0, 64), run(0, 64)]),
    "new_pos_and_velo": blocks_program(ops=[run(0, 3), absolute(0, 3000, 2000), run(0, 40),
                                           new_pos_and_velo(0, 4000, 1000, 2000), run(0, 64),
                                           run(0, 64)]),
    "velocity_override_halt": blocks_program(ops=[run(0, 3), velocity(0, 1500), run(0, 40),
                                                 override(0, 0.5), run(0, 40), halt(0, 20000, 200000),
                                                 run(0, 64)]),
    "stop_and_reset": blocks_program(ops=[run(0, 3), absolute(0, 2000, 2000), run(0, 30), stop(0),
                                         run(0, 64), stop(0), run(0, 2), execute(0, 0), run(0, 3)]),
    "compensation": blocks_program(ops=[run(0, 3), absolute(0, 10000, 2000), run(0, 50),
                                       superimposed(0, 250, 300, 500, 1000, 2000, 5000), run(0, 64),
                                       run(0, 64)]),
    "external_setpoints": blocks_program(ops=[run(0, 3), ext_enable(0, 100), run(0, 2),
                                             feed(0, 1, 100, 0, 1), run(0, 10), feed(0, 2, 100, 0, 1),
                                             run(0, 10), feed(0, 2, 0, 0, 0), run(0, 5)]),
    "mailbox_burst": blocks_program(ops=[run(0, 3), burst(0, 20, 10, 100), run(0, 5)]),
    "following_error_fault": blocks_program(variants=(0x04,), ops=[run(0, 3), absolute(0, 500, 2000),
                                                                  run(0, 64), execute(0, 0), run(0, 5)]),
    "feed_enable_lost": blocks_program(ops=[run(0, 3), velocity(0, 1000), run(0, 30), fault(0, 0),
                                           run(0, 64)]),
    "four_axes": blocks_program(variants=(0x00, 0x03, 0x18, 0xE2),
                                ops=[run(0, 3), absolute(0, 500, 1000), absolute(1, -300, 800),
                                     velocity(2, 200, 2), relative(3, 50, 100), run(0, 64),
                                     run(1, 64)]),
    "coupling_star": blocks_program(cycle=COUPLING, variants=(0x00, 0x00, 0x02),
                                    ops=[run(0, 3), gear_in(1, 0, 2), gear_in(2, 0, -0.5),
                                         run(0, 3), absolute(0, 500, 1000), run(0, 64), run(0, 64),
                                         gear_out(1), gear_out(2), run(0, 3)]),
    "coupling_cascade": blocks_program(cycle=COUPLING, variants=(0x00, 0x00, 0x00, 0x80),
                                       ops=[run(0, 3), gear_in(1, 0, 1.5), gear_in(2, 1, 3, 4),
                                            gear_in(3, 2, 0.1), gear_in(0, 3, 1), run(0, 3),
                                            velocity(0, 500), run(0, 40), gear_in(1, 0, 1.5),
                                            gear_in(1, 0, "huge"), run(0, 20), stop(0), run(0, 64),
                                            gear_out(3), run(0, 3)]),
    "homing_default": features_program(cycle=3, axes=((0, homing_feature()),),
                                       ops=[run(0, 3), home(0)] + [run(0, 64)] * 9),
    "homing_aborting_move": features_program(
        axes=((0, homing_feature(cam=5000)),),
        ops=[run(0, 3), absolute(0, 100000, 2000, 20000, 20000, 1e6), run(0, 39), home(0),
             run(0, 2), velocity(0, 500), run(0, 64), home(0), run(0, 20), halt(0), run(0, 64),
             home(0, mode=4, position=10), run(0, 5)]),
    "two_speed": features_program(axes=((0, two_speed_feature()),),
                                  ops=[run(0, 3), absolute(0, 1000, 500), run(0, 64), run(0, 64),
                                       stop(0), run(0, 64), execute(0, 0), run(0, 3)]),
    "gear_in_dyn": features_program(axes=((0, bytes([0])), (0, bytes([0]))),
                                    ops=[run(0, 3), gear_in_dyn(1, 0, 1, 8000), run(0, 3),
                                         velocity(0, 1000), run(0, 64), run(0, 64),
                                         gear_in_dyn(1, 0, 1.5, toggle=False), run(0, 64),
                                         run(0, 64), gear_in_dyn(1, 0, 1.5), run(0, 3)]),
    "delayed_push_by_hand": features_program(
        axes=((0, delayed_feature(0.05, actual_values=True)), (0, bytes([0]))),
        ops=[run(0, 3), gear_in(1, 0, 2), run(0, 3), fault(0, 2), run(0, 2), push(0, 100),
             run(0, 64), push(0, 0), push(1, 50), push(2, 10), run(0, 20), fault(0, 2), run(0, 20),
             absolute(0, 50, 1000), run(0, 64), fault(1, 0), run(0, 64)]),
    "hli_direct": hli_program(
        cycle=1, axes=((0, bytes([0]), 0), (0, bytes([0]), 0)),
        ops=[run(0, 3), hli_apply(1, [hli_entry(0, 2)]), absolute(0, 500, 1000)]
        + [run(0, 64)] * 6 + [command_position(1), hli_apply(1, []),
             hli_apply(1, []), absolute(1, 100, 500), run(0, 64)]),
    "hli_fract_self_mapping": hli_program(
        axes=((0, bytes([0]), 0), (0, bytes([0]), 0), (0, bytes([0]), 0x40)),
        ops=[run(0, 3), hli_apply(2, [hli_entry(2, 2), hli_entry(0, 4, -5, 9)]),
             absolute(0, 20, 500), run(0, 64), absolute(2, 30, 500), run(0, 64),
             command_position(2), command_position(("nr", 9)), hli_apply(2, [hli_entry(1, 3)]),
             hli_apply(2, []), command_position(2)]),
    "hli_change_while_moving": hli_program(
        axes=((0, bytes([0]), 0), (0, bytes([0]), 1)),
        ops=[run(0, 3), hli_apply(1, [hli_entry(0, 3)]), velocity(0, 800), run(0, 20),
             hli_apply(1, [hli_entry(0, 2)]), run(0, 61), execute(1, 0), run(0, 3), halt(0)] + [run(0, 64)] * 5 + [execute(1, 0), run(0, 3), hli_list(1, [hli_entry(0, 2)]), run(0, 5)]),
    "hli_bad_lists": hli_program(
        axes=((0, bytes([0]), 0), (0, two_speed_feature(), 0), (0, bytes([0]), 0x40)),
        ops=[run(0, 3), hli_apply(0, [hli_entry(("nr", 17), 2)]),
             hli_apply(0, [hli_entry(2, 250)]), hli_apply(0, [hli_entry(2, 4, 3, 0)]),
             hli_apply(0, [hli_entry(2, 4, 2000, 1)]),
             hli_apply(0, [hli_entry(1, 2)]), hli_apply(2, [hli_entry(0, 2)]),
             hli_apply(0, [hli_entry(2, 2)]),
             hli_raw(0, 0, hli_entry(0, 4, 1000, 1)), run(0, 3), fault(0, 2), run(0, 2),
             hli_apply(0, [hli_entry(0, 2)])]),
    "hli_fract_software_limit": hli_program(
        axes=((0, bytes([0]), 0), (1, homing_feature(homed=True), 0)),
        ops=[run(0, 3), hli_apply(1, [hli_entry(0, 4, 7, 2)]),
             absolute(0, 600, 2000)] + [run(0, 64)] * 8 + [execute(1, 0), run(0, 3)]),
    "hli_source_and_target_errors": hli_program(
        axes=((0, bytes([0]), 0), (0x04, bytes([0]), 0), (0, bytes([0]), 0)),
        ops=[run(0, 3), hli_apply(2, [hli_entry(0, 2), hli_entry(1, 4, 3, 2)]),
             velocity(0, 300), absolute(1, 500, 2000), run(0, 64), run(0, 64), fault(0, 0),
             run(0, 64), execute(0, 0), execute(1, 0), run(0, 3), velocity(0, 300), run(0, 30),
             fault(2, 2), run(0, 64), run(0, 64)]),
    "bad_inputs": blocks_program(ops=[run(0, 3), absolute(0, "nan", 1000), run(0, 3),
                                     absolute(0, 100, "inf"), run(0, 3), absolute(0, 100, -5),
                                     run(0, 3), absolute(0, "huge", 1000), run(0, 3),
                                     absolute(0, 100, "denormal"), run(0, 3)]),
}

PLANNER = {
    # mode byte: bit 0 velocity planner, bit 1 raw doubles, bit 7 plan_position with an end
    # velocity (read after the limits); bits 0 and 7: plan_stop (A- and J of the limits).
    "rest_to_rest": bytes([0]) + num(0) + num(0) + num(0) + num(1000) + num(2000) + num(5000)
    + num(5000) + num(50000),
    "moving_start": bytes([0]) + num(100) + num(1500) + num(-2000) + num(-500) + num(2000)
    + num(5000) + num(10000) + num(50000),
    "over_speed": bytes([0]) + num(0) + num(3000) + num(0) + num(5000) + num(2000) + num(5000)
    + num(5000) + num(50000),
    "velocity": bytes([1]) + num(0) + num(-500) + num(100) + num(1500) + num(2000) + num(5000)
    + num(5000) + num(50000),
    "raw": bytes([2]) + b"".join(struct.pack(">d", x) for x in
                                 (0.0, 0.0, 0.0, 100.0, 10.0, 100.0, 100.0, 1000.0)),
    "passing": bytes([0x80]) + num(0) + num(500) + num(0) + num(1000) + num(2000) + num(5000)
    + num(5000) + num(50000) + num(1500),
    "run_up_backwards": bytes([0x80]) + num(100) + num(0) + num(0) + num(101) + num(2000)
    + num(5000) + num(5000) + num(50000) + num(2000),
    "stop": bytes([0x81]) + num(0) + num(1500) + num(-2000) + num(0) + num(2000) + num(5000)
    + num(4000) + num(50000),
}


def config_documents():
    docs = {
        "empty_axes": {"axes": []},
        "one_axis": {"axes": [{"name": "x"}]},
        "kernel_and_axes": {"kernel": {"cycle_time": 0.002},
                            "axes": [{"name": "x", "max_velocity": 1000, "ref_velocity": 900},
                                     {"name": "y", "id": 7, "kind": "encoder"}]},
        "drive_lag": {"axes": [{"name": "z", "drive_model": "first_order_lag",
                                "drive_time_constant": 0.01, "drive_dead_time": 0.002,
                                "sw_limit_min_enabled": True, "sw_limit_min": -10,
                                "sw_limit_max_enabled": True, "sw_limit_max": 10}]},
        "bad_value": {"axes": [{"name": "x", "jerk": -1}]},
        "unknown_key": {"axes": [{"name": "x", "colour": "red"}]},
    }
    for example in sorted((HERE.parent.parent / "docs" / "examples").glob("*.json")):
        docs["example_" + example.stem] = json.loads(example.read_text())
    return {k: json.dumps(v, indent=1).encode() for k, v in docs.items()}


def write(kind, seeds):
    folder = HERE / "corpus" / kind
    folder.mkdir(parents=True, exist_ok=True)
    for name, data in seeds.items():
        (folder / name).write_bytes(data)


write("blocks", BLOCKS)
write("planner", PLANNER)
write("config", config_documents())
