"""dispkin's objects as Python values: pickle, copy and deepcopy make objects that are equal by
value and sample the same bit for bit; == and isclose compare by value; every result type has a
repr; a number in gives a number-shaped sample out; path accelerations are the derivative of the
path velocities."""

import copy
import math
import pathlib
import pickle

import numpy as np
import pytest

import dispkin

DATA = pathlib.Path(__file__).resolve().parents[2] / "tests" / "data"
Q0 = np.array([0.0, -1.9, 1.9, -1.57, -1.57, 0.0])


def arm():
    return dispkin.SerialArm.from_urdf(str(DATA / "urdf" / "arm_ur5e_dh.urdf"), "base_link", "tool0")


def hexapod():
    return dispkin.Hexapod.symmetric(0.15, math.radians(20), 0.10, math.radians(20), 0.20, 0.15, 0.32, 0.01)


def tool():
    ms = dispkin.MetricSet()
    ms.add_relative([[0.0, 0.0, 0.15], [0.02, 0.0, 0.1]])
    ms.add_sphere([0.0, 0.0, 0.0], 0.04)
    ms.add_absolute([[0.5, 0.0, 0.0]], group=2)
    ms.add_sphere([0.0, 0.3, 0.0], 0.01, absolute=True, group=2)
    ms.set_group_speed(2, 0.1)
    return ms


def pose(*xyzuvw):
    return dispkin.Pose.from_xyzuvw(list(xyzuvw[:3]) + [math.radians(a) for a in xyzuvw[3:]])


def blended_path():
    """LIN, CIRC and SPLINE moves with blends: every kind of section."""
    a, b, c, d = (
        pose(0, 0, 0, 0, 0, 0),
        pose(0.3, 0, 0, 0, 0, 10),
        pose(0.3, 0.2, 0, 0, 0, 30),
        pose(0, 0.2, 0.05, 5, 0, 40),
    )
    path = dispkin.Path.lin(a, b, pivot=(0, 0, 0.1))
    path.then(dispkin.Path.circ(b, pose(0.45, 0.1, 0, 0, 0, 20), c, pivot=(0, 0, 0.1)), blend=0.03)
    path.then(dispkin.Path.spline([c, pose(0.15, 0.25, 0.02, 2, 0, 35), d], pivot=(0, 0, 0.1)), blend=0.02)
    path.then(dispkin.Path.lin(d, pose(0, 0, 0.05, 5, 0, 40), "screw", pivot=(0, 0, 0.1)))
    return path


def round_trips(obj):
    """The object through pickle (every protocol), copy.copy and copy.deepcopy."""
    copies = [pickle.loads(pickle.dumps(obj, protocol)) for protocol in range(2, pickle.HIGHEST_PROTOCOL + 1)]
    return copies + [copy.copy(obj), copy.deepcopy(obj)]


def test_pose_round_trips_bit_for_bit_and_compares_by_value():
    p = dispkin.Pose.exp([0.1, -0.2, 0.3, 0.4, 0.5, -0.6])
    for q in round_trips(p):
        assert type(q) is dispkin.Pose and q == p and hash(q) == hash(p) and q is not p
        np.testing.assert_array_equal(q.quaternion, p.quaternion)
        np.testing.assert_array_equal(q.translation, p.translation)
    assert dispkin.Pose(translation=(1, 2, 3)) == dispkin.Pose(translation=(1.0, 2.0, 3.0))
    assert dispkin.Pose(translation=(1, 2, 3)) != dispkin.Pose(translation=(1, 2, 3.000000001))
    # q and -q are one rotation: the same pose, the same hash (a quaternion of exactly unit norm,
    # which the constructor keeps bit for bit).
    turn = dispkin.Pose(quaternion=(0.5, 0.5, 0.5, 0.5), translation=(0.1, 0.2, 0.3))
    flipped = dispkin.Pose(quaternion=(-0.5, -0.5, -0.5, -0.5), translation=(0.1, 0.2, 0.3))
    assert (
        flipped.quaternion[0] == -0.5 and flipped == turn and hash(flipped) == hash(turn) and len({turn, flipped}) == 1
    )
    np.testing.assert_array_equal(flipped.matrix(), turn.matrix())
    assert (p == "a pose") is False and p != 3


