"""The rows of the bad-input table (tests/python/test_bad_input_table.py) of one area: Hexapod:
descriptions, kinematics, leg checks."""

import numpy as np

import dispkin

from .rows import (
    B,
    INF,
    LEGS,
    LIMITS,
    MALFORMED,
    NAN,
    TRAPEZOID_LIMITS,
    V,
    accepted,
    good_set,
    hexapod,
    hexapod_json,
    leg_changed,
    row,
    trajectory,
    without,
)

# --- Hexapod ------------------------------------------------------------------------------
HJ = hexapod()
row(
    "Hexapod(...)",
    "NaN base joint",
    lambda: dispkin.Hexapod(
        np.where(np.arange(18).reshape(6, 3) == 0, NAN, HJ.base_joints), HJ.platform_joints, 0.15, 0.32, 0.01
    ),
    V,
    "base_joints = (nan, -0.02604722665, 0, 0.147721162952, 0.026",
)
row(
    "Hexapod(...)",
    "wrong shape base_joints (5, 3)",
    lambda: dispkin.Hexapod(HJ.base_joints[:5], HJ.platform_joints, 0.15, 0.32, 0.01),
    V,
    "base_joints: expected an array of shape (6, 3), got shape (5, 3)",
)
row(
    "Hexapod(...)",
    "wrong shape platform_joints (6, 2)",
    lambda: dispkin.Hexapod(HJ.base_joints, HJ.platform_joints[:, :2], 0.15, 0.32, 0.01),
    V,
    "platform_joints: expected an array of shape (6, 3), got shape (6, 2)",
)
row(
    "Hexapod(...)",
    "leg_min above leg_max",
    lambda: dispkin.Hexapod(HJ.base_joints, HJ.platform_joints, 0.4, 0.32, 0.01),
    V,
    "leg_max[0] = 0.32: must be finite",
)
row(
    "Hexapod(...)",
    "negative leg_min",
    lambda: dispkin.Hexapod(HJ.base_joints, HJ.platform_joints, -0.1, 0.32, 0.01),
    V,
    "leg_min[0] = -0.1: must be finite",
)
row(
    "Hexapod(...)",
    "zero leg_speed",
    lambda: dispkin.Hexapod(HJ.base_joints, HJ.platform_joints, 0.15, 0.32, 0.0),
    V,
    "leg_speed[0] = 0: must be in [1e-12, 1e12]",
)
row(
    "Hexapod(...)",
    "NaN leg_max",
    lambda: dispkin.Hexapod(HJ.base_joints, HJ.platform_joints, 0.15, NAN, 0.01),
    V,
    "leg_max[0] = nan: must be finite",
)
row(
    "Hexapod(...)",
    "wrong size leg_speed (5)",
    lambda: dispkin.Hexapod(HJ.base_joints, HJ.platform_joints, 0.15, 0.32, [0.01] * 5),
    V,
    "leg_speed: expected a number or an array of shape (6,), got shape (5,)",
)
accepted(
    "Hexapod(...)",
    "unreachable home",
    lambda: dispkin.Hexapod(
        HJ.base_joints, HJ.platform_joints, 0.15, 0.32, 0.01, home=dispkin.Pose((1, 0, 0, 0), (0, 0, 5.0))
    ),
    lambda h: h.home.translation[2] == 5.0,
    "home is only the pose forward() starts its search from; it need not be reachable (the default, the identity, puts the platform in the base plane)",
)
row(
    "Hexapod.symmetric",
    "zero base_radius",
    lambda: dispkin.Hexapod.symmetric(0.0, 0.3, 0.1, 0.3, 0.2, 0.1, 0.3, 0.01),
    V,
    "base_radius = 0",
)
row(
    "Hexapod.symmetric",
    "NaN height",
    lambda: dispkin.Hexapod.symmetric(0.15, 0.3, 0.1, 0.3, NAN, 0.1, 0.3, 0.01),
    V,
    "height = nan",
)
row(
    "Hexapod.symmetric",
    "negative leg_speed",
    lambda: dispkin.Hexapod.symmetric(0.15, 0.3, 0.1, 0.3, 0.2, 0.1, 0.3, -0.01),
    V,
    "leg_speed[0] = -0.01",
)
row(
    "Hexapod.symmetric",
    "+inf platform_radius",
    lambda: dispkin.Hexapod.symmetric(0.15, 0.3, INF, 0.3, 0.2, 0.1, 0.3, 0.01),
    V,
    "platform_radius = inf",
)
row(
    "Hexapod.symmetric",
    "leg_max below leg_min",
    lambda: dispkin.Hexapod.symmetric(0.15, 0.3, 0.1, 0.3, 0.2, 0.3, 0.1, 0.01),
    V,
    "leg_max[0] = 0.1: must be finite",
)
row(
    "Hexapod.symmetric",
    "negative base_gap",
    lambda: dispkin.Hexapod.symmetric(0.15, -0.3, 0.1, 0.3, 0.2, 0.1, 0.3, 0.01),
    V,
    "base_gap = -0.3",
)
row(
    "Hexapod.from_json",
    "truncated JSON",
    lambda: dispkin.Hexapod.from_json("{"),
    V,
    "description = \"<text>\": is not JSON",
)
row(
    "Hexapod.from_json", "empty text", lambda: dispkin.Hexapod.from_json(""), V, "description = \"<text>\": is not JSON"
)
row(
    "Hexapod.from_json",
    "not an object",
    lambda: dispkin.Hexapod.from_json("[1, 2]"),
    V,
    "description = \"[1,2]\": must be a JSON object",
)
row(
    "Hexapod.from_json",
    "missing legs",
    lambda: dispkin.Hexapod.from_json(without("legs")),
    V,
    "legs = \"<missing>\": required key is missing",
)
row("Hexapod.from_json", "5 legs", lambda: dispkin.Hexapod.from_json(hexapod_json(legs=LEGS[:5])), V, "legs = \"[{\"")
row(
    "Hexapod.from_json",
    "string speed",
    lambda: dispkin.Hexapod.from_json(hexapod_json(legs=leg_changed(speed="fast"))),
    V,
    "legs[0].speed = \"fast\": must be a number",
)
row(
    "Hexapod.from_json",
    "negative speed",
    lambda: dispkin.Hexapod.from_json(hexapod_json(legs=leg_changed(speed=-1.0))),
    V,
    "leg_speed[0] = -1: must be in [1e-12, 1e12]",
)
row(
    "Hexapod.from_json",
    "min above max",
    lambda: dispkin.Hexapod.from_json(hexapod_json(legs=leg_changed(min=0.5))),
    V,
    "leg_max[0] = 0.32: must be finite",
)
row(
    "Hexapod.from_json",
    "base with 2 coordinates",
    lambda: dispkin.Hexapod.from_json(hexapod_json(legs=leg_changed(base=[0.1, 0.0]))),
    V,
    "legs[0].base = \"[0.1,0.0]\": must be an array of 3 numbers",
)
row(
    "Hexapod.from_json",
    "NaN literal",
    lambda: dispkin.Hexapod.from_json(hexapod_json().replace('"speed": 0.01', '"speed": NaN', 1)),
    V,
    "description = \"<text>\": is not JSON",
)
row(
    "Hexapod.from_json",
    "wrong format tag",
    lambda: dispkin.Hexapod.from_json(hexapod_json(format="urdf")),
    V,
    "format = \"urdf\"",
)
row(
    "Hexapod.from_json",
    "non-unit home quaternion",
    lambda: dispkin.Hexapod.from_json(hexapod_json(home={"quaternion_wxyz": [2, 0, 0, 0], "translation": [0, 0, 0.2]})),
    V,
    "quaternion (w, x, y, z) = (2, 0, 0, 0): must be a unit quaternion",
)
row(
    "Hexapod.from_json",
    "unknown top-level key",
    lambda: dispkin.Hexapod.from_json(hexapod_json(leg_speed=-1.0)),
    V,
    "leg_speed = -1: unknown key (allowed here: format, version, units, legs, home)",
)
row(
    "Hexapod.load",
    "missing file",
    lambda: dispkin.Hexapod.load("/nonexistent/hexapod.json"),
    V,
    "path = \"/nonexistent/hexapod.json\": cannot be opened",
)
row("Hexapod.load", "directory", lambda: dispkin.Hexapod.load("/"), V, "/: description = \"<text>\": is not JSON")
row(
    "Hexapod.load",
    "malformed file",
    lambda: dispkin.Hexapod.load(str(MALFORMED)),
    V,
    "description = \"<text>\": is not JSON",
)
row("Hexapod.forward", "NaN legs", lambda: HJ.forward([NAN, 0.2, 0.2, 0.2, 0.2, 0.2]), V, "legs[0] = nan")
row(
    "Hexapod.forward",
    "wrong size legs (5)",
    lambda: HJ.forward([0.2] * 5),
    V,
    "legs: expected an array of shape (6,), got shape (5,)",
)
row("Hexapod.forward", "out-of-range legs", lambda: HJ.forward([5.0] * 6), V, "legs = (5, 5, 5, 5, 5, 5)")
row("Hexapod.forward", "negative legs", lambda: HJ.forward([-0.2] * 6), V, "legs[0] = -0.2")
row("Hexapod.forward", "NaN guess", lambda: HJ.forward([0.2] * 6, guess=np.full((4, 4), NAN)), V, "matrix = (nan, nan")
row(
    "Hexapod.require_reachable",
    "unreachable pose",
    lambda: HJ.require_reachable(dispkin.Pose((1, 0, 0, 0), (0, 0, 5.0))),
    V,
    "leg 0 length = 5.00095177608: outside the leg's range [0.15, 0.32]",
)
row(
    "Hexapod.require_reachable",
    "wrong shape pose (6,)",
    lambda: HJ.require_reachable([0, 0, 0.2, 0, 0, 0]),
    V,
    "pose: expected an array of shape (4, 4), got shape (6,)",
)
row("Hexapod.require_reachable", "NaN matrix", lambda: HJ.require_reachable(np.full((4, 4), NAN)), V, "matrix = (nan")
row("Hexapod.inverse", "NaN matrix", lambda: HJ.inverse(np.full((4, 4), NAN)), V, "matrix = (nan")
row(
    "Hexapod.inverse_xyzuvw",
    "NaN xyzuvw",
    lambda: HJ.inverse_xyzuvw([NAN, 0, 0.2, 0, 0, 0]),
    V,
    "xyzuvw = (nan, 0, 0.2, 0, 0, 0)",
)
row(
    "Hexapod.inverse",
    "wrong shape (N, 5)",
    lambda: HJ.inverse(np.zeros((2, 5))),
    V,
    "pose: expected an array of shape (4, 4), got shape (2, 5)",
)
row(
    "Hexapod.check",
    "wrong shape pose (6,)",
    lambda: HJ.check([0, 0, NAN, 0, 0, 0]),
    V,
    "pose: expected an array of shape (4, 4), got shape (6,)",
)
row("Hexapod.leg_jacobian", "NaN matrix", lambda: HJ.leg_jacobian(np.full((4, 4), NAN)), V, "matrix = (nan, nan")
row("Hexapod.check_trajectory", "zero dt", lambda: HJ.check_trajectory(trajectory(), 0.0), V, "dt = 0")
row("Hexapod.check_trajectory", "negative dt", lambda: HJ.check_trajectory(trajectory(), -0.01), V, "dt = -0.01")
row("Hexapod.check_trajectory", "NaN dt", lambda: HJ.check_trajectory(trajectory(), NAN), V, "dt = nan")
row("Hexapod.check_trajectory", "+inf dt", lambda: HJ.check_trajectory(trajectory(), INF), V, "dt = inf")
row("Hexapod.add_leg_speed_group", "negative group", lambda: HJ.add_leg_speed_group(good_set(), -1), V, "group = -1")
HEX_LINE = dispkin.Path.lin(HJ.home, HJ.home * B)


