"""PTP moves of a serial arm under the DISP limit: dispkin.plan(Path.ptp(q_a, q_b), ..., robot=arm).

The guarantee by finite differences of the sampled poses (every point of the set, chords over
1e-4 of the duration), the joints against the arm's own forward kinematics and limits, exact
ends, and bad input.
"""

import pathlib

import numpy as np
import pytest

import dispkin

from _helpers import rng_for

pytestmark = pytest.mark.skipif(not hasattr(dispkin, "SerialArm"), reason="built without the serial-arm plugin")

DATA = pathlib.Path(__file__).resolve().parents[1] / "data" / "urdf"


def ur5e():
    return dispkin.SerialArm.from_urdf(str(DATA / "arm_ur5e_dh.urdf"), "base_link", "tool0")


def kr6():
    return dispkin.SerialArm.from_urdf(str(DATA / "arm_kr6_like_dh.urdf"), "base_link", "flange")


def tool_set():
    s = dispkin.MetricSet()
    s.add_relative([[0.1, 0, 0], [0, 0.1, 0], [0, 0, 0.15], [-0.05, -0.05, 0.0]])
    s.add_absolute([[0.3, 0.2, 0.4]], 1)
    s.add_sphere([0.0, 0.0, 0.1], 0.05, True, 1)
    s.set_group_speed(1, 0.3)
    return s


def random_move(rng, arm):
    limits = arm.joint_limits
    lower, upper = np.maximum(limits.lower, -np.pi), np.minimum(limits.upper, np.pi)
    return rng.uniform(lower, upper), rng.uniform(lower, upper)


def chord_speeds(metric_set, poses, dt, system_velocity):
    """Per sample interval the largest speed / limit of the set's points (chords of the poses;
    the spheres are checked by the C++ oracle)."""
    worst = np.zeros(len(poses) - 1)
    for group in metric_set.groups:
        limit = metric_set.group_speed(group) or system_velocity
        rel = np.asarray(metric_set.relative_points(group)).reshape(-1, 3)
        ab = np.asarray(metric_set.absolute_points(group)).reshape(-1, 3)
        R, t = poses[:, :3, :3], poses[:, :3, 3]
        if len(rel):
            x = np.einsum("nij,pj->npi", R, rel) + t[:, None, :]
            worst = np.maximum(worst, np.linalg.norm(np.diff(x, axis=0), axis=2).max(axis=1) / dt / limit)
        if len(ab):
            b = np.einsum("nji,npj->npi", R, ab[None, :, :] - t[:, None, :])
            worst = np.maximum(worst, np.linalg.norm(np.diff(b, axis=0), axis=2).max(axis=1) / dt / limit)
    return worst


@pytest.mark.parametrize("make_arm", [ur5e, kr6], ids=["ur5e", "kr6"])
@pytest.mark.parametrize("profile", ["scurve", "trapezoid"])
def test_no_point_exceeds_its_limit_and_joints_follow_the_arm(make_arm, profile):
    arm = make_arm()
    rng = rng_for(f"ptp-{make_arm.__name__}-{profile}")
    s = tool_set()
    limits = dispkin.Limits(0.5, 2.0, 20.0 if profile == "scurve" else None)
    for _ in range(5):
        q_a, q_b = random_move(rng, arm)
        traj = dispkin.plan(dispkin.Path.ptp(q_a, q_b), s, limits, profile, robot=arm)
        assert isinstance(traj, dispkin.JointTrajectory)
        t = np.linspace(0.0, traj.duration, 10001)
        poses = traj.sample(t)
        assert poses.shape == (len(t), 4, 4)
        assert chord_speeds(s, poses, t[1] - t[0], limits.velocity).max() <= 1.0 + 1e-6
        q, qd, qdd = traj.joint_positions(t), traj.joint_velocities(t), traj.joint_accelerations(t)
        assert q.shape == qd.shape == qdd.shape == (len(t), arm.dof)
        for k in range(0, len(t), 500):
            np.testing.assert_allclose(arm.forward(q[k]).matrix(), poses[k], atol=1e-12)
        # Every joint on the line from q_a to q_b, in step (a synchronized move).
        u = traj.parameter(t)
        np.testing.assert_allclose(q, q_a + u[:, None] * (q_b - q_a), atol=1e-12)
        assert np.all(np.abs(qd) <= arm.joint_limits.velocity * (1 + 1e-9))
        np.testing.assert_array_equal(q[0], q_a)
        np.testing.assert_array_equal(q[-1], q_b)
        assert np.all(qd[0] == 0.0) and np.all(qd[-1] == 0.0)
        xyzuvw = traj.sample_xyzuvw(t[::1000])
        np.testing.assert_allclose(xyzuvw, [dispkin.Pose.from_matrix(m).to_xyzuvw() for m in poses[::1000]], atol=1e-12)
        # The body twist is the arm's body Jacobian times q-dot.
        twists = traj.body_twist(t[::1000])
        for k, twist in zip(range(0, len(t), 1000), twists):
            np.testing.assert_allclose(twist, arm.body_jacobian(q[k]) @ qd[k], atol=1e-12)