def test_pose_isclose_is_math_isclose_per_coordinate():
    p = pose(0.1, 0.2, 0.3, 10, 20, 30)
    near = dispkin.Pose(quaternion=p.quaternion, translation=p.translation + [0.0, 0.0, 1e-10])
    assert near != p and near.isclose(p) and near.isclose(p, rel_tol=0.0, abs_tol=1e-9)
    assert not near.isclose(p, rel_tol=1e-12)
    turned = p * dispkin.Pose.exp([0, 0, 0, 0, 0, 1e-7])
    assert not turned.isclose(p) and turned.isclose(p, abs_tol=1e-6)
    with pytest.raises(ValueError, match=r"rel_tol = -1"):
        p.isclose(p, rel_tol=-1.0)


def test_limits_compare_and_round_trip():
    a, b = dispkin.Limits(0.25, 1.0, 10.0), dispkin.Limits(0.25, 1.0)
    assert a == dispkin.Limits(0.25, 1.0, 10.0) and a != b and b == dispkin.Limits(0.25, 1.0, None)
    assert hash(a) == hash(dispkin.Limits(0.25, 1.0, 10.0)) and len({a, b, dispkin.Limits(0.25, 1.0)}) == 2
    assert a.isclose(dispkin.Limits(0.25 * (1 + 1e-12), 1.0, 10.0)) and not a.isclose(b)
    for limits in (a, b):
        for c in round_trips(limits):
            assert c == limits and c.jerk == limits.jerk


def test_metric_set_compares_and_round_trips():
    ms = tool()
    for c in round_trips(ms):
        assert c == ms and c is not ms and repr(c) == repr(ms)
        for g in ms.groups:
            np.testing.assert_array_equal(c.relative_points(g), ms.relative_points(g))
            np.testing.assert_array_equal(c.absolute_points(g), ms.absolute_points(g))
            assert c.group_speed(g) == ms.group_speed(g)
    moved = tool()
    moved.add_relative([0.0, 0.0, 0.0])
    assert moved != ms
    other_speed = tool()
    other_speed.set_group_speed(2, 0.1 * (1 + 1e-12))
    assert other_speed != ms and other_speed.isclose(ms) and not other_speed.isclose(ms, rel_tol=1e-14)
    assert dispkin.MetricSet() == dispkin.MetricSet()
    with pytest.raises(TypeError):
        hash(ms)  # mutable: not hashable


def test_path_round_trips_section_by_section_and_samples_the_same():
    path = blended_path()
    kinds = {s.kind for s in path.sections()}
    assert kinds == {"lin", "arc", "curve"}
    u = np.linspace(0.0, 1.0, 1001)
    for c in round_trips(path):
        assert len(c) == len(path)
        np.testing.assert_array_equal(c.sample(u), path.sample(u))
        for s, t in zip(c.sections(), path.sections()):
            assert s.kind == t.kind and s.start == t.start and s.end == t.end
        np.testing.assert_array_equal(c.section_lengths(tool(), 0.25), path.section_lengths(tool(), 0.25))
    # The copy keeps what later blends may take of its last move.
    c = pickle.loads(pickle.dumps(path))
    tail = dispkin.Path.lin(path.end, pose(0.1, 0, 0.05, 5, 0, 40))
    np.testing.assert_array_equal(c.then(tail, blend=0.01).sample(u), path.then(tail, blend=0.01).sample(u))
    joints = dispkin.Path.ptp([0.0, 1.0], [2.0, -1.0])
    for c in round_trips(joints):
        np.testing.assert_array_equal(c.start, joints.start)
        np.testing.assert_array_equal(c.end, joints.end)


def assert_same_trajectory(
    a, b, methods=("sample", "body_twist", "path_position", "path_velocity", "path_acceleration")
):
    assert a.duration == b.duration
    t = np.linspace(-0.1, a.duration + 0.1, 2003)
    for method in methods:
        np.testing.assert_array_equal(getattr(a, method)(t), getattr(b, method)(t), err_msg=method)


def test_trajectory_round_trips_bit_for_bit():
    path = blended_path()
    for profile, limits in (("scurve", dispkin.Limits(0.25, 1.0, 10.0)), ("trapezoid", dispkin.Limits(0.25, 1.0))):
        traj = dispkin.plan(path, tool(), limits, profile)
        for c in round_trips(traj):
            assert type(c) is dispkin.Trajectory
            assert_same_trajectory(c, traj)
            np.testing.assert_array_equal(c.speed_limits(), traj.speed_limits())
            np.testing.assert_array_equal(c.rest_positions(), traj.rest_positions())
            assert (c.piece_count, c.law_count) == (traj.piece_count, traj.law_count)


