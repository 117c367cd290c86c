"""SPLINE moves and blends at via points from Python."""

import math

import numpy as np
import pytest

import dispkin


def pose(x, y, z=0.0, yaw=0.0):
    return dispkin.Pose.from_xyzuvw([x, y, z, 0.0, 0.0, yaw])


def test_spline_passes_through_its_keys_and_is_cut_into_curve_sections():
    keys = [pose(0, 0), pose(0.2, 0.1, 0.05, 0.3), pose(0.4, 0.0, 0.0, 0.6), pose(0.5, 0.2, 0.1, 0.2)]
    path = dispkin.Path.spline(keys)
    sections = path.sections()
    assert {s.kind for s in sections} == {"curve"}
    assert path.start.is_approx(keys[0], 1e-12) and path.end.is_approx(keys[-1], 1e-12)
    # Every key is the start of some section (the pieces join there).
    for key in keys[1:-1]:
        assert min(np.linalg.norm(s.start.translation - key.translation) for s in sections) < 1e-12


def test_blend_keeps_the_ends_and_runs_through_without_stopping():
    a, p1, via, p2, b = (
        pose(0, 0),
        pose(0.3, 0, 0, 0.2),
        pose(0.45, 0.1, 0, 0.3),
        pose(0.3, 0.2, 0, 0.4),
        pose(0, 0.2, 0, 0.5),
    )
    path = dispkin.Path.lin(a, p1)
    path.then(dispkin.Path.circ(p1, via, p2), blend=0.05).then(dispkin.Path.lin(p2, b), before=0.04, after=0.06)
    assert path.start.is_approx(a, 1e-12) and path.end.is_approx(b, 1e-12)
    tool = dispkin.MetricSet()
    tool.add_relative(dispkin.shapes.icosahedron(0.05))
    traj = dispkin.plan(path, tool, dispkin.Limits(0.2, 1.0, 10.0))
    assert traj.piece_count == 1
    # The corner p1 is cut off: the track passes no closer than a few mm to it.
    track = path.sample(np.linspace(0, 1, 4000))[:, :3, 3]
    assert np.min(np.linalg.norm(track - p1.translation, axis=1)) > 1e-3
    assert np.max(np.linalg.norm(track - p1.translation, axis=1)) > 0.2


@pytest.mark.parametrize(
    "call, message",
    [
        (lambda: dispkin.Path.spline([pose(0, 0), pose(1, 0)]), "at least three"),
        (lambda: dispkin.Path.spline([pose(0, 0), pose(1, 0), pose(1, 0)]), "poses[2]"),
        (lambda: dispkin.Path.spline([pose(0, 0), pose(1, 0), pose(1, 1)], tolerance=math.nan), "tolerance"),
        (
            lambda: dispkin.Path.lin(pose(0, 0), pose(0.1, 0)).then(
                dispkin.Path.lin(pose(0.1, 0), pose(0.1, 0.1)), blend=0.06
            ),
            "half of the move",
        ),
        (
            lambda: dispkin.Path.lin(pose(0, 0), pose(0.1, 0)).then(
                dispkin.Path.lin(pose(0.1, 0), pose(0.1, 0.1)), blend=0.0
            ),
            "before",
        ),
        (
            lambda: dispkin.Path.lin(pose(0, 0), pose(0.1, 0)).then(
                dispkin.Path.lin(pose(0.1, 0), pose(0.1, 0.1)), before=0.01
            ),
            "after is missing",
        ),
        (
            lambda: dispkin.Path.lin(pose(0, 0), pose(0.1, 0)).then(
                dispkin.Path.lin(pose(0.1, 0), pose(0.1, 0.1)), blend=0.01, after=0.01
            ),
            "either blend",
        ),
    ],
)
def test_bad_curves_are_refused(call, message):
    with pytest.raises(ValueError, match=message.replace("[", r"\[").replace("]", r"\]")):
        call()


def test_overlapped_velocity_method_follows_the_articles_formulas():
    a, via, b = pose(0, 0), pose(0.4, 0, 0, 0.3), pose(0.4, 0.4, 0, 0.6)
    tool = dispkin.MetricSet()
    tool.add_relative(dispkin.shapes.icosahedron(0.05))
    limits = dispkin.Limits(0.2, 1.0)
    before = dispkin.plan(dispkin.Path.lin(a, via), tool, limits, profile="trapezoid")
    after = dispkin.plan(dispkin.Path.lin(via, b), tool, limits, profile="trapezoid")
    o = dispkin.OverlappedTrajectory(before, after, 0.2)
    assert o.duration == pytest.approx(before.duration + after.duration - 0.2, abs=1e-12)
    t = np.linspace(o.overlap_start, before.duration, 50)
    got = o.sample(t)
    pb, pf = before.sample(t), after.sample(t - o.overlap_start)
    p2 = via.matrix()
    np.testing.assert_allclose(got[:, :3, 3], pb[:, :3, 3] + pf[:, :3, 3] - p2[:3, 3], atol=1e-12)
    np.testing.assert_allclose(got[:, :3, :3], pf[:, :3, :3] @ p2[:3, :3].T @ pb[:, :3, :3], atol=1e-12)
    # Through the via point without stopping.
    assert np.min(o.path_velocity(np.linspace(0.5, o.duration - 0.5, 200))) > 0.1
    with pytest.raises(ValueError, match="overlap = -1"):
        dispkin.OverlappedTrajectory(before, after, -1.0)


def test_velocity_limited_law_joins_segments_under_their_limits():
    segments = np.array([[0.2, 0.5], [0.05, 0.1], [0.3, 0.4]])
    laws = dispkin.velocity_limited_law(segments, a_max=1.0, j_max=20.0)
    assert {law.kind for law in laws} == {"scurve"} and len(laws) >= 3
    # Laws in order, each within one segment (a segment may hold several); the velocity joins.
    edges = np.cumsum(segments[:, 0])
    start, before = 0.0, 0.0
    for law in laws:
        states = law.sample(np.linspace(0, law.duration, 200))
        segment = int(np.searchsorted(edges, start + 0.5 * law.distance))
        assert start + law.distance <= edges[segment] + 1e-12
        assert states[:, 1].max() <= segments[segment, 1] * (1 + 1e-9)
        assert states[0, 1] == pytest.approx(before, abs=1e-9)
        before, start = states[-1, 1], start + law.distance
    assert start == pytest.approx(edges[-1]) and before == pytest.approx(0.0, abs=1e-9)
    # Never slower than the chain that rests its acceleration at every boundary.
    chain = dispkin.velocity_limited_chain(segments, a_max=1.0, j_max=20.0)
    assert len(chain) == 3
    assert sum(law.duration for law in laws) <= sum(law.duration for law in chain) * (1 + 1e-12)
    with pytest.raises(ValueError, match=r"segments: expected an array of shape \(N, 2\)"):
        dispkin.velocity_limited_law(np.ones((2, 3)), 1.0)


def test_tight_blends_slow_the_path_down():
    a, via, b = pose(0, 0), pose(0.4, 0), pose(0.4, 0.4)
    path = dispkin.Path.lin(a, via).then(dispkin.Path.lin(via, b), blend=0.01)
    tool = dispkin.MetricSet()
    tool.add_relative(dispkin.shapes.icosahedron(0.02))
    traj = dispkin.plan(path, tool, dispkin.Limits(0.5, 1.0, 20.0))
    assert traj.piece_count == 1 and traj.law_count > 1
    t = np.linspace(0, traj.duration, 20000)
    s, v = traj.path_position(t), traj.path_velocity(t)
    assert np.max(v[(s > 0.39) & (s < 0.41)]) < 0.2
