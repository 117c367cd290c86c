"""Hexapod: shapes in and out, inverse against numpy, forward round trips, pivots, the
workspace check, description files and errors."""

import json
import math

import numpy as np
import pytest

import dispkin
from _helpers import axis_rotation, rng_for


def desktop():
    return dispkin.Hexapod.symmetric(0.15, math.radians(20), 0.10, math.radians(20), 0.20, 0.15, 0.32, 0.01)


def near_home(h, rng, n):
    poses = []
    while len(poses) < n:
        twist = np.concatenate([rng.uniform(-0.03, 0.03, 3), rng.uniform(-0.15, 0.15, 3)])
        pose = h.home * dispkin.Pose.exp(twist)
        if h.check(pose).reachable:
            poses.append(pose)
    return poses


def numpy_legs(h, matrix):
    p = h.platform_joints @ matrix[:3, :3].T + matrix[:3, 3]
    return np.linalg.norm(p - h.base_joints, axis=1)


def test_inverse_matches_numpy_for_one_pose_a_list_and_a_stack():
    h = desktop()
    poses = near_home(h, rng_for("hexapod inverse"), 50)
    stack = np.array([p.matrix() for p in poses])
    expected = np.array([numpy_legs(h, m) for m in stack])
    one = h.inverse(poses[0])
    assert one.shape == (6,)
    np.testing.assert_allclose(one, expected[0], rtol=0, atol=1e-14)
    np.testing.assert_allclose(h.inverse(stack[0]), expected[0], rtol=0, atol=1e-14)
    assert h.inverse(poses).shape == (50, 6)
    np.testing.assert_allclose(h.inverse(poses), expected, rtol=0, atol=1e-14)
    np.testing.assert_allclose(h.inverse(stack), expected, rtol=0, atol=1e-14)
    assert h.inverse([]).shape == (0, 6)


def test_inverse_xyzuvw_rotates_about_the_pivot():
    h = desktop()
    v = np.array([0.01, -0.02, 0.21, 0.05, -0.08, 0.1])
    pivot = np.array([0.0, 0.01, 0.05])
    r = axis_rotation(0, v[3]) @ axis_rotation(1, v[4]) @ axis_rotation(2, v[5])
    x = (h.platform_joints - pivot) @ r.T + pivot + v[:3]
    expected = np.linalg.norm(x - h.base_joints, axis=1)
    np.testing.assert_allclose(h.inverse_xyzuvw(v, pivot), expected, rtol=0, atol=1e-14)
    np.testing.assert_allclose(
        h.inverse_xyzuvw(np.stack([v, v]), pivot), np.stack([expected, expected]), rtol=0, atol=1e-14
    )
    np.testing.assert_allclose(h.inverse_xyzuvw(v), h.inverse(dispkin.Pose.from_xyzuvw(v)), rtol=0, atol=0)


def test_forward_of_inverse_is_the_pose():
    h = desktop()
    for pose in near_home(h, rng_for("hexapod forward"), 200):
        legs = h.inverse(pose)
        found = h.forward(legs)
        assert found.is_approx(pose, 1e-12)
        assert np.max(np.abs(h.inverse(found) - legs)) <= 1e-12
        assert h.forward(legs, guess=pose.matrix()).is_approx(pose, 1e-12)


def test_leg_jacobian_maps_body_twists_to_leg_speeds():
    h = desktop()
    pose = near_home(h, rng_for("hexapod jacobian"), 1)[0]
    j = h.leg_jacobian(pose)
    assert j.shape == (6, 6)
    xi = np.array([0.3, -0.2, 0.1, 0.5, -0.4, 0.2])
    step = 1e-6
    numeric = (h.inverse(pose * dispkin.Pose.exp(step * xi)) - h.inverse(pose * dispkin.Pose.exp(-step * xi))) / (
        2 * step
    )
    np.testing.assert_allclose(j @ xi, numeric, rtol=0, atol=1e-8)


def test_symmetric_layouts():
    h = dispkin.Hexapod.symmetric(0.2, 0.3, 0.1, 0.0, 0.25, 0.1, 0.5, 0.02)
    assert h.base_joints.shape == (6, 3) and h.platform_joints.shape == (6, 3)
    np.testing.assert_allclose(h.base_joints[0], [0.2 * math.cos(-0.15), 0.2 * math.sin(-0.15), 0.0], atol=1e-15)
    np.testing.assert_allclose(h.platform_joints[1], h.platform_joints[2], atol=1e-16)  # 6-3
    np.testing.assert_allclose(
        h.platform_joints[1], [0.1 * math.cos(math.pi / 3), 0.1 * math.sin(math.pi / 3), 0], atol=1e-15
    )
    np.testing.assert_allclose(h.home.translation, [0, 0, 0.25])
    assert h.dof == 6 and h.joint_names == ["leg1", "leg2", "leg3", "leg4", "leg5", "leg6"]


