"""Blends by nested SLERP (the Mamezou trajectory article's "Fitting Posture") from Python."""

import math
import pickle

import numpy as np
import pytest

import dispkin


def pose(x, y, z=0.0, u=0.0, v=0.0, w=0.0):
    return dispkin.Pose.from_xyzuvw([x, y, z, u, v, w])


def slerp(t, p, q):
    """SLERP of unit quaternions (w, x, y, z), the shorter way, written out."""
    p, q = np.asarray(p, float), np.asarray(q, float)
    d = float(np.dot(p, q))
    if d < 0.0:
        q, d = -q, -d
    theta = math.acos(min(1.0, d))
    if theta < 1e-12:
        return p
    return (math.sin((1 - t) * theta) * p + math.sin(t * theta) * q) / math.sin(theta)


def tool():
    s = dispkin.MetricSet()
    s.add_relative(dispkin.shapes.icosahedron(0.05))
    return s


A, VIA, B, C = (
    pose(0, 0, 0, 0, 0, 0),
    pose(0.3, 0, 0.05, 10, 0, 40),
    pose(0.35, 0.25, 0, 0, 20, 90),
    pose(0.1, 0.3, 0.1, 30, 0, 60),
)


def test_orientation_is_the_articles_nested_slerp_and_the_pivot_a_quadratic_bezier():
    w = 0.3
    path = dispkin.Path.lin(A, VIA).then(dispkin.Path.lin(VIA, B), weight=w, orientation_blend="nested_slerp")
    blend = [s for s in path.sections() if s.kind == "slerp_blend"]
    assert blend
    qm = VIA.quaternion
    q1, q2 = slerp(1 - w, A.quaternion, qm), slerp(w, qm, B.quaternion)
    c1 = A.translation + (1 - w) * (VIA.translation - A.translation)
    c2 = VIA.translation + w * (B.translation - VIA.translation)
    n = len(blend)
    for k, s in enumerate(blend):
        for tau in np.linspace(0.0, 1.0, 5):
            t = (k + tau) / n
            q = slerp(t, slerp(t, q1, qm), slerp(t, qm, q2))
            got = s.pose(tau)
            assert abs(abs(np.dot(got.quaternion, q)) - 1.0) < 1e-12
            c = (1 - t) ** 2 * c1 + 2 * t * (1 - t) * VIA.translation + t * t * c2
            np.testing.assert_allclose(got.translation, c, atol=1e-12)
    assert path.end.is_approx(B, 1e-12)


def test_planner_runs_through_nested_slerp_blends_without_stopping():
    path = dispkin.Path.lin(A, VIA)
    path.then(dispkin.Path.lin(VIA, B), weight=0.4, orientation_blend="nested_slerp").then(
        dispkin.Path.lin(B, C), before=0.05, after=0.04, orientation_blend="nested_slerp"
    )
    traj = dispkin.plan(path, tool(), dispkin.Limits(0.2, 1.0, 10.0))
    assert traj.piece_count == 1
    np.testing.assert_allclose(traj.sample(traj.duration), C.matrix(), atol=1e-9)
    # The tool's acceleration along the blends matches differences of the body twist.
    t = np.linspace(0.1, traj.duration - 0.1, 50)
    dt = 1e-6
    fd = (traj.body_twist(t + dt) - traj.body_twist(t - dt)) / (2 * dt)
    np.testing.assert_allclose(traj.body_acceleration(t), fd, atol=1e-4)


def test_nested_slerp_path_and_trajectory_pickle_round_trip():
    path = dispkin.Path.lin(A, VIA).then(dispkin.Path.lin(VIA, B), weight=0.25, orientation_blend="nested_slerp")
    u = np.linspace(0.0, 1.0, 501)
    again = pickle.loads(pickle.dumps(path))
    assert [s.kind for s in again.sections()] == [s.kind for s in path.sections()]
    np.testing.assert_array_equal(again.sample(u), path.sample(u))
    traj = dispkin.plan(path, tool(), dispkin.Limits(0.2, 1.0, 10.0))
    copy = pickle.loads(pickle.dumps(traj))
    t = np.linspace(0.0, traj.duration, 301)
    np.testing.assert_array_equal(copy.sample(t), traj.sample(t))


@pytest.mark.parametrize(
    "kwargs, name",
    [
        (dict(weight=0.3, orientation_blend="slerp"), "orientation_blend"),
        (dict(weight=0.3, before=0.01), "weight"),
        (dict(weight=0.0), "weight"),
        (dict(weight=0.6), "weight"),
        (dict(weight=float("nan")), "weight"),
        (dict(orientation_blend="nested_slerp"), "orientation_blend"),
    ],
)
def test_bad_blend_arguments_name_the_argument(kwargs, name):
    path = dispkin.Path.lin(A, VIA)
    with pytest.raises(ValueError, match=name):
        path.then(dispkin.Path.lin(VIA, B), **kwargs)
    assert len(path) == 1


def test_nested_slerp_needs_decoupled_lins_at_both_sub_points():
    with pytest.raises(ValueError, match="next"):
        dispkin.Path.lin(A, VIA).then(
            dispkin.Path.circ(VIA, pose(0.4, 0.1), B), weight=0.3, orientation_blend="nested_slerp"
        )
    with pytest.raises(ValueError, match="decoupled LIN"):
        dispkin.Path.lin(A, VIA).then(dispkin.Path.lin(VIA, B, "screw"), weight=0.3, orientation_blend="nested_slerp")
    with pytest.raises(ValueError, match="orientation_blend"):
        dispkin.Path.circ(A, pose(0.2, -0.05), VIA).then(
            dispkin.Path.lin(VIA, B), weight=0.3, orientation_blend="nested_slerp"
        )
