"""Events on a planned trajectory from Python (doc/events.md): a stop on the path whose duration is
Ruckig's time-optimal 1-DoF braking from the same path velocity and acceleration, a resumption, a
speed override; the motion before each event unchanged bit for bit, pickles of the results, and
the refusals."""

import math
import pickle

import numpy as np
import pytest

import dispkin
from _helpers import rng_for

ruckig = pytest.importorskip("ruckig")

DEG = math.pi / 180


def pose(x, y, z, u=0.0, v=0.0, w=0.0):
    return dispkin.Pose.from_xyzuvw([x, y, z, u, v, w])


def tool():
    tool = dispkin.MetricSet()
    tool.add_relative(dispkin.shapes.icosphere(0.15, 2))
    return tool


def paths():
    """A LIN, a CIRC, a cornered chain and a blended pose list: stops inside laws of every kind."""
    chain = dispkin.Path.lin(pose(0, 0, 0), pose(0.3, 0, 0, 0, 0, 40 * DEG)).then(
        dispkin.Path.lin(pose(0.3, 0, 0, 0, 0, 40 * DEG), pose(0.3, 0.25, 0.1, 20 * DEG, 0, 40 * DEG))
    )
    poses = [pose(0.1 * k, 0.05 * (k % 2), 0.0, 0.0, 0.0, 5 * DEG * k) for k in range(8)]
    blended = dispkin.Path.lin(poses[0], poses[1])
    for p, q in zip(poses[1:], poses[2:]):
        blended = blended.then(dispkin.Path.lin(p, q))
    return [
        ("lin", dispkin.Path.lin(pose(0, 0, 0), pose(0.5, 0.2, 0, 0, 0, 60 * DEG)), 0.0),
        (
            "circ",
            dispkin.Path.circ(pose(0, 0, 0), pose(0.2, 0.2, 0, 0, 0, 15 * DEG), pose(0.4, 0, 0, 0, 0, 30 * DEG)),
            0.0,
        ),
        ("chain", chain, 0.0),
        ("blended chain", blended, 0.01),
    ]


def plans():
    for name, path, tolerance in paths():
        for profile, limits in (("scurve", dispkin.Limits(0.4, 2.0, 15.0)), ("trapezoid", dispkin.Limits(0.4, 2.0))):
            yield (
                name + " " + profile,
                path,
                profile,
                dispkin.plan(path, tool(), limits, profile, corner_tolerance=tolerance),
            )


PLANS = list(plans())


def ruckig_braking_time(v0, a0, a_max, j_max):
    """Ruckig's time-optimal 1-DoF change of velocity to rest (velocity interface, target a = 0)."""
    otg = ruckig.Ruckig(1)
    inp = ruckig.InputParameter(1)
    inp.control_interface = ruckig.ControlInterface.Velocity
    inp.current_position = [0.0]
    inp.current_velocity = [v0]
    inp.current_acceleration = [a0]
    inp.target_velocity = [0.0]
    inp.target_acceleration = [0.0]
    inp.max_velocity = [1e3]
    inp.max_acceleration = [a_max]
    inp.max_jerk = [j_max]
    trajectory = ruckig.Trajectory(1)
    assert otg.calculate(inp, trajectory) == ruckig.Result.Working
    return trajectory.duration


@pytest.mark.parametrize("name, path, profile, traj", PLANS, ids=[p[0] for p in PLANS])
def test_a_stop_brakes_as_fast_as_ruckig_and_keeps_the_motion_before_it(name, path, profile, traj):
    rng = rng_for("stop " + name)
    a_max, jerk = traj.time_law_limits
    assert (jerk is None) == (profile == "trapezoid")
    for t in rng.uniform(0.0, traj.duration, 12):
        stopped = traj.stopped_at(t)
        v0, a0 = float(traj.path_velocity(t)), float(traj.path_acceleration(t))
        if jerk is None:
            expected = v0 / a_max  # a is no state of the trapezoid: decelerate at a_max
        elif v0 < 1e-12:
            expected = abs(a0) / jerk
        else:
            expected = ruckig_braking_time(v0, a0, a_max, jerk)
        assert stopped.duration - t == pytest.approx(expected, rel=1e-9, abs=1e-12 * traj.duration)
        before = np.linspace(0.0, t, 200, endpoint=False)
        assert np.array_equal(stopped.sample(before), traj.sample(before))
        assert np.array_equal(stopped.path_velocity(before), traj.path_velocity(before))
        # At rest on the path, the path's pose there.
        end = stopped.end_position
        assert stopped.stopped == (end < traj.length)
        assert abs(float(stopped.path_velocity(stopped.duration))) <= 1e-12
        assert float(stopped.path_position(stopped.duration)) == end
        # Never faster than as planned, and the path acceleration within its limit.
        times = np.linspace(t, stopped.duration, 2000)
        assert np.all(np.abs(stopped.path_acceleration(times)) <= a_max * (1 + 1e-9))
        assert np.all(stopped.path_velocity(times) >= -1e-12)


