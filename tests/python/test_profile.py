"""Profiles against Ruckig (doc/planning.md §8 item 8), an independent time-optimal generator.

Ruckig (PyPI ``ruckig``, requirements-dev.txt) plans one degree of freedom from position 0 to S
with the same limits; ``max_jerk = inf`` gives its acceleration-limited (trapezoidal) law. Each
sweep runs DISPKIN_TEST_COUNT (default 10^4) seeded cases; one Ruckig call costs about 8 µs, so
the file runs in a few seconds. Durations must agree to 1e-9 relative.

Ruckig's own precision: it accepts a law whose end position is within p_precision = 1e-8
(absolute, include/ruckig/profile.hpp), velocity within 1e-8, acceleration within 1e-10. For
distances of micrometres that is up to 1 % of S, and its duration then belongs to a slightly
different problem. Where the durations differ by more than 1e-9 the test therefore requires that
Ruckig's law misses S by more than 1e-9 relative (measured with its own at_time): a faster
law that really reached S would prove ours not time-optimal and fails the test.
"""

import math

import numpy as np
import pytest

ruckig = pytest.importorskip("ruckig")

import dispkin  # noqa: E402
from _helpers import COUNT, rng_for  # noqa: E402

REL = 1e-9
INF = float("inf")


def log_uniform(rng, lo, hi, n):
    return 10.0 ** rng.uniform(math.log10(lo), math.log10(hi), n)


def random_limits(rng, n):
    """Distances 1e-6 ... 10, limits spanning three to five decades (as the C++ sweeps)."""
    return (
        log_uniform(rng, 1e-6, 10.0, n),
        log_uniform(rng, 1e-2, 10.0, n),
        log_uniform(rng, 1e-2, 100.0, n),
        log_uniform(rng, 1e-1, 1e4, n),
    )


class Ruckig1:
    """Ruckig, one degree of freedom, from (0, v_start, 0) to (S, v_end, 0)."""

    def __init__(self):
        self.otg = ruckig.Ruckig(1)
        self.trajectory = ruckig.Trajectory(1)

    def plan(self, S, v_max, a_max, j_max, v_start=0.0, v_end=0.0, min_velocity=None):
        inp = ruckig.InputParameter(1)
        inp.current_position = [0.0]
        inp.current_velocity = [v_start]
        inp.current_acceleration = [0.0]
        inp.target_position = [S]
        inp.target_velocity = [v_end]
        inp.target_acceleration = [0.0]
        inp.max_velocity = [v_max]
        inp.max_acceleration = [a_max]
        inp.max_jerk = [j_max]
        if min_velocity is not None:
            inp.min_velocity = [min_velocity]
        try:
            result = self.otg.calculate(inp, self.trajectory)
        except ruckig.RuckigError:  # no law exists under these limits
            return None
        return self.trajectory if result == ruckig.Result.Working else None

    def duration(self, *args, **kwargs):
        trajectory = self.plan(*args, **kwargs)
        return None if trajectory is None else trajectory.duration


def is_valid_law(profile, S, v_max, a_max, j_max, v_end):
    """Our law, checked here and not taken on trust: its last phase ends at (S, v_end) to 1e-9
    and 1001 samples keep 0 <= v <= v_max, |a| <= a_max, |jerk| <= j_max (1e-12 relative)."""
    duration, jerk, s, v, a = profile.phases[-1]
    end_s = s + duration * (v + duration * (a / 2 + jerk * duration / 6))
    end_v = v + duration * (a + jerk * duration / 2)
    x = profile.sample(np.linspace(0.0, profile.duration, 1001))
    tol = 1 + 1e-12
    return (
        abs(end_s - S) <= REL * S
        and abs(end_v - v_end) <= REL * v_max
        and x[:, 1].min() >= -1e-12 * v_max
        and x[:, 1].max() <= v_max * tol
        and np.abs(x[:, 2]).max() <= a_max * tol
        and np.abs(x[:, 3]).max() <= j_max * tol
    )


def agrees_with_ruckig(profile, trajectory, S, v_max, a_max, j_max, v_end=0.0):
    """Durations equal to 1e-9 relative. Otherwise the slower of the two laws must be explained:
    if ours is slower, Ruckig's faster law must miss S by more than 1e-9 relative (its duration
    answers another problem; see the module docstring); if Ruckig's is slower, ours must be a
    valid law (then Ruckig's is not time-optimal). Returns "equal", "ruckig imprecise" or
    "ruckig slower", or None when neither explanation holds."""
    ours, theirs = profile.duration, trajectory.duration
    if abs(ours - theirs) <= REL * theirs or (theirs == 0.0 and ours == 0.0):
        return "equal"
    if ours > theirs:
        reached = trajectory.at_time(theirs)[0][0]
        return "ruckig imprecise" if abs(reached - S) > REL * S else None
    return "ruckig slower" if is_valid_law(profile, S, v_max, a_max, j_max, v_end) else None


