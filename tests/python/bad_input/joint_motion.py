"""The rows of the bad-input table (tests/python/test_bad_input_table.py) of one area: Joint
motion of a UR5e: check_joint_limits, retime, PTP moves planned with robot=."""

import numpy as np

import dispkin

from .rows import LIMITS, NAN, V, good_set, row
from .serial_arm import URDF


# --- check_joint_limits / retime (UR5e) ---------------------------------------------------
def ur5e():
    return dispkin.SerialArm.from_urdf(str(URDF / "arm_ur5e_dh.urdf"), "base_link", "tool0")


Q_UR = [0.3, -1.2, 1.5, -1.9, -1.57, 0.2]


def ur_path():
    a = ur5e().forward(Q_UR)
    return dispkin.Path.lin(a, dispkin.Pose(a.quaternion, a.translation + np.array([0.05, 0, 0])))


def ur_trajectory():
    return dispkin.plan(ur_path(), good_set(), LIMITS)


row(
    "SerialArm.with_joint_limits",
    "velocity of the wrong size",
    lambda: ur5e().with_joint_limits(velocity=[1.0, 2.0]),
    V,
    "velocity size = 2",
)
row(
    "SerialArm.with_joint_limits",
    "zero velocity",
    lambda: ur5e().with_joint_limits(velocity=[1, 1, 0, 1, 1, 1]),
    V,
    "joint \"elbow_joint\" velocity = 0",
)
row(
    "SerialArm.with_joint_limits",
    "NaN lower",
    lambda: ur5e().with_joint_limits(lower=[NAN, 0, 0, 0, 0, 0]),
    V,
    "joint \"shoulder_pan_joint\" (lower, upper) = (nan",
)

# --- plan(Path.ptp(...), ..., robot=arm): PTP moves (UR5e) ----------------------------------
PTP_LIMITS = dispkin.Limits(0.1, 1.0, 10.0)
row(
    "plan (PTP)",
    "no robot",
    lambda: dispkin.plan(dispkin.Path.ptp(np.zeros(6), np.full(6, 0.1)), good_set(), PTP_LIMITS),
    V,
    "robot = \"None\": must be a SerialArm",
)
row(
    "plan (PTP)",
    "q_a of the wrong size for the arm",
    lambda: dispkin.plan(dispkin.Path.ptp(np.zeros(5), np.ones(5)), good_set(), PTP_LIMITS, robot=ur5e()),
    V,
    "q_a size = 5: must be the arm's dof 6",
)
row(
    "plan (PTP)",
    "q_b outside the joint range",
    lambda: dispkin.plan(dispkin.Path.ptp(np.zeros(6), [0, 7.0, 0, 0, 0, 0]), good_set(), PTP_LIMITS, robot=ur5e()),
    V,
    "q_b[1] = 7: is outside the position limits",
)
row(
    "plan (PTP)",
    "q_b equal to q_a",
    lambda: dispkin.plan(dispkin.Path.ptp(np.zeros(6), np.zeros(6)), good_set(), PTP_LIMITS, robot=ur5e()),
    V,
    "equals q_a: a PTP move must move",
)
row(
    "plan (PTP)",
    "zero tolerance",
    lambda: dispkin.plan(
        dispkin.Path.ptp(np.zeros(6), np.full(6, 0.1)), good_set(), PTP_LIMITS, robot=ur5e(), tolerance=0.0
    ),
    V,
    "tolerance = 0: must be in (0, 0.5]",
)
row(
    "plan (PTP)",
    "negative joint acceleration",
    lambda: dispkin.plan(
        dispkin.Path.ptp(np.zeros(6), np.full(6, 0.1)),
        good_set(),
        PTP_LIMITS,
        robot=ur5e(),
        joint_acceleration=[1, 1, -1, 1, 1, 1],
    ),
    V,
    "joint_acceleration[2] = -1: must be > 0",
)
row(
    "Path.ptp",
    "NaN q_b",
    lambda: dispkin.Path.ptp(np.zeros(6), [0, 0, NAN, 0, 0, 0]),
    V,
    "q_end = (0, 0, nan, 0, 0, 0): must be finite",
)
row(
    "JointTrajectory.sample",
    "times of shape (2, 2)",
    lambda: dispkin.plan(dispkin.Path.ptp(np.zeros(6), np.full(6, 0.1)), good_set(), PTP_LIMITS, robot=ur5e()).sample(
        np.zeros((2, 2))
    ),
    V,
    "times: expected a number or an array of shape (N,), got shape (2, 2)",
)