def test_machines_round_trip():
    h = hexapod()
    for c in round_trips(h):
        assert c.to_json() == h.to_json()
        poses = [h.home * dispkin.Pose.exp([0.01 * k, 0, 0, 0, 0.02 * k, 0]) for k in range(5)]
        np.testing.assert_array_equal(c.inverse(poses), h.inverse(poses))
    a = arm().with_joint_limits(velocity=np.full(6, 2.5))
    a.gravity = (0.0, 0.0, -9.80665)
    for c in round_trips(a):
        assert c.urdf == a.urdf and (c.base_link, c.tip_link, c.robot_name) == (a.base_link, a.tip_link, a.robot_name)
        for name in ("lower", "upper", "velocity", "effort"):
            np.testing.assert_array_equal(getattr(c.joint_limits, name), getattr(a.joint_limits, name))
        np.testing.assert_array_equal(c.gravity, a.gravity)
        np.testing.assert_array_equal(c.torques(Q0, Q0, Q0), a.torques(Q0, Q0, Q0))
        assert c.forward(Q0) == a.forward(Q0)


def test_joint_trajectory_round_trips_by_planning_again():
    path = dispkin.Path.ptp(Q0, Q0 + [0.8, 0.3, -0.3, 0.2, 0.1, 0.4])
    traj = dispkin.plan(path, tool(), dispkin.Limits(0.25, 1.0, 10.0), robot=arm(), joint_acceleration=np.full(6, 4.0))
    for c in round_trips(traj):
        assert type(c) is dispkin.JointTrajectory
        assert_same_trajectory(
            c, traj, ("sample", "joint_positions", "joint_velocities", "joint_accelerations", "path_velocity")
        )


def test_results_round_trip_field_by_field():
    h = hexapod()
    out_of_range = h.home * dispkin.Pose(translation=(0, 0, 0.2))
    check = h.check(out_of_range)
    assert not check.reachable and check.violations
    for c in round_trips(check):
        np.testing.assert_array_equal(c.lengths, check.lengths)
        assert [repr(v) for v in c.violations] == [repr(v) for v in check.violations]
    ms = dispkin.MetricSet()
    h.add_leg_speed_group(ms, 0)
    traj = dispkin.plan(dispkin.Path.lin(h.home, out_of_range), ms, dispkin.Limits(0.05, 0.5), "trapezoid")
    tcheck = h.check_trajectory(traj, 1e-3)
    assert tcheck.excursions
    for c in round_trips(tcheck):
        for name in ("min_length", "max_length", "max_speed"):
            np.testing.assert_array_equal(getattr(c, name), getattr(tcheck, name))
        assert [
            (e.kind, e.leg, e.start_time, e.end_time, e.worst_time, e.worst_value, e.excess) for e in c.excursions
        ] == [
            (e.kind, e.leg, e.start_time, e.end_time, e.worst_time, e.worst_value, e.excess) for e in tcheck.excursions
        ]
    a = arm()
    found = a.inverse_solutions(a.forward(Q0))
    for c in round_trips(found):
        assert (c.within_limits, c.complete, c.family) == (found.within_limits, found.complete, found.family)
        for q, r in zip(c.solutions, found.solutions):
            np.testing.assert_array_equal(q, r)
    for c in round_trips(a.joint_limits):
        np.testing.assert_array_equal(c.velocity, a.joint_limits.velocity)
    lin = dispkin.Path.lin(a.forward(Q0), a.forward(Q0) * pose(0, 0, 0, 0, 0, 90))
    scaled = dispkin.retime(lin, tool(), dispkin.Limits(0.25, 1.0, 10.0), a, Q0)
    optimal = dispkin.retime(lin, tool(), dispkin.Limits(0.25, 1.0), a, Q0, profile="trapezoid", method="optimal")
    for result in (scaled, optimal):
        for c in round_trips(result):
            assert_same_trajectory(c.trajectory, result.trajectory)
            assert repr(c) == repr(result) and repr(c.report) == repr(result.report)
            for key, value in result.report.samples.items():
                np.testing.assert_array_equal(c.report.samples[key], value)
    assert pickle.loads(pickle.dumps(scaled)).limits == scaled.limits
    np.testing.assert_array_equal(pickle.loads(pickle.dumps(optimal)).grid_speed, optimal.grid_speed)