def test_ruckig_supports_infinite_jerk():
    # The trapezoid comparison relies on it: S = 1 at v = a = 1 takes S/v + v/a = 2 s.
    assert Ruckig1().duration(1.0, 1.0, 1.0, INF) == pytest.approx(2.0, rel=1e-15)


def test_scurve_rest_to_rest_matches_ruckig():
    rng = rng_for("scurve_rest_to_rest")
    r = Ruckig1()
    for S, v, a, j in zip(*(x.tolist() for x in random_limits(rng, COUNT))):
        ours = dispkin.Profile.scurve(S, v, a, j)
        assert agrees_with_ruckig(ours, r.plan(S, v, a, j), S, v, a, j) == "equal", (
            S,
            v,
            a,
            j,
            ours,
            r.duration(S, v, a, j),
        )


def test_trapezoid_rest_to_rest_matches_ruckig():
    rng = rng_for("trapezoid_rest_to_rest")
    r = Ruckig1()
    S, V, A, _ = (x.tolist() for x in random_limits(rng, COUNT))
    for s, v, a in zip(S, V, A):
        ours = dispkin.Profile.trapezoid(s, v, a)
        assert agrees_with_ruckig(ours, r.plan(s, v, a, INF), s, v, a, INF) == "equal", (
            s,
            v,
            a,
            ours,
            r.duration(s, v, a, INF),
        )


def boundary_cases(rng, n, kind):
    """Boundary velocities 0, v_max or between; in 7 cases of 8 S is raised by the distance of
    the direct change v_start -> v_end (textbook: at the mean velocity, for dv/a + a/j if
    dv >= a^2/j else 2 sqrt(dv/j); trapezoid: |v_e^2 - v_s^2| / 2a), so that most cases plan."""
    S, V, A, J = random_limits(rng, n)
    pick = rng.integers(0, 5, size=(2, n))  # 0: at rest, 1: at v_max, else anywhere between
    between = V * rng.uniform(0.0, 1.0, size=(2, n))
    v0, v1 = np.where(pick == 0, 0.0, np.where(pick == 1, V, between))
    dv = np.abs(v1 - v0)
    if kind == "scurve":
        change = np.where(dv >= A * A / J, dv / A + A / J, 2.0 * np.sqrt(dv / J)) * (v0 + v1) / 2
    else:
        change = np.abs(v1 * v1 - v0 * v0) / (2 * A)
    S = S + np.where(rng.integers(0, 8, n) > 0, change, 0.0)
    return S, V, A, J, v0, v1


