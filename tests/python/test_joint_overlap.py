"""The overlapped velocity method for PTP moves from Python: dispkin.OverlappedJointTrajectory."""

import pathlib

import numpy as np
import pytest

import dispkin

from _helpers import rng_for

pytestmark = pytest.mark.skipif(not hasattr(dispkin, "SerialArm"), reason="built without the serial-arm plugin")

DATA = pathlib.Path(__file__).resolve().parents[1] / "data" / "urdf"


def arm():
    return dispkin.SerialArm.from_urdf(str(DATA / "arm_kr6_like_dh.urdf"), "base_link", "flange")


def tool_set():
    s = dispkin.MetricSet()
    s.add_relative([[0.1, 0, 0], [0, 0.1, 0], [0, 0, 0.15]])
    return s


def two_moves(robot, rng):
    limits = robot.joint_limits
    lower, upper = np.maximum(limits.lower, -np.pi), np.minimum(limits.upper, np.pi)
    a, via, b = (rng.uniform(lower, upper) for _ in range(3))
    lim = dispkin.Limits(0.5, 1.0, 20.0)
    return (
        dispkin.plan(dispkin.Path.ptp(a, via), tool_set(), lim, robot=robot),
        dispkin.plan(dispkin.Path.ptp(via, b), tool_set(), lim, robot=robot),
    )


def test_joints_add_during_the_overlap_and_the_pose_is_the_arms():
    robot = arm()
    before, after = two_moves(robot, rng_for("joint-overlap"))
    overlap = 0.4 * min(before.duration, after.duration)
    o = dispkin.OverlappedJointTrajectory(before, after, overlap)
    assert o.duration == pytest.approx(before.duration + after.duration - overlap, abs=1e-12)
    t = np.linspace(0.0, o.duration, 501)
    begin = before.duration - overlap
    later = np.clip(t - begin, 0.0, None)
    expected = before.joint_positions(t) + np.where(
        (t > begin)[:, None], after.joint_positions(later) - after.start, 0.0
    )
    np.testing.assert_allclose(o.joint_positions(t), expected, atol=1e-12)
    expected_qd = before.joint_velocities(t) + np.where((t > begin)[:, None], after.joint_velocities(later), 0.0)
    np.testing.assert_allclose(o.joint_velocities(t), expected_qd, atol=1e-12)
    poses = o.sample(t)
    for k in range(0, len(t), 50):
        np.testing.assert_allclose(poses[k], robot.forward(o.joint_positions(t[k])).matrix(), atol=1e-12)


def test_bad_overlaps_name_the_argument():
    before, after = two_moves(arm(), rng_for("joint-overlap-bad"))
    with pytest.raises(ValueError, match="overlap"):
        dispkin.OverlappedJointTrajectory(before, after, -1.0)
    with pytest.raises(ValueError, match="overlap"):
        dispkin.OverlappedJointTrajectory(before, after, float("nan"))
    with pytest.raises(ValueError, match="after"):
        dispkin.OverlappedJointTrajectory(after, after, 0.0)