def test_bad_states_are_refused_with_the_type_named():
    with pytest.raises(ValueError, match=r"^Pose.__setstate__: state: expected a tuple of 2 items"):
        dispkin.Pose.__new__(dispkin.Pose).__setstate__((1, 2, 3))
    with pytest.raises(
        ValueError, match=r"^Pose.__setstate__: quaternion \(w, x, y, z\) = \(2, 0, 0, 0\): must be a unit quaternion"
    ):
        dispkin.Pose.__new__(dispkin.Pose).__setstate__(((2.0, 0.0, 0.0, 0.0), (0.0, 0.0, 0.0)))
    state = blended_path().__getstate__()
    broken = ((state[0][0],) + state[0][2:], state[1], state[2], state[3][1:], (0,))  # a section left out: a gap
    with pytest.raises(ValueError, match=r"next = .*must start where the path ends"):
        dispkin.Path.__new__(dispkin.Path).__setstate__(broken)


def test_every_result_type_has_a_repr():
    h = hexapod()
    check = h.check(h.home)
    assert repr(check).startswith("WorkspaceCheck(reachable=True, lengths=(") and "legs_out_of_range=[]" in repr(check)
    far = h.check(h.home * dispkin.Pose(translation=(0, 0, 0.2)))
    legs = ", ".join(str(v.leg) for v in far.violations)
    assert repr(far).startswith("WorkspaceCheck(reachable=False") and f"legs_out_of_range=[{legs}]" in repr(far)
    ms = dispkin.MetricSet()
    h.add_leg_speed_group(ms, 0)
    tcheck = h.check_trajectory(
        dispkin.plan(
            dispkin.Path.lin(h.home, h.home * pose(0.01, 0, 0, 0, 0, 0)), ms, dispkin.Limits(0.005, 0.05), "trapezoid"
        ),
        1e-3,
    )
    assert repr(tcheck).startswith("TrajectoryCheck(ok=True, min_length=(") and "excursions=0)" in repr(tcheck)
    a = arm()
    found = a.inverse_solutions(a.forward(Q0))
    n = len(found.solutions)
    assert (
        repr(found)
        == f"InverseResult(solutions={n}, within_limits={sum(found.within_limits)}, complete=True, family='{found.family}')"
    )
    lin = dispkin.Path.lin(a.forward(Q0), a.forward(Q0) * pose(0, 0, 0, 0, 0, 90))
    scaled = dispkin.retime(lin, tool(), dispkin.Limits(0.25, 1.0, 10.0), a, Q0)
    assert repr(scaled) == (
        f"RetimeResult(duration={scaled.trajectory.duration!r}, iterations={scaled.iterations}, "
        f"velocity_factor={scaled.report.velocity_factor!r}, "
        f"acceleration_factor={scaled.report.acceleration_factor!r})"
    )
    optimal = dispkin.retime(lin, tool(), dispkin.Limits(0.25, 1.0), a, Q0, profile="trapezoid", method="optimal")
    assert repr(optimal).startswith(f"OptimalRetimeResult(duration={optimal.trajectory.duration!r}, velocity_ratio=")
    for obj in (check, tcheck, found, scaled, optimal, scaled.report, a.joint_limits, far.violations[0]):
        assert " object at 0x" not in repr(obj)


def test_a_number_in_gives_a_number_shaped_sample_out():
    traj = dispkin.plan(blended_path(), tool(), dispkin.Limits(0.25, 1.0, 10.0))
    t = 0.37 * traj.duration
    for method, shape in (("sample", (4, 4)), ("sample_xyzuvw", (6,)), ("body_twist", (6,))):
        one = getattr(traj, method)(t)
        assert one.shape == shape, method
        np.testing.assert_array_equal(one, getattr(traj, method)([t])[0])
    for method in ("path_position", "path_velocity", "path_acceleration"):
        value = getattr(traj, method)(t)
        assert type(value) is float and value == getattr(traj, method)([t])[0]
    assert traj.sample(np.float64(t)).shape == (4, 4) and traj.sample([t]).shape == (1, 4, 4)
    ptp = dispkin.plan(dispkin.Path.ptp(Q0, Q0 + 0.3), tool(), dispkin.Limits(0.25, 1.0, 10.0), robot=arm())
    assert ptp.sample(0.1).shape == (4, 4) and ptp.joint_positions(0.1).shape == (6,)
    assert type(ptp.path_velocity(0.1)) is float and ptp.joint_positions([0.1]).shape == (1, 6)