@pytest.mark.parametrize("name, path, profile, traj", PLANS, ids=[p[0] for p in PLANS])
def test_a_stopped_motion_resumes_to_the_end(name, path, profile, traj):
    rng = rng_for("resume " + name)
    for t in rng.uniform(0.0, traj.duration, 6):
        stopped = traj.stopped_at(t)
        if not stopped.stopped:
            continue
        wait = stopped.duration + float(rng.uniform(0.0, 0.5))
        resumed = stopped.resumed_at(wait)
        assert not resumed.stopped
        before = np.linspace(0.0, wait, 200, endpoint=False)
        assert np.array_equal(resumed.sample(before), stopped.sample(before))
        assert np.allclose(resumed.sample(resumed.duration), path.end.matrix(), atol=1e-9)
        # Waiting at rest costs its wait and the extra stop and start, never less than the plan.
        assert resumed.duration >= traj.duration


def test_an_override_scales_the_speed_and_above_one_reaches_the_moves_own_velocity():
    # The second move is programmed at 0.1 m/s under a system velocity of 0.4 m/s.
    a, b, c = pose(0, 0, 0), pose(0.4, 0, 0), pose(0.8, 0, 0)
    path = dispkin.Path.lin(a, b).then(dispkin.Path.lin(b, c, velocity=0.1))
    traj = dispkin.plan(path, tool(), dispkin.Limits(0.4, 2.0, 15.0), corner_tolerance=0.001)
    t = traj.duration * 0.6  # inside the slow move
    half = traj.with_override(t, 0.5)
    double = traj.with_override(t, 2.0)
    assert half.override_factor == 0.5 and double.override_factor == 2.0
    assert double.duration < traj.duration < half.duration
    late = np.linspace(t + 1.0, double.duration - 1.0, 200)
    assert np.max(double.path_velocity(late)) == pytest.approx(0.2, rel=1e-9)
    assert np.max(half.path_velocity(np.linspace(t + 1.0, half.duration - 2.0, 200))) == pytest.approx(0.05, rel=1e-9)
    # Overrides compose: a later one replaces the factor, the motion before it stays.
    back = half.with_override(t + 2.0, 1.0)
    before = np.linspace(0.0, t + 2.0, 300, endpoint=False)
    assert np.array_equal(back.sample(before), half.sample(before))
    assert back.override_factor == 1.0


@pytest.mark.parametrize("name, path, profile, traj", PLANS[:4], ids=[p[0] for p in PLANS[:4]])
def test_events_survive_a_pickle_bit_for_bit(name, path, profile, traj):
    event = traj.with_override(0.3 * traj.duration, 0.7).stopped_at(0.6 * traj.duration)
    copy = pickle.loads(pickle.dumps(event))
    times = np.linspace(0.0, event.duration, 500)
    assert np.array_equal(copy.sample(times), event.sample(times))
    assert copy.stopped == event.stopped and copy.override_factor == 0.7
    assert copy.time_law_limits == event.time_law_limits
    if event.stopped:
        resumed, again = event.resumed_at(event.duration + 0.1), copy.resumed_at(event.duration + 0.1)
        assert np.array_equal(resumed.sample(times), again.sample(times))