@pytest.mark.parametrize("kind", ["scurve", "trapezoid"])
def test_boundary_velocities_match_ruckig(kind):
    """Non-zero boundary velocities, zero boundary accelerations. Ruckig's velocity may go
    negative (min_velocity = -v_max, its default): where we plan, it finds no faster law even so.
    Where we refuse (S too short for accelerate-cruise-decelerate), Ruckig without negative
    velocities either finds nothing or a law whose velocity dips below both boundary velocities:
    the structure we do not support (the trapezoid never has one)."""
    rng = rng_for("boundary_" + kind)
    r = Ruckig1()
    planned = refused = dips = retried = ruckig_failed = unequal = 0
    # COUNT + COUNT/4 cases, so that about COUNT of them plan (the others are refused).
    for S, v, a, j, v0, v1 in zip(*(x.tolist() for x in boundary_cases(rng, COUNT + COUNT // 4, kind))):
        jerk = j if kind == "scurve" else INF
        try:
            ours = (
                dispkin.Profile.scurve(S, v, a, j, v0, v1)
                if kind == "scurve"
                else dispkin.Profile.trapezoid(S, v, a, v0, v1)
            )
        except ValueError as e:
            assert "too short" in str(e)
            refused += 1
            trajectory = r.plan(S, v, a, jerk, v0, v1, min_velocity=0.0)
            if trajectory is not None:
                lowest = min(trajectory.at_time(t)[1][0] for t in np.linspace(0.0, trajectory.duration, 101))
                assert lowest < min(v0, v1), (S, v, a, jerk, v0, v1, lowest)
                dips += 1
            continue
        planned += 1
        trajectory = r.plan(S, v, a, jerk, v0, v1)
        if trajectory is None:
            # Ruckig 0.19 raises "error in step 1" for some cases with a boundary velocity at
            # exactly v_max, or S at the edge of the direct change. For v_max (1 + 1e-12) it
            # mostly succeeds, and that law is slower than the exact problem's by ~1e-12 relative;
            # the few left are counted, and must stay rare.
            retried += 1
            trajectory = r.plan(S, v * (1 + 1e-12), a, jerk, v0, v1)
            if trajectory is None:
                ruckig_failed += 1
                assert is_valid_law(ours, S, v, a, jerk, v1), (S, v, a, jerk, v0, v1)
                continue
        verdict = agrees_with_ruckig(ours, trajectory, S, v, a, jerk, v1)
        assert verdict is not None, (S, v, a, jerk, v0, v1, ours.duration, trajectory.duration)
        unequal += verdict != "equal"
    assert planned > COUNT * 9 // 10 and refused > 0
    # Ruckig's failures and imprecise or slower laws: each below 1 % of the cases.
    assert retried < planned // 100 and ruckig_failed < planned // 1000 + 2 and unequal < planned // 100
    if kind == "trapezoid":
        assert dips == 0


def test_velocity_dip_is_refused_though_ruckig_finds_one():
    # 0.01 -> 1 m/s at j = 1 needs S >= 1.00509 without a dip; at S = 1.003 Ruckig slows to
    # 0.0038 m/s first. We refuse such a law with a clear message instead of faking it.
    with pytest.raises(ValueError, match=r"^distance = 1.003: too short .* not supported"):
        dispkin.Profile.scurve(1.003, 10.0, 100.0, 1.0, 0.01, 1.0)
    trajectory = Ruckig1().plan(1.003, 10.0, 100.0, 1.0, 0.01, 1.0, min_velocity=0.0)
    lowest = min(trajectory.at_time(t)[1][0] for t in np.linspace(0.0, trajectory.duration, 1001))
    assert 0.0 <= lowest < 0.005


def test_sample_limits_and_end_state():
    p = dispkin.Profile.scurve(2.0, 1.0, 2.0, 5.0, 0.3, 0.1)
    t = np.linspace(-0.1, p.duration + 0.1, 2001)
    x = p.sample(t)
    assert x.shape == (2001, 4) and x.dtype == np.float64
    assert np.all(np.diff(x[:, 0]) >= 0.0)
    assert x[:, 1].max() <= 1.0 * (1 + 1e-12) and x[:, 1].min() >= 0.0
    assert np.abs(x[:, 2]).max() <= 2.0 * (1 + 1e-12) and np.abs(x[:, 3]).max() == 5.0
    assert tuple(x[0]) == (0.0, 0.3, 0.0, 0.0)
    assert tuple(x[-1]) == (2.0, 0.1, 0.0, 0.0)
    # s is the integral of v: trapezoidal rule on the dense samples.
    inside = (t >= 0) & (t <= p.duration)
    integral = np.sum(np.diff(t[inside]) * (x[inside][1:, 1] + x[inside][:-1, 1]) / 2)
    assert integral + x[inside][0, 0] == pytest.approx(x[inside][-1, 0], rel=1e-6)


def test_phases_and_repr():
    p = dispkin.Profile.scurve(10.0, 1.0, 0.5, 1.0)
    assert p.kind == "scurve" and len(p.phases) == 7
    assert [ph[1] for ph in p.phases] == [1.0, 0.0, -1.0, 0.0, -1.0, 0.0, 1.0]
    assert sum(ph[0] for ph in p.phases) == pytest.approx(p.duration, rel=1e-15)
    assert repr(p).startswith('Profile(kind="scurve", distance=10.0, duration=')
    t = dispkin.Profile.trapezoid(0.5, 1.0, 1.0)
    assert t.kind == "trapezoid" and [ph[4] for ph in t.phases] == [1.0, -1.0]
    assert dispkin.Profile.trapezoid(0.0, 1.0, 1.0).phases == []


@pytest.mark.parametrize(
    "call, match",
    [
        (lambda: dispkin.Profile.scurve(float("nan"), 1, 1, 1), r"^distance = nan: must be finite"),
        (lambda: dispkin.Profile.trapezoid(-1.0, 1, 1), r"^distance = -1: must be finite and not negative"),
        (lambda: dispkin.Profile.trapezoid(1.0, 0.0, 1), r"^v_max = 0: must be finite and greater than zero"),
        (lambda: dispkin.Profile.scurve(1.0, 1, INF, 1), r"^a_max = inf: "),
        (lambda: dispkin.Profile.scurve(1.0, 1, 1, -1), r"^j_max = -1: "),
        (
            lambda: dispkin.Profile.scurve(1.0, 1, 1, 1, v_start=2.0),
            r"^v_start = 2: must be finite and within \[0, v_max = 1\]",
        ),
        (lambda: dispkin.Profile.trapezoid(1.0, 1, 1, v_end=-0.5), r"^v_end = -0.5: "),
        (lambda: dispkin.Profile.trapezoid(0.1, 1, 1, 1.0, 0.0), r"^distance = 0.1: too short"),
        (
            lambda: dispkin.Profile.scurve(1.0, 1, 1, 1).sample([[0.0, 1.0]]),
            r"^times: expected an array of shape \(N,\), got shape \(1, 2\)",
        ),
        (
            lambda: dispkin.Profile.scurve(1.0, 1, 1, 1).sample([0.0, float("nan")]),
            r"^times\[1\] = nan: must be finite",
        ),
    ],
)
def test_bad_input(call, match):
    with pytest.raises(ValueError, match=match):
        call()
