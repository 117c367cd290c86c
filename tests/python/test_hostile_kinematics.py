"""Hostile inputs to the kinematics (doc/input-budget.md): inverse kinematics under wide joint
limits, the IK time budget on long chains, joint accelerations a scaling retime would ignore, a
CIRC through a via point nearly on the line, and the schema's words for XYZUVW. Each case gives
dispkin's own error or the right answer, within bounded time and memory.
"""

import math
import pathlib
import time

import numpy as np
import pytest

import dispkin

from _hostile import SLOWDOWN, UR5E, refusal_in_child, robots_dir


# --- 3, 4. IK with wide joint limits ----------------------------------------------------------

Q = np.array([0.3, -1.2, 1.5, -1.9, -1.57, 0.2])


def ur5e_with_limits(bound):
    arm = dispkin.SerialArm.from_urdf(UR5E, "base_link", "tool0")
    return arm.with_joint_limits(lower=[-bound] * 6, upper=[bound] * 6)


def wrapped(q):
    return np.remainder(np.asarray(q) + np.pi, 2 * np.pi) - np.pi


@pytest.mark.parametrize("bound", [math.pi, 2 * math.pi, 20.0, 100.0, 1e8, 1e16])
def test_inverse_returns_the_distinct_solutions_nearest_zero(bound):
    arm = ur5e_with_limits(bound)
    pose = arm.forward(Q)
    solutions = arm.inverse(pose)
    reference = ur5e_with_limits(math.pi - 1e-9).inverse(pose)  # one copy per branch already
    assert len(solutions) == len(reference) == 8
    for s in solutions:
        assert arm.forward(s).is_approx(pose, 1e-10)
        assert np.all(np.abs(s) <= math.pi + 1e-9), s  # the copy nearest 0, to the polish's rounding
    assert min(np.abs(s - Q).max() for s in solutions) <= 1e-9


def test_wide_limits_take_neither_time_nor_memory():
    # ±100 rad: 8 solutions × 32⁶ copies = 8.6e9 were enumerated (23.6 GB, killed).
    message = refusal_in_child(
        f"""
        arm = dispkin.SerialArm.from_urdf({UR5E!r}, "base_link", "tool0").with_joint_limits(lower=[-100] * 6, upper=[100] * 6)
        pose = arm.forward({Q.tolist()})
        assert len(arm.inverse(pose)) == 8
        arm.inverse(pose, offer_equivalents=True)
        """,
        address_space=1 << 31,
    )
    assert "offer_equivalents = \"true\": asks for the 2π copies of the 8 solutions inside the joint limits" in message
    assert "more than 10000" in message


def test_the_copies_on_request_are_every_one_inside_the_limits():
    arm = ur5e_with_limits(2 * math.pi)
    pose = arm.forward(Q)
    copies = arm.inverse(pose, offer_equivalents=True)
    assert len(copies) == 8 * 2**6  # each joint has two values in [−2π, 2π]
    assert len({tuple(np.round(wrapped(c), 7)) for c in copies}) == 8
    assert min(np.abs(c - Q).max() for c in copies) <= 1e-9
    for c in copies:
        assert np.all(np.abs(c) <= 2 * math.pi + 1e-10) and arm.forward(c).is_approx(pose, 1e-10)


def test_follow_keeps_turning_through_wide_limits():
    # The branch follower finds the 2π copy nearest the previous joints in closed form: with
    # ±1e16 rad it neither steps through the range nor loses the joint's turn count.
    arm = ur5e_with_limits(1e16)
    start = Q + np.array([4 * np.pi, 0, 0, 0, 0, -2 * np.pi])
    poses = [arm.forward(start + 0.01 * k) for k in range(5)]
    path = arm.follow(poses, start)
    assert np.abs(path - (start + 0.01 * np.arange(5)[:, None])).max() <= 1e-9


def test_iris_rotor_limits_of_1e16_find_the_solutions():
    iris = robots_dir() / "iris_description" / "robots" / "iris.urdf"
    if not iris.exists():
        pytest.skip(f"{iris} is not installed")
    arm = dispkin.SerialArm.from_urdf(str(iris), "iris__base_link", "iris__rotor_0")
    assert arm.joint_limits.upper[0] >= 1e15
    for angle in np.linspace(-3, 3, 200):
        pose = arm.forward([angle])
        solutions = arm.inverse(pose)
        assert solutions and min(abs(s[0] - angle) for s in solutions) <= 1e-9


# --- 10. the IK time budget on long chains ---------------------------------------------------