def test_an_older_state_loads_without_limits_and_refuses_events():
    # A translation: its LIN is not cut.
    a, b = dispkin.Pose.from_xyzuvw([0, 0, 0, 0, 0, 0]), dispkin.Pose.from_xyzuvw([0.3, 0.1, 0, 0, 0, 0])
    traj = dispkin.plan(dispkin.Path.lin(a, b), tool(), dispkin.Limits(0.4, 2.0, 15.0))
    state = traj.__getstate__()
    # A plan whose sections are its path's own, whole (its parts one to one): items 0–6 are the
    # state from before the events.
    assert len(state) == 10 and state[9] == tuple((k, 0.0, 1.0) for k in range(len(state[0])))
    older = dispkin.Trajectory.__new__(dispkin.Trajectory)
    older.__setstate__(state[:3] + (tuple(span[:3] for span in state[3]),) + state[4:7])
    assert older.time_law_limits is None and older.override_factor == 1.0
    with pytest.raises(ValueError, match="holds no time-law limits"):
        older.stopped_at(0.1)


@pytest.mark.parametrize(
    "call, message",
    [
        (lambda t: t.with_override(0.1, 0.0), r"^factor = 0: must be in \[0\.001, 10\]"),
        (lambda t: t.with_override(0.1, math.inf), r"^factor = inf"),
        (lambda t: t.stopped_at(math.nan), r"^t = nan: must be finite"),
        (lambda t: t.resumed_at(0.1), r"^t = 0\.1: resumes a stopped trajectory only"),
    ],
)
def test_bad_events_are_refused_naming_the_argument(call, message):
    with pytest.raises(ValueError, match=message):
        call(PLANS[0][3])


def ruckig_position_time(distance, v0, a0, v_max, a_max, j_max):
    """Ruckig's time-optimal 1-DoF motion from (0, v0, a0) to rest at `distance` (position interface)."""
    otg = ruckig.Ruckig(1)
    inp = ruckig.InputParameter(1)
    inp.current_position = [0.0]
    inp.current_velocity = [v0]
    inp.current_acceleration = [a0]
    inp.target_position = [distance]
    inp.target_velocity = [0.0]
    inp.target_acceleration = [0.0]
    inp.max_velocity = [v_max]
    inp.max_acceleration = [a_max]
    inp.max_jerk = [j_max]
    trajectory = ruckig.Trajectory(1)
    assert otg.calculate(inp, trajectory) == ruckig.Result.Working
    return trajectory.duration


def test_a_plan_from_a_moving_state_is_ruckigs_law_along_a_straight_move():
    """plan(..., start_velocity=, start_acceleration=) along a translation under one limit: the
    1-DoF time-optimal law from that state, as long as Ruckig's to 1e-9 (doc/events.md section 3)."""
    points = dispkin.MetricSet()
    for p in ([0.0, 0.0, 0.0], [0.1, 0.0, 0.0], [0.0, 0.1, 0.0]):
        points.add_relative(p)
    path = dispkin.Path.lin(pose(0, 0, 0), pose(0.6, 0.3, 0.0))
    limits = dispkin.Limits(0.4, 2.0, 15.0)
    rng = rng_for("plan from a moving state")
    for _ in range(40):
        v0 = rng.uniform(0.0, 0.4)
        a0 = rng.uniform(-2.0, 2.0)
        if a0 < 0 and a0 * a0 / (2 * 15.0) > v0:
            continue  # below the release curve: refused (tested below)
        traj = dispkin.plan(path, points, limits, start_velocity=v0, start_acceleration=a0)
        assert traj.path_velocity(0.0) == pytest.approx(v0, abs=1e-12)
        assert traj.path_acceleration(0.0) == pytest.approx(a0, abs=1e-12)
        expected = ruckig_position_time(traj.length, v0, a0, 0.4, 2.0, 15.0)
        assert traj.duration == pytest.approx(expected, rel=1e-9), (v0, a0)
    with pytest.raises(ValueError, match="start_velocity = 0.5: must be at most the velocity limit"):
        dispkin.plan(path, points, limits, start_velocity=0.5)
    with pytest.raises(ValueError, match="start_acceleration = -2: brakes harder than the jerk limit"):
        dispkin.plan(path, points, limits, start_velocity=0.01, start_acceleration=-2.0)
    rest = dispkin.plan(path, points, limits)
    assert (
        rest.starting_from(0.2, 1.0).duration
        == dispkin.plan(path, points, limits, start_velocity=0.2, start_acceleration=1.0).duration
    )
