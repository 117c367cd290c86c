"""The rows of the bad-input table (tests/python/test_bad_input_table.py) of one area: Limits
files (dispkin.limits_files)."""

import pathlib

from dispkin import limits_files
import dispkin

from .rows import LIMITS, NAN, TRAPEZOID_LIMITS, V, _TMP, good_set, row
from .joint_motion import Q_UR, ur5e, ur_path, ur_trajectory

# --- limits files (dispkin.limits_files) ----------------------------------------------------

LIMITS_FILE = pathlib.Path(_TMP) / "limits.yaml"


def limits_file(text):
    LIMITS_FILE.write_text(text)
    return LIMITS_FILE


row(
    "read_moveit_joint_limits",
    "missing file",
    lambda: limits_files.read_moveit_joint_limits("/nonexistent/joint_limits.yaml"),
    V,
    "cannot be read",
)
row(
    "read_moveit_joint_limits",
    "negative max_velocity",
    lambda: limits_files.read_moveit_joint_limits(
        limits_file("joint_limits:\n  j1:\n    has_velocity_limits: true\n    max_velocity: -2\n")
    ),
    V,
    "joint_limits.j1.max_velocity = -2: must be > 0",
)
row(
    "read_moveit_joint_limits",
    "+inf max_acceleration",
    lambda: limits_files.read_moveit_joint_limits(
        limits_file("joint_limits:\n  j1:\n    has_acceleration_limits: true\n    max_acceleration: .inf\n")
    ),
    V,
    "joint_limits.j1.max_acceleration = inf: must be finite",
)
row(
    "apply_moveit_joint_limits",
    "unknown joint",
    lambda: limits_files.apply_moveit_joint_limits(
        ur5e(), limits_file("joint_limits:\n  j1:\n    has_velocity_limits: true\n    max_velocity: 2\n")
    ),
    V,
    "joint_limits.j1: not a joint of the arm",
)
row(
    "read_pilz_cartesian_limits",
    "positive max_trans_dec",
    lambda: limits_files.read_pilz_cartesian_limits(
        limits_file("cartesian_limits: {max_trans_vel: 1, max_trans_acc: 2, max_trans_dec: 3, max_rot_vel: 1}\n")
    ),
    V,
    "cartesian_limits.max_trans_dec = 3: must be < 0",
)
row(
    "read_pilz_cartesian_limits",
    "zero max_rot_vel",
    lambda: limits_files.read_pilz_cartesian_limits(
        limits_file("cartesian_limits: {max_trans_vel: 1, max_trans_acc: 2, max_trans_dec: -3, max_rot_vel: 0}\n")
    ),
    V,
    "cartesian_limits.max_rot_vel = 0: must be > 0",
)

row(
    "check_joint_limits",
    "negative samples_between",
    lambda: dispkin.check_joint_limits(ur_trajectory(), ur5e(), Q_UR, samples_between=-1),
    V,
    "samples_between = -1",
)
row(
    "check_joint_limits",
    "q_start of the wrong size",
    lambda: dispkin.check_joint_limits(ur_trajectory(), ur5e(), Q_UR[:5]),
    V,
    "q_start size = 5",
)
row(
    "check_joint_limits",
    "NaN q_start",
    lambda: dispkin.check_joint_limits(ur_trajectory(), ur5e(), [NAN] * 6),
    V,
    "q_start = (nan",
)
row(
    "retime",
    "unknown method",
    lambda: dispkin.retime(ur_path(), good_set(), LIMITS, ur5e(), Q_UR, method="fastest"),
    V,
    "method = \"fastest\"",
)
row(
    "retime",
    "optimal S-curve without a jerk limit",
    lambda: dispkin.retime(ur_path(), good_set(), TRAPEZOID_LIMITS, ur5e(), Q_UR, method="optimal"),
    V,
    "jerk is missing",
)
row(
    "retime",
    "optimal, 1 grid interval",
    lambda: dispkin.retime(
        ur_path(), good_set(), TRAPEZOID_LIMITS, ur5e(), Q_UR, profile="trapezoid", method="optimal", grid_intervals=1
    ),
    V,
    "grid_intervals = 1",
)
row(
    "retime",
    "optimal, joint_acceleration of wrong size",
    lambda: dispkin.retime(
        ur_path(),
        good_set(),
        TRAPEZOID_LIMITS,
        ur5e(),
        Q_UR,
        profile="trapezoid",
        method="optimal",
        joint_acceleration=[1.0, 2.0],
    ),
    V,
    "joint_acceleration size = 2",
)
row(
    "retime",
    "optimal, negative joint_acceleration",
    lambda: dispkin.retime(
        ur_path(),
        good_set(),
        TRAPEZOID_LIMITS,
        ur5e(),
        Q_UR,
        profile="trapezoid",
        method="optimal",
        joint_acceleration=[1.0, 1.0, -1.0, 1.0, 1.0, 1.0],
    ),
    V,
    "joint_acceleration[2] = -1",
)
row(
    "retime",
    "optimal with a jerk limit",
    lambda: dispkin.retime(ur_path(), good_set(), LIMITS, ur5e(), Q_UR, profile="trapezoid", method="optimal"),
    V,
    "jerk",
)
row(
    "retime",
    "unknown profile",
    lambda: dispkin.retime(ur_path(), good_set(), LIMITS, ur5e(), Q_UR, profile="sine"),
    V,
    "profile = \"sine\"",
)
row(
    "retime",
    "zero max_iterations",
    lambda: dispkin.retime(ur_path(), good_set(), LIMITS, ur5e(), Q_UR, max_iterations=0),
    V,
    "max_iterations = 0",
)