def long_chain_urdf(joints):
    """A chain of `joints` revolute joints, axes alternating z and y, links of 1/joints m."""
    parts = ['<robot name="chain"><link name="l0"/>']
    for k in range(1, joints + 1):
        axis = "0 0 1" if k % 2 else "0 1 0"
        parts.append(
            f'<link name="l{k}"/><joint name="j{k}" type="revolute"><parent link="l{k - 1}"/><child link="l{k}"/>'
            f'<origin xyz="{1.0 / joints} 0 0"/><axis xyz="{axis}"/><limit lower="-3" upper="3" velocity="1" effort="1"/></joint>'
        )
    parts.append("</robot>")
    return "".join(parts)


@pytest.mark.parametrize("joints, budget, slack", [(1000, 0.05, 0.15), (10_000, 0.5, 1.0)])
def test_the_time_budget_bounds_the_search_on_long_chains(joints, budget, slack):
    arm = dispkin.SerialArm.from_urdf(long_chain_urdf(joints), "l0", f"l{joints}")
    assert arm.family == "general"
    pose = arm.forward(np.full(joints, 0.001))
    start = time.perf_counter()
    result = arm.inverse_solutions(pose, time_budget=budget)
    elapsed = time.perf_counter() - start
    assert not result.complete
    assert elapsed <= budget + slack * SLOWDOWN, f"{elapsed:.2f} s for a budget of {budget} s"  # was 0.45 s / 39 s
    for s in result.solutions:
        assert arm.forward(s).is_approx(pose, 1e-10)


# --- 11. retime(method="scaling") and joint accelerations -------------------------------------


def test_scaling_retime_refuses_joint_accelerations_it_would_ignore():
    arm = dispkin.SerialArm.from_urdf(UR5E, "base_link", "tool0")
    a = arm.forward(Q)
    path = dispkin.Path.lin(a, dispkin.Pose(a.quaternion, a.translation + np.array([0.05, 0, 0])))
    points = dispkin.MetricSet()
    points.add_relative(np.eye(3))
    with pytest.raises(
        ValueError, match=r"joint_acceleration = \(1, 1, 1, 1, 1, 1\): is not a limit of method=\"scaling\""
    ):
        dispkin.retime(path, points, dispkin.Limits(0.1, 1.0, 10.0), arm, Q, joint_acceleration=np.ones(6))


# --- 14. a CIRC through a via point nearly on the line beyond its end --------------------------


@pytest.mark.parametrize("offset", [1e-9, 1e-7, 1e-5])
def test_a_nearly_collinear_via_beyond_the_end_is_refused(offset):
    a, end = dispkin.Pose(), dispkin.Pose.from_xyzuvw([0.1, 0, 0, 0, 0, 0])
    via = dispkin.Pose.from_xyzuvw([0.2, offset, 0, 0, 0, 0])
    with pytest.raises(
        ValueError, match=r"^via = \(0\.2, .*\): is almost collinear with the start and end points and outside"
    ):
        dispkin.Path.circ(a, via, end)


def test_a_wide_arc_through_well_spread_points_is_planned():
    # Three quarters of a circle of 0.1 m: its via point is beyond the chord's end too.
    a, via, end = (dispkin.Pose.from_xyzuvw([0.1 * math.cos(t), 0.1 * math.sin(t), 0, 0, 0, 0]) for t in (0, 2.0, 4.7))
    path = dispkin.Path.circ(a, via, end)
    assert path.end.is_approx(end, 1e-12)


# --- 16. the schema's words for XYZUVW --------------------------------------------------------


def test_the_schema_describes_xyzuvw_as_the_code_computes_it():
    text = (pathlib.Path(dispkin.__file__).parent / "job.schema.json").read_text(encoding="utf-8")
    assert "R = Rx(u)·Ry(v)·Rz(w)" in text and "moving x, y, z axes, u first" in text
    u, v, w = 0.3, -0.5, 0.9

    def rx(t):
        return np.array([[1, 0, 0], [0, math.cos(t), -math.sin(t)], [0, math.sin(t), math.cos(t)]])

    def ry(t):
        return np.array([[math.cos(t), 0, math.sin(t)], [0, 1, 0], [-math.sin(t), 0, math.cos(t)]])

    def rz(t):
        return np.array([[math.cos(t), -math.sin(t), 0], [math.sin(t), math.cos(t), 0], [0, 0, 1]])

    rotation = dispkin.Pose.from_xyzuvw([0, 0, 0, u, v, w]).rotation()
    np.testing.assert_allclose(rotation, rx(u) @ ry(v) @ rz(w), rtol=0, atol=1e-15)
