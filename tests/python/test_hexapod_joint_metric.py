"""Leg-speed rule (b), the joint-space metric, from Python: hx.leg_section_lengths and
dispkin.plan(..., joint_metric=hx) keep every leg within its speed; any object with the method
works; the bound is tight enough that a leg reaches its limit."""

import math

import numpy as np
import pytest

import dispkin
from _helpers import rng_for


def desktop():
    return dispkin.Hexapod.symmetric(0.15, math.radians(20), 0.10, math.radians(20), 0.20, 0.15, 0.32, 0.01)


def tool_points():
    s = dispkin.MetricSet()
    s.add_relative([[0.0, 0.0, 0.05], [0.02, 0.0, 0.05], [0.0, 0.02, 0.05]])
    return s


def reachable(h, rng):
    while True:
        twist = np.concatenate([rng.uniform(-0.04, 0.04, 3), rng.uniform(-0.2, 0.2, 3)])
        pose = h.home * dispkin.Pose.exp(twist)
        if h.check(pose).reachable:
            return pose


LIMITS = dispkin.Limits(0.1, 1.0, 20.0)  # system velocity 10x the leg speed


def test_section_lengths_are_the_rate_bounds_over_the_leg_speeds():
    h = desktop()
    rng = rng_for("joint metric lengths")
    path = dispkin.Path.lin(reachable(h, rng), reachable(h, rng))
    rates = h.leg_rate_bounds(path)
    assert rates.shape == (1, 6)
    lengths = h.leg_section_lengths(path, 0.1)
    assert lengths.shape == (1,)
    assert lengths[0] == pytest.approx(0.1 * np.max(rates[0] / h.leg_speed), rel=1e-15)
    # The bound is at least the leg rate sampled densely (finite differences of the leg lengths).
    u = np.linspace(0.0, 1.0, 20001)
    legs = np.array([h.inverse(path.sample(x)) for x in u])
    sampled = np.max(np.abs(np.diff(legs, axis=0)) / np.diff(u)[:, None], axis=0)
    assert np.all(rates[0] >= sampled * (1 - 1e-6))
    assert np.all(rates[0] <= sampled + 2e-3 * np.max(sampled / h.leg_speed) * h.leg_speed)


def test_planned_with_the_joint_metric_no_leg_is_too_fast():
    h = desktop()
    rng = rng_for("joint metric plan")
    for _ in range(10):
        path = dispkin.Path.lin(reachable(h, rng), reachable(h, rng))
        traj = dispkin.plan(path, tool_points(), LIMITS, joint_metric=h)
        check = h.check(traj, dt=traj.duration / 5000)
        assert check.ok, check.excursions
        assert np.all(check.max_speed <= h.leg_speed * (1 + 1e-9))
        assert np.all(traj.section_lengths() >= h.leg_section_lengths(path, LIMITS.velocity))


def test_leg_speed_dominated_move_reaches_the_limit():
    h = desktop()
    a = dispkin.Pose.from_xyzuvw([-0.011, 0.021, 0.162, -0.032, -0.077, -0.014])
    b = dispkin.Pose.from_xyzuvw([-0.030, -0.022, 0.205, -0.067, 0.175, 0.063])
    traj = dispkin.plan(dispkin.Path.lin(a, b), tool_points(), LIMITS, joint_metric=h)
    ratio = np.max(h.check(traj, dt=traj.duration / 20000).max_speed / h.leg_speed)
    assert 0.99 <= ratio <= 1 + 1e-9


def test_any_object_with_the_method_is_a_joint_metric():
    h = desktop()
    rng = rng_for("joint metric duck")
    path = dispkin.Path.lin(reachable(h, rng), reachable(h, rng))

    class Twice:
        def leg_section_lengths(self, path, system_velocity):
            return 2 * h.leg_section_lengths(path, system_velocity)

    once = dispkin.plan(path, tool_points(), LIMITS, joint_metric=h)
    twice = dispkin.plan(path, tool_points(), LIMITS, joint_metric=Twice())
    np.testing.assert_allclose(twice.section_lengths(), 2 * once.section_lengths(), rtol=1e-15)
    assert twice.duration > once.duration