def test_general_constructor_accepts_scalar_or_per_leg_limits():
    s = desktop()
    h = dispkin.Hexapod(s.base_joints, s.platform_joints, 0.15, np.full(6, 0.32), [0.01] * 6, home=s.home)
    np.testing.assert_array_equal(h.base_joints, s.base_joints)
    np.testing.assert_array_equal(h.platform_joints, s.platform_joints)
    np.testing.assert_array_equal(h.leg_min, np.full(6, 0.15))
    np.testing.assert_array_equal(h.leg_max, np.full(6, 0.32))
    assert h.home.is_approx(s.home, 0.0)
    assert dispkin.Hexapod(s.base_joints, s.platform_joints, 0.1, 0.3, 0.01).home.is_approx(dispkin.Pose(), 0.0)


def test_new_pivot_keeps_the_pose():
    v = np.array([0.01, 0.02, 0.2, 0.1, -0.2, 0.3])
    old, new = np.array([0.0, 0.0, 0.05]), np.array([0.02, -0.01, 0.1])
    w = dispkin.xyzuvw_for_new_pivot(v, old, new)
    assert dispkin.Pose.from_xyzuvw(w, new).is_approx(dispkin.Pose.from_xyzuvw(v, old), 1e-14)
    np.testing.assert_array_equal(w[3:], v[3:])


def test_check_names_the_leg():
    s = desktop()
    length = s.inverse(s.home)[0]
    hi = np.full(6, 0.32)
    hi[4] = length - 0.005
    h = dispkin.Hexapod(s.base_joints, s.platform_joints, 0.15, hi, 0.01, home=s.home)
    c = h.check(h.home)
    assert not c.reachable and not c
    assert len(c.violations) == 1
    v = c.violations[0]
    assert v.leg == 4 and v.upper == hi[4] and abs(v.excess - 0.005) < 1e-15 and v.length == c.lengths[4]
    with pytest.raises(ValueError, match=r"^leg 4 length = .*outside the leg's range"):
        h.require_reachable(h.home)
    assert s.check(s.home.matrix()).reachable


def test_forward_refuses_legs_out_of_range():
    h = desktop()
    legs = h.inverse(h.home)
    legs[5] = 5.0
    with pytest.raises(ValueError, match=r"legs\[5\] is outside its length range"):
        h.forward(legs)


def test_forward_failures_raise_runtime_error():
    # Wide leg ranges, so that forward() gets to Newton's method and reports its failures.
    h = dispkin.Hexapod.symmetric(0.15, math.radians(20), 0.10, math.radians(20), 0.20, 0.0, 10.0, 0.01)
    legs = h.inverse(h.home)
    legs[5] = 5.0
    with pytest.raises(RuntimeError, match=r"no convergence after 50 iterations, leg length residual"):
        h.forward(legs)
    flat = dispkin.Pose()
    with pytest.raises(RuntimeError, match=r"singular leg Jacobian"):
        h.forward(h.inverse(flat) + 1e-3, guess=flat)


def test_save_and_load_round_trip(tmp_path):
    h = desktop()
    path = tmp_path / "hexapod.json"
    h.save(str(path))
    description = json.loads(path.read_text())
    assert description["format"] == "dispkin.hexapod" and len(description["legs"]) == 6
    g = dispkin.Hexapod.load(str(path))
    np.testing.assert_array_equal(g.base_joints, h.base_joints)
    np.testing.assert_array_equal(g.platform_joints, h.platform_joints)
    np.testing.assert_array_equal(g.leg_speed, h.leg_speed)
    assert g.home.is_approx(h.home, 0.0)


def test_malformed_description_names_the_key(tmp_path):
    description = json.loads(desktop().to_json())
    del description["legs"][3]["platform"]
    path = tmp_path / "broken.json"
    path.write_text(json.dumps(description))
    with pytest.raises(ValueError, match=r"legs\[3\]\.platform = \"<missing>\": required key is missing"):
        dispkin.Hexapod.load(str(path))
    with pytest.raises(ValueError, match=r"is not JSON"):
        dispkin.Hexapod.from_json("{")


@pytest.mark.parametrize(
    "kwargs, message",
    [
        (dict(base_joints=np.zeros((5, 3))), r"^base_joints: expected an array of shape \(6, 3\), got shape \(5, 3\)"),
        (dict(platform_joints=np.zeros((6, 3))), r"^platform_joints = .*must not be collinear"),
        (dict(leg_min=np.zeros(5)), r"^leg_min: expected a number or an array of shape \(6,\), got shape \(5,\)"),
        (dict(leg_max=0.1), r"^leg_max\[0\] = 0.1: must be finite and greater than leg_min\[0\]"),
        (dict(leg_speed=-1.0), r"^leg_speed\[0\] = -1: must be in \[1e-12, 1e12\]"),
        (dict(home=np.eye(3)), r"^home: expected an array of shape \(4, 4\)"),
    ],
)
def test_bad_constructor_arguments(kwargs, message):
    s = desktop()
    args = dict(
        base_joints=s.base_joints, platform_joints=s.platform_joints, leg_min=0.15, leg_max=0.32, leg_speed=0.01
    )
    args.update(kwargs)
    with pytest.raises(ValueError, match=message):
        dispkin.Hexapod(**args)