class _LegLengths:
    # A stand-in joint metric returning whatever it is given.
    def __init__(self, value):
        self.value = value

    def leg_section_lengths(self, path, system_velocity):
        return self.value


row(
    "Hexapod.leg_section_lengths",
    "zero system_velocity",
    lambda: HJ.leg_section_lengths(HEX_LINE, 0.0),
    V,
    "system_velocity = 0",
)
row(
    "Hexapod.leg_section_lengths",
    "NaN system_velocity",
    lambda: HJ.leg_section_lengths(HEX_LINE, NAN),
    V,
    "system_velocity = nan",
)
row(
    "check_joint_limits",
    "hexapod, negative samples_between",
    lambda: dispkin.check_joint_limits(dispkin.plan(HEX_LINE, good_set(), LIMITS), HJ, samples_between=-1),
    V,
    "samples_between = -1",
)
row(
    "retime",
    "hexapod, scaling method",
    lambda: dispkin.retime(HEX_LINE, good_set(), TRAPEZOID_LIMITS, HJ, method="scaling"),
    V,
    "method = \"scaling\"",
)
row(
    "retime",
    "hexapod, joint_acceleration of wrong size",
    lambda: dispkin.retime(HEX_LINE, good_set(), TRAPEZOID_LIMITS, HJ, joint_acceleration=[1.0]),
    V,
    "joint_acceleration size = 1",
)
row(
    "Hexapod.leg_section_lengths",
    "+inf system_velocity",
    lambda: HJ.leg_section_lengths(HEX_LINE, INF),
    V,
    "system_velocity = inf",
)
row(
    "Hexapod.leg_section_lengths",
    "zero tolerance",
    lambda: HJ.leg_section_lengths(HEX_LINE, 0.1, tolerance=0.0),
    V,
    "tolerance = 0: must be in (0, 1]",
)
row("Hexapod.leg_rate_bounds", "NaN tolerance", lambda: HJ.leg_rate_bounds(HEX_LINE, NAN), V, "tolerance = nan")
row("Hexapod.leg_rate_bounds", "tolerance above 1", lambda: HJ.leg_rate_bounds(HEX_LINE, 2.0), V, "tolerance = 2")
row(
    "plan",
    "joint_metric without the method",
    lambda: dispkin.plan(HEX_LINE, good_set(), LIMITS, joint_metric=42),
    V,
    "joint_metric = \"42\": must have a method leg_section_lengths",
)
row(
    "plan",
    "joint_metric wrong count",
    lambda: dispkin.plan(HEX_LINE, good_set(), LIMITS, joint_metric=_LegLengths([0.1, 0.2])),
    V,
    "joint_metric(path, limits) size = 2: must be 0 or the path's section count 1",
)
row(
    "plan",
    "joint_metric negative length",
    lambda: dispkin.plan(HEX_LINE, good_set(), LIMITS, joint_metric=_LegLengths([-0.5])),
    V,
    "joint_metric(path, limits)[0] = -0.5",
)
row(
    "plan",
    "joint_metric NaN length",
    lambda: dispkin.plan(HEX_LINE, good_set(), LIMITS, joint_metric=_LegLengths([NAN])),
    V,
    "joint_metric(path, limits)[0] = nan",
)
row(
    "plan",
    "joint_metric wrong shape (1, 1)",
    lambda: dispkin.plan(HEX_LINE, good_set(), LIMITS, joint_metric=_LegLengths([[0.1]])),
    V,
    "joint_metric.leg_section_lengths(path, velocity): expected an array of shape (1,), got shape (1, 1)",
)
row(
    "plan",
    "joint_metric not numbers",
    lambda: dispkin.plan(HEX_LINE, good_set(), LIMITS, joint_metric=_LegLengths("long")),
    V,
    "joint_metric.leg_section_lengths(path, velocity): expected an array of shape (1,)",
)