def test_sections_bound_the_dense_speed():
    arm = ur5e()
    s = tool_set()
    q_a, q_b = np.array([0.2, -1.4, 1.2, -0.9, -1.3, 0.1]), np.array([1.5, -0.7, 0.6, -1.8, -0.8, 1.2])
    traj = dispkin.plan(dispkin.Path.ptp(q_a, q_b), s, dispkin.Limits(0.5, 2.0, 20.0), robot=arm)
    sections = traj.sections()
    assert sections.shape[1] == 5 and sections[0, 0] == 0.0 and sections[-1, 1] == 1.0
    for u0, u1, length, _, _ in sections[:: max(1, len(sections) // 30)]:
        for u in np.linspace(u0, u1, 33):
            q = q_a + u * (q_b - q_a)
            twist = arm.body_jacobian(q) @ (q_b - q_a) * (u1 - u0)
            assert dispkin.max_point_speed(s, arm.forward(q), twist, 0.5) <= length * (1 + 1e-12)
    # s runs at a rate du/ds at most h/L of each section, within 1 % of it (the junction rule).
    assert sections[:, 2].sum() <= traj.length <= 1.01 * sections[:, 2].sum()


def test_joint_limits_bind_and_hold():
    base = ur5e()
    arm = base.with_joint_limits(velocity=np.full(6, 0.4))
    s = dispkin.MetricSet()
    s.add_relative([[0.05, 0, 0], [0, 0.05, 0], [0, 0, 0.05]])
    q_a, q_b = np.zeros(6), np.array([1.0, -0.5, 0.8, 0.3, -0.6, 1.2])
    traj = dispkin.plan(
        dispkin.Path.ptp(q_a, q_b), s, dispkin.Limits(5.0, 50.0, 500.0), robot=arm, joint_acceleration=np.full(6, 1.0)
    )
    t = np.linspace(0.0, traj.duration, 4001)
    qd, qdd = traj.joint_velocities(t), traj.joint_accelerations(t)
    assert np.abs(qd).max() <= 0.4 * (1 + 1e-9)
    assert np.abs(qd).max() >= 0.95 * 0.4  # the 5 % staircase of the velocity-limit curve
    assert np.abs(qdd).max() <= 1.0 * (1 + 1e-9)


def test_bad_input_is_refused():
    arm = ur5e()
    s = tool_set()
    limits = dispkin.Limits(0.5, 2.0, 20.0)
    q = np.zeros(6)
    with pytest.raises(ValueError, match="robot"):
        dispkin.plan(dispkin.Path.ptp(q, q + 0.1), s, limits)
    with pytest.raises(ValueError, match="q_a size"):
        dispkin.plan(dispkin.Path.ptp(np.zeros(5), np.ones(5)), s, limits, robot=arm)
    with pytest.raises(ValueError, match="q_end"):
        dispkin.Path.ptp(q, np.array([0, 0, np.nan, 0, 0, 0]))
    with pytest.raises(ValueError, match="position limits"):
        dispkin.plan(dispkin.Path.ptp(q, np.array([0, 7.0, 0, 0, 0, 0])), s, limits, robot=arm)
    with pytest.raises(ValueError, match="equals q_a"):
        dispkin.plan(dispkin.Path.ptp(q, q), s, limits, robot=arm)
    with pytest.raises(ValueError, match="jerk"):
        dispkin.plan(dispkin.Path.ptp(q, q + 0.1), s, dispkin.Limits(0.5, 2.0), "scurve", robot=arm)
    with pytest.raises(ValueError, match="joint_acceleration"):
        dispkin.plan(dispkin.Path.ptp(q, q + 0.1), s, limits, robot=arm, joint_acceleration=np.ones(3))
    with pytest.raises(ValueError, match="tolerance"):
        dispkin.plan(dispkin.Path.ptp(q, q + 0.1), s, limits, robot=arm, tolerance=0.0)
    with pytest.raises(ValueError, match="times"):
        dispkin.plan(dispkin.Path.ptp(q, q + 0.1), s, limits, robot=arm).sample(np.zeros((2, 2)))