def test_bad_joint_metrics_are_refused():
    h = desktop()
    path = dispkin.Path.lin(h.home, h.home * dispkin.Pose.exp([0, 0, 0.01, 0, 0, 0]))

    class Wrong:
        def __init__(self, value):
            self.value = value

        def leg_section_lengths(self, path, system_velocity):
            return self.value

    with pytest.raises(ValueError, match="joint_metric = .*must have a method leg_section_lengths"):
        dispkin.plan(path, tool_points(), LIMITS, joint_metric=42)
    with pytest.raises(ValueError, match=r"joint_metric\(path, limits\) size = 2"):
        dispkin.plan(path, tool_points(), LIMITS, joint_metric=Wrong([0.1, 0.2]))
    with pytest.raises(ValueError, match=r"joint_metric\(path, limits\)\[0\] = -1"):
        dispkin.plan(path, tool_points(), LIMITS, joint_metric=Wrong([-1.0]))
    with pytest.raises(ValueError, match=r"expected an array of shape \(1,\), got shape \(1, 1\)"):
        dispkin.plan(path, tool_points(), LIMITS, joint_metric=Wrong([[0.1]]))
    with pytest.raises(ValueError, match="system_velocity = 0"):
        h.leg_section_lengths(path, 0.0)
    with pytest.raises(ValueError, match="tolerance = 0"):
        h.leg_rate_bounds(path, 0.0)
    with pytest.raises(TypeError):
        dispkin.plan(path, tool_points(), LIMITS, "scurve", h)  # keyword only


def test_circ_runs_through_without_stopping():
    h = desktop()
    shifted = lambda x, y: h.home * dispkin.Pose.exp([x, y, 0.0, 0.0, 0.0, 0.05])  # noqa: E731
    arc = dispkin.Path.circ(shifted(0.02, 0.0), shifted(0.0, 0.02), shifted(-0.02, 0.0), tolerance=0.01)
    traj = dispkin.plan(arc, tool_points(), LIMITS, joint_metric=h)
    assert traj.piece_count == 1
    assert np.all(traj.section_lengths() >= h.leg_section_lengths(arc, LIMITS.velocity))
    assert h.check(traj, dt=traj.duration / 20000).ok


def test_with_blended_corners_the_joint_metric_is_that_of_the_blended_path():
    # A right-angle corner (blended) and a reversal (not blendable): plan blends, then measures the
    # legs along the blended path; the corner left stops for the blend's reason.
    h = desktop()
    shifted = lambda x, y: h.home * dispkin.Pose.exp([x, y, 0.0, 0.0, 0.0, 0.0])  # noqa: E731
    path = dispkin.Path.lin(shifted(0.0, 0.0), shifted(0.02, 0.0))
    path.then(dispkin.Path.lin(shifted(0.02, 0.0), shifted(0.02, 0.02)))
    path.then(dispkin.Path.lin(shifted(0.02, 0.02), shifted(0.02, 0.0)))
    traj = dispkin.plan(path, tool_points(), LIMITS, joint_metric=h, corner_tolerance=0.005)
    blended, _ = path.blended(0.005)
    reference = dispkin.plan(blended, tool_points(), LIMITS, joint_metric=h)
    assert traj.duration == reference.duration
    assert np.array_equal(traj.section_lengths(), reference.section_lengths())
    assert len(traj.stops) == 1
    assert "reverses" in traj.stops[0][1]
    assert h.check(traj, dt=traj.duration / 20000).ok


def test_retime_blends_the_corners_as_plan_does():
    # retime(..., corner_tolerance=d) re-times the path plan() would run along: the blended one.
    h = desktop()
    shifted = lambda x, y: h.home * dispkin.Pose.exp([x, y, 0.0, 0.0, 0.0, 0.0])  # noqa: E731
    path = dispkin.Path.lin(shifted(0.0, 0.0), shifted(0.02, 0.0))
    path.then(dispkin.Path.lin(shifted(0.02, 0.0), shifted(0.02, 0.02)))
    limits = dispkin.Limits(0.1, 1.0)
    blended, _ = path.blended(0.005)
    once = dispkin.retime(path, tool_points(), limits, h, corner_tolerance=0.005, grid_intervals=20)
    reference = dispkin.retime(blended, tool_points(), limits, h, grid_intervals=20)
    assert once.trajectory.duration == reference.trajectory.duration
    assert once.trajectory.piece_count == 1
    assert np.array_equal(once.trajectory.section_lengths(), reference.trajectory.section_lengths())
    with pytest.raises(ValueError, match="corner_tolerance = -1"):
        dispkin.retime(path, tool_points(), limits, h, corner_tolerance=-1.0)
