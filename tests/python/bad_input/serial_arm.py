"""The rows of the bad-input table (tests/python/test_bad_input_table.py) of one area:
SerialArm (tests/data/urdf/arm_*.urdf): URDF, kinematics, inverse kinematics."""

import pathlib

import numpy as np

import dispkin

from .rows import INF, NAN, V, row

# --- SerialArm (tests/data/urdf/arm_*.urdf) -------------------------------------------------
URDF = pathlib.Path(__file__).resolve().parents[2] / "data" / "urdf"
PLANAR = str(URDF / "arm_planar_two_link.urdf")


def arm():
    return dispkin.SerialArm.from_urdf(PLANAR, "base", "link2")


row(
    "SerialArm.from_urdf",
    "missing file",
    lambda: dispkin.SerialArm.from_urdf("/nonexistent/arm.urdf", "a", "b"),
    V,
    "path = \"/nonexistent/arm.urdf\": cannot be opened",
)
row(
    "SerialArm.from_urdf",
    "not XML",
    lambda: dispkin.SerialArm.from_urdf(str(URDF / "arm_bad_not_xml.urdf"), "base", "l1"),
    V,
    "URDF: not a valid robot description",
)
row(
    "SerialArm.from_urdf",
    "XML text without <robot>",
    lambda: dispkin.SerialArm.from_urdf("<model/>", "base", "l1"),
    V,
    "URDF: not a valid robot description: Could not find the 'robot' element",
)
row(
    "SerialArm.from_urdf",
    "unknown base link",
    lambda: dispkin.SerialArm.from_urdf(PLANAR, "nowhere", "link2"),
    V,
    "base_link = \"nowhere\": is not a link of robot \"planar_two_link\"",
)
row(
    "SerialArm.from_urdf",
    "unknown tip link",
    lambda: dispkin.SerialArm.from_urdf(PLANAR, "base", "nowhere"),
    V,
    "tip_link = \"nowhere\": is not a link",
)
row(
    "SerialArm.from_urdf",
    "base not an ancestor",
    lambda: dispkin.SerialArm.from_urdf(PLANAR, "link2", "link1"),
    V,
    "base_link = \"link2\": is not an ancestor of tip_link \"link1\"",
)
row(
    "SerialArm.from_urdf",
    "prismatic joint on the path",
    lambda: dispkin.SerialArm.from_urdf(PLANAR, "base", "finger"),
    V,
    "joint \"finger_joint\" between \"link2\" and \"finger\": only revolute, continuous and fixed joints",
)
row(
    "SerialArm.from_urdf",
    "lower above upper",
    lambda: dispkin.SerialArm.from_urdf(str(URDF / "arm_bad_limits.urdf"), "base", "l1"),
    V,
    "joint \"j1\" limit (lower, upper) = (1, -1): needs lower < upper",
)
row(
    "SerialArm.from_urdf",
    "empty base link",
    lambda: dispkin.SerialArm.from_urdf(PLANAR, "", "link2"),
    V,
    "base_link = \"\": must name a link",
)
row(
    "SerialArm.forward",
    "wrong size q (3)",
    lambda: arm().forward([0, 0, 0]),
    V,
    "q = (0, 0, 0): expected 2 joint values, got 3",
)
row(
    "SerialArm.forward",
    "wrong shape q (2, 1)",
    lambda: arm().forward([[0], [0]]),
    V,
    "q: expected an array of shape (n,), got shape (2, 1)",
)
row("SerialArm.forward", "NaN q", lambda: arm().forward([0, NAN]), V, "q = (0, nan): must be finite")
row("SerialArm.inverse", "NaN matrix", lambda: arm().inverse(np.full((4, 4), NAN)), V, "matrix = (nan")
row(
    "SerialArm.inverse_many",
    "one (4, 4) matrix",
    lambda: arm().inverse_many(np.eye(4)),
    V,
    "poses: expected an array of shape (N, 4, 4) or a sequence of Poses, got shape (4, 4)",
)
row(
    "SerialArm.inverse_many",
    "NaN in the second pose",
    lambda: arm().inverse_many(np.array([np.eye(4), np.full((4, 4), NAN)])),
    V,
    "poses[1] matrix = (nan",
)
row(
    "SerialArm.inverse_many",
    "sheared rotation in a list",
    lambda: arm().inverse_many(
        [dispkin.Pose(), np.array([[1, 0.5, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1.0]])]
    ),
    V,
    "poses[1] rotation = (",
)
row(
    "SerialArm.inverse_solutions",
    "zero max_attempts",
    lambda: arm().inverse_solutions(dispkin.Pose(), max_attempts=0),
    V,
    "max_attempts = 0: must be greater than zero",
)
row(
    "SerialArm.inverse_solutions",
    "negative time_budget",
    lambda: arm().inverse_solutions(dispkin.Pose(), time_budget=-1.0),
    V,
    "time_budget = -1: must be finite and greater than zero",
)
row("SerialArm.jacobian", "+inf q", lambda: arm().jacobian([INF, 0]), V, "q = (inf, 0): must be finite")
row(
    "SerialArm.torques",
    "wrong size qd (1)",
    lambda: arm().torques([0, 0], [0], [0, 0]),
    V,
    "qd = (0): expected 2 joint values, got 1",
)
row(
    "SerialArm.torques", "NaN qdd", lambda: arm().torques([0, 0], [0, 0], [NAN, 0]), V, "qdd = (nan, 0): must be finite"
)
row(
    "SerialArm.static_torques",
    "empty q",
    lambda: arm().static_torques(np.zeros(0)),
    V,
    "q = (): expected 2 joint values, got 0",
)
row(
    "SerialArm.gravity",
    "NaN gravity",
    lambda: setattr(arm(), "gravity", [0, 0, NAN]),
    V,
    "gravity = (0, 0, nan): must be finite",
)
row(
    "SerialArm.gravity",
    "wrong size gravity (2)",
    lambda: setattr(arm(), "gravity", [0, 0]),
    V,
    "gravity: expected an array of shape (3,), got shape (2,)",
)
row(
    "SerialArm.configuration",
    "not a 6R arm",
    lambda: arm().configuration([0, 0]),
    V,
    "dof = 2: configuration flags are defined for 6R arms",
)
row(
    "SerialArm.nearest",
    "no solutions",
    lambda: dispkin.SerialArm.nearest([], [0, 0]),
    V,
    "solutions = 0: must not be empty",
)
row(
    "SerialArm.nearest",
    "wrong size q_ref",
    lambda: dispkin.SerialArm.nearest([np.zeros(6)], [0, 0]),
    V,
    "q_ref = (0, 0): expected 6 joint values like the solutions, got 2",
)
row(
    "SerialArm.follow",
    "unreachable pose",
    lambda: arm().follow([dispkin.Pose((1, 0, 0, 0), (5, 0, 0))], [0, 0]),
    RuntimeError,
    "poses[0] translation = (5, 0, 0): has no inverse-kinematics solution",
)
row(
    "SerialArm.follow",
    "negative gain",
    lambda: arm().follow([dispkin.Pose()], [0, 0], gain=-1.0),
    V,
    "redundancy_rule.gain = -1: must be finite and at least 0",
)
row(
    "SerialArm.follow",
    "NaN max_rate",
    lambda: arm().follow([dispkin.Pose()], [0, 0], max_rate=NAN),
    V,
    "redundancy_rule.max_rate = nan: must be finite and at least 0",
)
row(
    "SerialArm.follow",
    "+inf singularity_weight",
    lambda: arm().follow([dispkin.Pose()], [0, 0], singularity_weight=INF),
    V,
    "redundancy_rule.singularity_weight = inf: must be finite and at least 0",
)