@pytest.mark.parametrize(
    "call, message",
    [
        (lambda h: h.inverse(np.eye(3)), r"^pose: expected an array of shape \(4, 4\), got shape \(3, 3\)"),
        (
            lambda h: h.inverse(np.zeros((2, 3, 3))),
            r"^pose: expected a Pose, a sequence of Poses, or an array of shape \(4, 4\) or \(N, 4, 4\), got shape \(2, 3, 3\)",
        ),
        (lambda h: h.inverse([h.home, "x"]), r"^pose\[1\]: expected an array of shape \(4, 4\)"),
        (
            lambda h: h.inverse_xyzuvw(np.zeros(5)),
            r"^xyzuvw: expected an array of shape \(6,\) or \(N, 6\), got shape \(5,\)",
        ),
        (lambda h: h.inverse_xyzuvw(np.zeros(6), pivot=(0, 0)), r"^pivot: expected an array of shape \(3,\)"),
        (lambda h: h.forward(np.ones(7)), r"^legs: expected an array of shape \(6,\)"),
        (lambda h: h.forward([0.2, math.nan, 0.2, 0.2, 0.2, 0.2]), r"^legs\[1\] = nan"),
        (lambda h: h.check(np.eye(4) * 2), r"^matrix last row = \(0, 0, 0, 2\)"),
        (
            lambda h: dispkin.Hexapod.symmetric(0.0, 0.3, 0.1, 0.3, 0.2, 0.1, 0.3, 0.01),
            r"^base_radius = 0: must be finite and greater than zero",
        ),
        (
            lambda h: dispkin.xyzuvw_for_new_pivot(np.zeros(6), (0, 0, 0), (0, 0, math.inf)),
            r"^new_pivot = .*must be finite",
        ),
    ],
)
def test_bad_call_arguments(call, message):
    with pytest.raises(ValueError, match=message):
        call(desktop())


def test_leg_speed_group_bounds_every_leg_along_a_planned_trajectory():
    h = desktop()
    a, b = near_home(h, rng_for("hexapod trajectory"), 2)
    tool = dispkin.MetricSet()
    tool.add_relative([(0.0, 0.0, 0.05), (0.02, 0.0, 0.05), (0.0, 0.02, 0.05)])
    fast = h.check_trajectory(dispkin.plan(dispkin.Path.lin(a, b), tool, dispkin.Limits(0.1, 1.0, 20.0)), 1e-3)
    assert not fast.ok and all(e.kind == "speed" for e in fast.excursions)
    assert max(fast.max_speed) > 2 * h.leg_speed[0]

    h.add_leg_speed_group(tool, 1)
    trajectory = dispkin.plan(dispkin.Path.lin(a, b), tool, dispkin.Limits(0.1, 1.0, 20.0))
    check = h.check_trajectory(trajectory, trajectory.duration / 2000)
    assert check.ok and check.excursions == []
    assert np.all(check.max_speed <= h.leg_speed * (1 + 1e-9))
    assert check.max_speed.shape == (6,) and check.min_length.shape == (6,)
    # The extremes are those of the sampled leg lengths.
    times = np.linspace(0.0, trajectory.duration, 2001)
    legs = h.inverse(trajectory.sample(times))
    np.testing.assert_allclose(check.min_length, legs.min(axis=0), rtol=0, atol=1e-15)
    np.testing.assert_allclose(check.max_length, legs.max(axis=0), rtol=0, atol=1e-15)
    with pytest.raises(ValueError, match=r"^dt = 0: must be finite and greater than zero"):
        h.check_trajectory(trajectory, 0.0)


def test_check_of_a_trajectory_is_check_trajectory():
    hx = dispkin.Hexapod.symmetric(0.12, math.radians(20), 0.08, math.radians(20), 0.15, 0.13, 0.20, 0.01)
    a = dispkin.Pose.from_xyzuvw([0, 0, 0.15, 0, 0, 0])
    b = dispkin.Pose.from_xyzuvw([0.01, 0, 0.15, 0, math.radians(3), 0])
    tool = dispkin.MetricSet()
    tool.add_relative(dispkin.shapes.icosahedron(0.02))
    hx.add_leg_speed_group(tool, 1)
    traj = dispkin.plan(dispkin.Path.lin(a, b), tool, dispkin.Limits(0.01, 0.05, 0.5))
    report = hx.check(traj)
    same = hx.check_trajectory(traj, 1e-3)
    assert report.ok and same.ok
    np.testing.assert_array_equal(report.max_speed, same.max_speed)
    assert isinstance(hx.check(a), dispkin.WorkspaceCheck)
