"""The overlapped velocity method for a PTP move and a LIN from Python: dispkin.FollowedTrajectory
(the LIN as joint motion on the arm's IK branch) and dispkin.OverlappedMixedTrajectory."""

import pathlib

import numpy as np
import pytest

import dispkin

pytestmark = pytest.mark.skipif(not hasattr(dispkin, "SerialArm"), reason="built without the serial-arm plugin")

DATA = pathlib.Path(__file__).resolve().parents[1] / "data" / "urdf"
VIA = np.array([0.3, -1.4, 1.2, 0.4, 0.8, 0.3])
OTHER = np.array([-0.4, -1.0, 0.9, -0.3, 1.1, -0.5])


def arm():
    return dispkin.SerialArm.from_urdf(str(DATA / "arm_kr6_like_dh.urdf"), "base_link", "flange")


def tool_set():
    s = dispkin.MetricSet()
    s.add_relative([[0.1, 0, 0], [0, 0.1, 0], [0, 0, 0.15]])
    return s


LIMITS = dispkin.Limits(0.5, 1.0, 20.0)


def lin_near_via(robot, towards_via):
    at_via = robot.forward(VIA)
    away = at_via * dispkin.Pose.exp([0.06, -0.04, 0.05, 0.1, 0.0, 0.15])
    path = dispkin.Path.lin(away, at_via) if towards_via else dispkin.Path.lin(at_via, away)
    return dispkin.plan(path, tool_set(), LIMITS)


def check_overlap(robot, o, before, after, lin, lin_offset):
    """The article's joint formula during the overlap, each move alone outside it, the exact end."""
    overlap = o.overlap
    begin = before.duration - overlap
    assert o.duration == pytest.approx(before.duration + after.duration - overlap, abs=1e-12)
    t = np.linspace(0.0, o.duration, 401)
    later = np.clip(t - begin, 0.0, None)
    inside = ((t > begin) & (t < before.duration))[:, None]
    via = after.joint_positions(0.0)
    np.testing.assert_array_equal(via, before.joint_positions(before.duration))
    expected = np.where(
        inside,
        before.joint_positions(t) + after.joint_positions(later) - via,
        np.where((t <= begin)[:, None], before.joint_positions(t), after.joint_positions(later)),
    )
    np.testing.assert_allclose(o.joint_positions(t), expected, rtol=0, atol=1e-12)
    expected_qd = np.where(
        inside,
        before.joint_velocities(t) + after.joint_velocities(later),
        np.where((t <= begin)[:, None], before.joint_velocities(t), after.joint_velocities(later)),
    )
    np.testing.assert_allclose(o.joint_velocities(t), expected_qd, rtol=0, atol=1e-12)
    # Outside the overlap the LIN's own poses, by forward kinematics of the joints, to 1e-9.
    poses = o.sample(t)
    lin_times = t - lin_offset
    on_lin = (lin_times >= 0.0) & (lin_times <= lin.duration) & ~inside[:, 0]
    assert on_lin.sum() > 20
    wanted = lin.sample(lin_times[on_lin])
    for got, want, q in zip(poses[on_lin], wanted, o.joint_positions(t[on_lin])):
        np.testing.assert_allclose(got, robot.forward(q).matrix(), rtol=0, atol=1e-12)
        np.testing.assert_allclose(got, want, rtol=0, atol=1e-9)
    np.testing.assert_array_equal(o.joint_positions(o.duration), after.joint_positions(after.duration))


def test_ptp_then_lin():
    robot = arm()
    ptp = dispkin.plan(dispkin.Path.ptp(OTHER, VIA), tool_set(), LIMITS, robot=robot)
    lin = lin_near_via(robot, towards_via=False)
    followed = dispkin.FollowedTrajectory.from_start(lin, robot, ptp.end)
    np.testing.assert_array_equal(followed.start, ptp.end)
    assert followed.midpoint_error <= 1e-10 and followed.node_count > 10
    o = dispkin.OverlappedMixedTrajectory(ptp, followed, 0.5 * min(ptp.duration, followed.duration))
    assert o.ptp_first
    check_overlap(robot, o, ptp, followed, lin, lin_offset=o.overlap_start)


def test_lin_then_ptp():
    robot = arm()
    ptp = dispkin.plan(dispkin.Path.ptp(VIA, OTHER), tool_set(), LIMITS, robot=robot)
    lin = lin_near_via(robot, towards_via=True)
    followed = dispkin.FollowedTrajectory.to_end(lin, robot, ptp.start)
    np.testing.assert_array_equal(followed.end, ptp.start)
    o = dispkin.OverlappedMixedTrajectory(followed, ptp, 0.7 * min(ptp.duration, followed.duration))
    assert not o.ptp_first
    check_overlap(robot, o, followed, ptp, lin, lin_offset=0.0)


def test_bad_input_names_the_argument():
    robot = arm()
    lin = lin_near_via(robot, towards_via=False)
    with pytest.raises(ValueError, match="q_start"):
        dispkin.FollowedTrajectory.from_start(lin, robot, OTHER)
    with pytest.raises(ValueError, match="q_end"):
        dispkin.FollowedTrajectory.to_end(lin, robot, VIA)
    with pytest.raises(ValueError, match="spacing"):
        dispkin.FollowedTrajectory.from_start(lin, robot, VIA, spacing=-1.0)
    followed = dispkin.FollowedTrajectory.from_start(lin, robot, VIA)
    ptp = dispkin.plan(dispkin.Path.ptp(OTHER, VIA), tool_set(), LIMITS, robot=robot)
    with pytest.raises(ValueError, match="overlap"):
        dispkin.OverlappedMixedTrajectory(ptp, followed, -1.0)
    with pytest.raises(ValueError, match="overlap"):
        dispkin.OverlappedMixedTrajectory(ptp, followed, float("nan"))
    with pytest.raises(ValueError, match="after"):
        dispkin.OverlappedMixedTrajectory(followed, ptp, 0.0)