def test_path_acceleration_is_the_derivative_of_the_path_velocity():
    traj = dispkin.plan(blended_path(), tool(), dispkin.Limits(0.25, 1.0, 10.0))
    h = 1e-6
    t = np.linspace(h, traj.duration - h, 4001)
    central = (traj.path_velocity(t + h) - traj.path_velocity(t - h)) / (2 * h)
    # The S-curve's acceleration is continuous: central differences agree to O(h² j').
    np.testing.assert_allclose(traj.path_acceleration(t), central, atol=1e-6)
    assert np.max(np.abs(traj.path_acceleration(t))) == pytest.approx(1.0, rel=1e-3)  # the limit is reached


def test_profiles_and_frames_round_trip():
    for law in (dispkin.Profile.trapezoid(0.3, 0.25, 1.0, 0.1, 0.05), dispkin.Profile.scurve(0.3, 0.25, 1.0, 10.0)):
        t = np.linspace(-0.1, law.duration + 0.1, 1001)
        for c in round_trips(law):
            assert (c.kind, c.duration, c.distance, c.peak_velocity, c.phases) == (
                law.kind,
                law.duration,
                law.distance,
                law.peak_velocity,
                law.phases,
            )
            np.testing.assert_array_equal(c.sample(t), law.sample(t))
    frames = dispkin.WorkToolFrames(pose(0, 0, 0.2, 0, 0, 10), pose(0, 0, 0.05, 5, 0, 0))
    for c in round_trips(frames):
        assert c.work == frames.work and c.tool == frames.tool
        np.testing.assert_array_equal(c.pivot, frames.pivot)


def central_differences_within_sections(traj, path, count, h=1e-5):
    """(times, body_acceleration, central differences of body_twist, section kinds) at `count`
    times whose difference window stays inside one section: across a junction the rate of the
    twist per unit of path may jump (a blend meets a line, a spline's keys are C1 in rotation)."""
    t = np.linspace(h, traj.duration - h, count)
    starts = np.concatenate([[0.0], np.cumsum(traj.section_lengths())])
    before, after = traj.path_position(t - h), traj.path_position(t + h)
    inside = np.searchsorted(starts, before, side="right") == np.searchsorted(starts, after, side="right")
    t = t[inside]
    section = np.searchsorted(starts, traj.path_position(t), side="right") - 1
    source = traj.section_sources()[section, 0].astype(int)  # the path's section each piece was cut from
    kinds = {path.sections()[k].kind for k in source}
    central = (traj.body_twist(t + h) - traj.body_twist(t - h)) / (2 * h)
    return t, traj.body_acceleration(t), central, kinds


def test_body_acceleration_is_the_derivative_of_the_body_twist():
    path = blended_path()
    traj = dispkin.plan(path, tool(), dispkin.Limits(0.25, 1.0, 10.0))
    t, acceleration, central, kinds = central_differences_within_sections(traj, path, 6001)
    assert kinds == {"lin", "arc", "curve"}  # every kind of section is compared
    # Linear and angular parts each at their own scale (the tool does turn faster and slower).
    for part in (slice(0, 3), slice(3, 6)):
        scale = np.max(np.abs(central[:, part]))
        assert scale > 0.1
        np.testing.assert_allclose(acceleration[:, part], central[:, part], atol=1e-6 * scale)
    one = traj.body_acceleration(t[100])
    assert one.shape == (6,)
    np.testing.assert_array_equal(one, acceleration[100])
    # A screw, and a spline turning so little that its curve coefficients come from their series.
    a, b = pose(0, 0, 0, 0, 0, 0), pose(0.2, 0.1, 0, 0, 0, 0.01)
    for other in (dispkin.Path.lin(a, b, "screw"), dispkin.Path.spline([a, pose(0.1, 0.08, 0, 0, 0, 0.004), b])):
        traj = dispkin.plan(other, tool(), dispkin.Limits(0.25, 1.0, 10.0))
        _, acceleration, central, _ = central_differences_within_sections(traj, other, 2001)
        np.testing.assert_allclose(acceleration, central, atol=1e-6 * np.max(np.abs(central)))
