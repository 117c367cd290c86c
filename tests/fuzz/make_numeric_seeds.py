#!/usr/bin/env python3
"""Writes the seed inputs of the numeric fuzz targets (corpus/fuzz_{pose,metric,path_plan,
profile,serial_ik}/) in the byte encoding of fuzz_input.hpp: a selector or flag is one byte, a
number is a mode byte followed by its payload (mode 2: int16 big-endian / 256, mode 1: an index
into the table of special values, mode 0: 8 raw IEEE bytes)."""

import pathlib
import struct

HERE = pathlib.Path(__file__).parent / "corpus"
SPECIAL = {"nan": 4, "inf": 5, "-inf": 6, "max": 7, "tiny": 10, "1e300": 13}


def num(x):
    if isinstance(x, str):
        return bytes([1, SPECIAL[x]])
    if x == int(x * 256) / 256 and abs(x) < 128:
        return bytes([2]) + struct.pack(">h", int(x * 256))
    return bytes([0]) + struct.pack("<d", x)


def seq(*items):
    """Ints are raw bytes (selectors, flags), floats and strings are numbers."""
    out = b""
    for it in items:
        out += bytes([it]) if type(it) is int else num(it)
    return out


def pose(t=(0.0, 0.0, 0.0), q=(1.0, 0.0, 0.0, 0.0), normalise=1):
    return seq(
        *[float(v) if type(v) is not str else v for v in q],
        *[float(v) if type(v) is not str else v for v in t],
        normalise,
    )


SEEDS = {
    "fuzz_pose": {
        "quaternion": seq(0) + pose((0.5, -1.0, 2.0), (1.0, 0.5, 0.0, 0.0)) + pose() + seq(0.0, 0.0, 0.1),
        "rotation": seq(1, 0, 1.0, 0.0, 0.0, 0.5, 0, 0, 1.0, 0.0, 0.0, 0.0) + pose() + seq(0.0, 0.0, 0.0),
        "matrix": seq(2, 0, 0.0, 1.0, 0.0, 0.0, 1, 1, 1.0, 2.0, 3.0, 1)
        + seq(0.0, 0.0, 0.0, 1.0)
        + pose()
        + seq(1.0, 0.0, 0.0),
        "xyzuvw_gimbal": seq(3, 0.1, 0.2, 0.3, 0.5, 1.5703125, -1.0, 0.0, 0.0, 0.0) + pose() + seq(0.0, 0.0, 0.0),
        "nan": seq(3, "nan", 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0),
        "huge": seq(0) + pose(("max", "max", 1.0)) + pose() + seq("1e300", 0.0, 0.0),
    },
    "fuzz_metric": {
        "triangle": seq(
            4,
            0,
            0,
            0,
            0.0,
            0.0,
            0.0,
            0,
            0,
            0,
            1.0,
            0.0,
            0.0,
            0,
            0,
            0,
            0.0,
            1.0,
            0.0,
            0,
            0,
            2,
            0.0,
            0.0,
            0.5,
            0.25,
            1,
            0,
        )
        + pose()
        + pose((1.0, 0.0, 0.0), (1.0, 0.0, 0.0, 1.0))
        + seq(0)
        + pose()
        + pose((0.0, 1.0, 0.0))
        + seq(3, 0.0, 0.0, 0.0)
        + pose()
        + pose()
        + seq(5, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0),
        "groups": seq(
            5,
            1,
            0,
            2,
            0.0,
            0.0,
            0.0,
            0.5,
            0,
            1,
            0,
            4,
            0.25,
            2,
            0,
            1,
            1.0,
            2.0,
            3.0,
            0,
            0,
            3,
            3,
            0.0,
            0.0,
            0.0,
            1.0,
            0.0,
            0.0,
            0.0,
            1.0,
            0.0,
            1,
            1,
            1.0,
        )
        + pose()
        + pose((0.0, 0.0, 1.0))
        + seq(1)
        + pose()
        + pose((0.0, 0.0, 1.0), (0.0, 1.0, 0.0, 0.0))
        + seq(4, 0.0, 0.0, 0.5),
        "nan_point": seq(1, 0, 0, 0, "nan", 0.0, 0.0, 0) + pose() + pose() + seq(0),
    },
    "fuzz_path_plan": {
        "lin": seq(0)
        + pose()
        + pose((0.5, 0.0, 0.0), (1.0, 0.0, 0.0, 0.5))
        + seq(0, 0, 0)
        + seq(0.0, 0.5, 1.0, 0.25, 0, 0, 1.0, 2.0, 1, 10.0, 0),
        "circ_then_blend": seq(1)
        + pose()
        + pose((0.5, 0.5, 0.0))
        + pose((1.0, 0.0, 0.0))
        + seq(0, 0)
        + seq(1, 7, 0)
        + pose((1.0, 1.0, 0.0))
        + seq(0, 0, 1, 0.125)
        + seq(0.0, 1, 0.0, 0.0, 0.0, 0.0625, 1, 0.5, 0.5, 2.0, 0, 0, 1, 4.0, 0),
        "spline": seq(2)
        + pose()
        + seq(1)
        + pose((0.25, 0.5, 0.0))
        + pose((0.75, 0.0, 0.5), (1.0, 0.0, 1.0, 0.0))
        + pose((1.0, 1.0, 1.0))
        + seq(0, 0, 0, 0.5, 0, 0, 0.5, 1.0, 1, 5.0, 0, 0.5),
    },
    "fuzz_profile": {
        "trapezoid": seq(0, 1.0, 0.5, 2.0, 0.0, 0.0, 0.5),
        "scurve": seq(1, 2.0, 1.0, 2.0, 8.0, 1, 0.25, 1, 0.5, 1.0),
        "scurve_tiny": seq(1, "tiny", 1.0, 1.0, 1.0, 0, 0, 0.0),
        "velocity_limited": seq(2, 3, 1.0, 1.0, 0.5, 0.25, 2.0, 2.0, 1.0, 1, 10.0, 1, 0.5, 1, 0.0, 0.5),
        "nan": seq(0, "nan", 1.0, 1.0, 0.0, 0.0),
    },
    "fuzz_serial_ik": {
        "home": seq(0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0),
        "elbow_singular": seq(0, 0, 1, 0, 0, 0, 2, 0, 1, 0, 1, 0, 1, 1)
        + seq(1e-3, 0.0, 0.0, 0.0, 1e-3, 0.0)
        + seq(1, 1),
        "joints": seq(0, 1, 0.5, 1, -1.0, 1, 1.5, 1, 0.25, 1, -0.75, 1, 2.0, 0, 0, 1),
        "pose": seq(1) + pose((0.4, 0.1, 0.3), (0.0, 1.0, 0.0, 0.0)) + seq(0, 1),
        "far_pose": seq(1) + pose((100.0, 0.0, 0.0)) + seq(1, 0),
    },
}

for target, seeds in SEEDS.items():
    (HERE / target).mkdir(parents=True, exist_ok=True)
    for name, data in seeds.items():
        (HERE / target / f"{name}.bin").write_bytes(data)
