"""The planner from Python: the API names (plan, sample, sample_xyzuvw, path_velocity, ...), the
guarantee, and the KDL comparison."""

import math

import numpy as np
import pytest

import dispkin

DEG = math.pi / 180


def pose(x, y, z, u=0.0, v=0.0, w=0.0):
    return dispkin.Pose.from_xyzuvw([x, y, z, u, v, w])


def tool_sphere(radius=0.1):
    tool = dispkin.MetricSet()
    tool.add_relative(dispkin.shapes.icosphere(radius, 3))  # a fine sphere of relative points
    return tool


def max_point_speed_sampled(traj, points, steps=20000):
    """Largest speed of the relative points, by chords over steps of duration / steps."""
    t = np.linspace(0.0, traj.duration, steps + 1)
    mats = traj.sample(t)
    world = np.einsum("nij,pj->npi", mats[:, :3, :3], points) + mats[:, None, :3, 3]
    return float(np.max(np.linalg.norm(np.diff(world, axis=0), axis=2)) / (t[1] - t[0]))


def test_api_names_and_shapes():
    path = dispkin.Path.lin(pose(0, 0, 0), pose(0.2, 0.05, 0, 0, 0, 30 * DEG))
    limits = dispkin.Limits(velocity=0.1, acceleration=0.5, jerk=5.0)
    traj = dispkin.plan(path, tool_sphere(), limits, profile="scurve")
    assert traj.duration > 0
    times = np.linspace(0, traj.duration, 11)
    assert traj.sample(times).shape == (11, 4, 4)
    assert traj.sample_xyzuvw(times).shape == (11, 6)
    v = traj.path_velocity(times)
    assert v.shape == (11,) and v[0] == 0.0 and v[-1] == pytest.approx(0.0, abs=1e-12)
    assert np.all(v <= 0.1 * (1 + 1e-12))
    np.testing.assert_allclose(traj.sample_xyzuvw([traj.duration])[0], path.end.to_xyzuvw(), atol=1e-9)
    trapezoid = dispkin.plan(path, tool_sphere(), dispkin.Limits(0.1, 0.5), profile="trapezoid")
    assert trapezoid.duration < traj.duration  # no jerk limit: faster


def test_guarantee_on_a_circ_and_a_cornered_chain():
    points = dispkin.shapes.icosahedron(0.1)
    tool = dispkin.MetricSet()
    tool.add_relative(points)
    limits = dispkin.Limits(0.1, 1.0, 10.0)
    arc = dispkin.Path.circ(pose(0.3, 0, 0), pose(0, 0.3, 0, 0, 0, 30 * DEG), pose(-0.3, 0, 0, 0, 0, 90 * DEG))
    chain = dispkin.Path.lin(pose(0, 0, 0), pose(0.2, 0, 0, 0, 0, 40 * DEG)).then(
        dispkin.Path.lin(pose(0.2, 0, 0, 0, 0, 40 * DEG), pose(0.2, 0.2, 0, 20 * DEG, 0, 40 * DEG))
    )
    for path in (arc, chain):
        traj = dispkin.plan(path, tool, limits)
        assert max_point_speed_sampled(traj, points) <= 0.1 * (1 + 1e-6)
    assert dispkin.plan(chain, tool, limits).piece_count == 2


def test_sampling_does_not_depend_on_the_order_of_the_times():
    """Sampling arrays follows the previous sample (a cursor): any order gives the same values."""
    arc = dispkin.Path.circ(pose(0.3, 0, 0), pose(0, 0.3, 0, 0, 0, 30 * DEG), pose(-0.3, 0, 0, 0, 0, 90 * DEG))
    traj = dispkin.plan(arc, tool_sphere(), dispkin.Limits(0.1, 1.0, 10.0))
    times = np.concatenate([np.linspace(-0.1, 1.1, 2001), np.linspace(1.0, 0.0, 301)]) * traj.duration
    shuffled = np.random.default_rng(4).permutation(times)
    one_by_one = np.array([traj.sample([t])[0] for t in shuffled])
    np.testing.assert_array_equal(traj.sample(shuffled), one_by_one)
    order = np.argsort(shuffled, kind="stable")
    np.testing.assert_array_equal(traj.sample(shuffled[order]), one_by_one[order])
    np.testing.assert_array_equal(traj.sample_xyzuvw(times[::-1]), traj.sample_xyzuvw(times)[::-1])


def test_kdl_eqradius_timing_exceeds_the_limit_dispkin_never_does():
    """Same moves: KDL-style path length max(|dp|, eqradius * angle) lets tool-sphere points run
    faster than commanded; dispkin's plan never does."""
    rng = np.random.default_rng(7)
    eqradius, v = 0.1, 0.1
    points = dispkin.shapes.icosphere(eqradius, 2)
    tool = dispkin.MetricSet()
    tool.add_relative(points)
    kdl_worst, ours_worst = 0.0, 0.0
    for _ in range(20):
        d = rng.normal(size=3)
        d *= rng.uniform(0.02, 0.2) / np.linalg.norm(d)
        axis = rng.normal(size=3)
        angle = rng.uniform(0.2, 1.5)
        b = dispkin.Pose.exp(np.concatenate([np.zeros(3), axis / np.linalg.norm(axis) * angle]))
        b = dispkin.Pose(quaternion=b.quaternion, translation=d)
        path = dispkin.Path.lin(dispkin.Pose(), b)
        # KDL: constant path speed v along max(|dp|, eqradius * angle): each point's peak speed
        # is (exact section length) / (KDL length) * v.
        kdl_length = max(np.linalg.norm(d), eqradius * angle)
        exact = dispkin.section_length(tool, dispkin.Pose(), b, "decoupled")
        kdl_worst = max(kdl_worst, exact / kdl_length)
        traj = dispkin.plan(path, tool, dispkin.Limits(v, 1.0, 10.0))
        ours_worst = max(ours_worst, max_point_speed_sampled(traj, points, 4000) / v)
    assert kdl_worst > 1.2  # the conventional timing overshoots the commanded speed
    assert ours_worst <= 1 + 1e-6


@pytest.mark.parametrize(
    "call, message",
    [
        (lambda: dispkin.Limits(0.0, 1.0), r"^velocity = 0"),
        (lambda: dispkin.Limits(0.1, float("nan")), r"^acceleration = nan"),
        (lambda: dispkin.Limits(0.1, 1.0, -1.0), r"^jerk = -1"),
        (
            lambda: dispkin.plan(
                dispkin.Path.lin(pose(0, 0, 0), pose(1, 0, 0)), tool_sphere(), dispkin.Limits(0.1, 1.0)
            ),
            r"^jerk is missing",
        ),
        (
            lambda: dispkin.plan(
                dispkin.Path.lin(pose(0, 0, 0), pose(1, 0, 0)),
                tool_sphere(),
                dispkin.Limits(0.1, 1.0, 2.0),
                profile="trapezoid",
            ),
            r"^jerk = 2",
        ),
        (
            lambda: dispkin.plan(
                dispkin.Path.lin(pose(0, 0, 0), pose(1, 0, 0)),
                tool_sphere(),
                dispkin.Limits(0.1, 1.0, 2.0),
                profile="bang",
            ),
            r'^profile = "bang"',
        ),
    ],
)
def test_bad_input(call, message):
    with pytest.raises(ValueError, match=message):
        call()
