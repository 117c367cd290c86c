"""Profile.from_state against Ruckig, and the invariants of a law from a state (doc/profiles.md §7).

Ruckig (PyPI ``ruckig``) plans one degree of freedom from (0, v_start, a_start) to (S, v_end, 0)
with the same limits and ``min_velocity = 0`` (dispkin's laws never run backwards). For states
inside the limits (|a_start| <= a_max, v_start + a_start|a_start|/(2 j) <= v_max) both are
time-optimal and the durations must agree to 1e-9 relative. Where they do not, the slower of the
two must be explained, as in test_profile.py: Ruckig's law misses S by more than 1e-9 relative
(its position tolerance is 1e-8 absolute), or Ruckig's law is the slower one and ours is checked
valid here by an independent integration of its phases. Such cases must stay rare.

The cases are drawn in strata, each covering one part of the maths: near-zero distances (just
above the shortest law), dips (a small and a large end velocity, a little above it), v_end = v_max, a_start = +-a_max, an a_start that must be cut at once
(v_n = v_max), long distances with a cruise, and the relaxed family (S between the direct pulse
and the pulse through v_n). COUNT cases per stratum (DISPKIN_TEST_COUNT, default 10^4): about
15 s for the file. A run of 10^6 states is reported in benchmarks/RESULTS.md.

Beyond the limits Ruckig first brakes hard into them; dispkin eases onto them. There our law must
never be slower than Ruckig's, and never run backwards. (Ruckig's brake holds its deceleration a
hair inside -a_max, a few 1e-9 relative, so its velocity stays above ours while both fall to v_max:
where its law is faster by more than 1e-9, that must be the reason, and the gap below 5e-8;
2e-8 is the largest seen in 6·10^5 states.)
"""

import math
import pickle

import numpy as np
import pytest
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

import dispkin
from _helpers import COUNT, rng_for

ruckig = pytest.importorskip("ruckig")

REL = 1e-9


def natural(v, a, j):
    """(16) The velocity at which a, brought to zero at full jerk, is zero."""
    return v + a * abs(a) / (2.0 * j)


class Ruckig1:
    def __init__(self):
        self.otg = ruckig.Ruckig(1)
        self.trajectory = ruckig.Trajectory(1)

    def plan(self, S, v_max, a_max, j_max, v0, a0, v1):
        inp = ruckig.InputParameter(1)
        inp.current_position = [0.0]
        inp.current_velocity = [v0]
        inp.current_acceleration = [a0]
        inp.target_position = [S]
        inp.target_velocity = [v1]
        inp.target_acceleration = [0.0]
        inp.max_velocity = [v_max]
        inp.min_velocity = [0.0]
        inp.max_acceleration = [a_max]
        inp.max_jerk = [j_max]
        try:
            result = self.otg.calculate(inp, self.trajectory)
        except ruckig.RuckigError:
            return None
        return self.trajectory if result == ruckig.Result.Working else None


def integrated_end(profile, v0, a0):
    """The end state of the phases' durations and jerks integrated from (0, v0, a0), in Python
    floats, independent of the states the law stores; and the lowest and highest velocity."""
    s, v, a = 0.0, v0, a0
    lowest, highest = v0, v0
    for duration, jerk, *_ in profile.phases:
        if jerk != 0.0 and 0.0 < -a / jerk < duration:
            t = -a / jerk
            extreme = v + a * t + jerk * t * t / 2
            lowest, highest = min(lowest, extreme), max(highest, extreme)
        s += duration * (v + duration * (a / 2 + jerk * duration / 6))
        v += duration * (a + jerk * duration / 2)
        a += jerk * duration
        lowest, highest = min(lowest, v), max(highest, v)
    return s, v, a, lowest, highest


def is_valid_law(profile, S, v_max, a_max, j_max, v0, a0, v1):
    """Ours, checked and not taken on trust: the phases integrated from the start state end at
    (S, v1, 0), and 0 <= v <= v_max, |a| <= a_max, |jerk| <= j_max at every phase's extremes."""
    s, v, a, lowest, highest = integrated_end(profile, v0, a0)
    scale = v_max + a_max * profile.duration
    ok_end = (
        abs(s - S) <= REL * (S + scale * profile.duration)
        and abs(v - v1) <= REL * scale
        and abs(a) <= REL * (a_max + j_max * profile.duration)
    )
    accelerations = [abs(p[4]) for p in profile.phases]
    return (
        ok_end
        and lowest >= -1e-12 * scale
        and highest <= v_max * (1 + 1e-12)
        and max(accelerations, default=0.0) <= a_max * (1 + 1e-12)
        and max((abs(p[1]) for p in profile.phases), default=0.0) <= j_max * (1 + 1e-12)
    )


def verdict(profile, trajectory, S, v_max, a_max, j_max, v0, a0, v1):
    ours, theirs = profile.duration, trajectory.duration
    if abs(ours - theirs) <= REL * theirs:
        return "equal"
    if ours > theirs:
        reached = trajectory.at_time(theirs)[0][0]
        return "ruckig imprecise" if abs(reached - S) > REL * S else None
    return "ruckig slower" if is_valid_law(profile, S, v_max, a_max, j_max, v0, a0, v1) else None


def log_uniform(rng, lo, hi):
    return 10.0 ** rng.uniform(math.log10(lo), math.log10(hi))


def needed(message):
    """The distance a too-short message names ("it needs at least X, Y more")."""
    return float(message.split("it needs at least ")[1].split(",")[0])


def inside_state(rng, stratum):
    """One state inside the limits for a stratum, as (v_max, a_max, j_max, v0, a0, v1, S)."""
    while True:
        v_max, a_max, j_max = log_uniform(rng, 1e-2, 10), log_uniform(rng, 1e-2, 100), log_uniform(rng, 1e-1, 1e4)
        v0, a0, v1 = v_max * rng.uniform(), a_max * rng.uniform(-1, 1), v_max * rng.uniform()
        S = log_uniform(rng, 1e-6, 10)
        if stratum == "v_end = v_max":
            v1 = v_max
        elif stratum == "a_start = +-a_max":
            a0 = a_max * rng.choice([-1.0, 1.0])
        elif stratum == "cut at once":
            # v_n = v_max to 1e-12 (inside, so that Ruckig does not see a state beyond it)
            a0 = abs(a0)
            v0 = (v_max - a0 * a0 / (2 * j_max)) * (1 - 1e-12)
        elif stratum == "cruise":
            S = log_uniform(rng, 10, 1e4) * v_max
        elif stratum == "dip":
            # A small velocity and a large one: the laws that dip (stop first) live here.
            low, high = v_max * rng.uniform(0, 0.05), v_max * rng.uniform(0.5, 1)
            v0, v1 = (low, high) if rng.uniform() < 0.5 else (high, low)
            a0 = a_max * rng.uniform(-0.1, 0.1)
        if v0 >= 0 and natural(v0, a0, j_max) <= v_max and natural(v0, min(a0, 0), j_max) >= 0:
            return v_max, a_max, j_max, v0, a0, v1, S


STRATA = [
    "anywhere",
    "near-zero distance",
    "dip",
    "v_end = v_max",
    "a_start = +-a_max",
    "cut at once",
    "cruise",
    "relaxed",
]


def plan_stratum(rng, stratum):
    """A state of the stratum and our law for it. "near-zero distance": S just above the
    shortest law (1 + 1e-9 ... 1e-3); "dip": a small and a large end velocity, S 1e-5 ... 0.1
    above the shortest law; "relaxed": a_start and v_end on the sides where the relaxed family
    exists, S 1e-4 ... 1 above the shortest law (log-uniform)."""
    while True:
        v_max, a_max, j_max, v0, a0, v1, S = inside_state(rng, stratum)
        if stratum == "relaxed":
            v_n = natural(v0, a0, j_max)
            if not ((a0 < 0 and v1 < v_n) or (a0 > 0 and v1 > v_n)) or abs(a0) < 0.2 * a_max:
                continue
        try:
            law = dispkin.Profile.from_state(S, v_max, a_max, j_max, v0, a0, v1)
            if stratum not in ("near-zero distance", "dip", "relaxed"):
                return (S, v_max, a_max, j_max, v0, a0, v1), law
        except ValueError:
            if stratum not in ("near-zero distance", "dip", "relaxed"):
                continue
        shortest = needed(str(_too_short(v_max, a_max, j_max, v0, a0, v1)))
        lowest = {"near-zero distance": 1e-9, "dip": 1e-5, "relaxed": 1e-4}[stratum]
        highest = {"near-zero distance": 1e-3, "dip": 1e-1, "relaxed": 1.0}[stratum]
        scale = 1e-9 + log_uniform(rng, lowest, highest)
        S = shortest * (1 + scale)
        return (S, v_max, a_max, j_max, v0, a0, v1), dispkin.Profile.from_state(S, v_max, a_max, j_max, v0, a0, v1)


def _too_short(v_max, a_max, j_max, v0, a0, v1):
    with pytest.raises(ValueError, match="too short") as e:
        dispkin.Profile.from_state(0.0, v_max, a_max, j_max, v0, a0, v1)
    return e.value


def family(law, v0, a0, v1, j_max):
    """Which family of doc/profiles.md §7 a law (inside the limits) belongs to, from its phases:
    "cruise" (a peak law at v_max), "trough" (its velocity dips below both ends, §7.5),
    "relaxed" (a_start != 0 turned back towards zero but not to it, then pushed again: the
    acceleration keeps the sign of a_start, §7.4), else "peak" (§7.3)."""
    phases = law.phases
    if any(jerk == 0.0 and a == 0.0 and d > 0.0 for d, jerk, _, _, a in phases):
        return "cruise"
    lowest = integrated_end(law, v0, a0)[3]
    floor = min(natural(v0, min(a0, 0.0), j_max), v1)
    if lowest < floor - 1e-9 * max(v0, v1, 1e-300):
        return "trough"
    accelerations = [a for *_, a in phases][1:]
    if a0 != 0.0 and len(phases) >= 2 and all(a * a0 > 0.0 for a in accelerations) and phases[0][1] * a0 < 0.0:
        return "relaxed"
    return "peak"


@pytest.mark.parametrize("stratum", STRATA)
def test_inside_the_limits_matches_ruckig(stratum):
    rng = rng_for("from_state " + stratum)
    r = Ruckig1()
    n = max(COUNT, 50)
    verdicts = {"equal": 0, "ruckig imprecise": 0, "ruckig slower": 0, "ruckig failed": 0}
    families = {"cruise": 0, "peak": 0, "relaxed": 0, "trough": 0}
    for _ in range(n):
        case, law = plan_stratum(rng, stratum)
        families[family(law, *case[4:], case[3])] += 1
        trajectory = r.plan(*case)
        if trajectory is None:
            verdicts["ruckig failed"] += 1
            assert is_valid_law(law, *case), case
            continue
        v = verdict(law, trajectory, *case)
        assert v is not None, (case, law.duration, trajectory.duration)
        verdicts[v] += 1
    print(f"from_state vs Ruckig, {stratum}: {n} states, {verdicts}, families {families}")  # pytest -s
    # Ruckig's failures, imprecise and slower laws together below 1 % of the cases.
    assert verdicts["equal"] >= 0.99 * n, verdicts
    # The strata reach the families they are for.
    wanted = {
        "cruise": ("cruise", 0.9),
        "dip": ("trough", 0.1),
        "relaxed": ("relaxed", 0.15),
        "anywhere": ("peak", 0.2),
    }
    if stratum in wanted:
        name, share = wanted[stratum]
        assert families[name] >= share * n, families


def test_refused_distances_have_no_law():
    """Where dispkin refuses a distance as too short (0.1 % below the shortest law, the
    stop-and-go law of the dips when there is one), Ruckig finds no law either, except where the
    shortfall is below Ruckig's position tolerance (1e-8 absolute)."""
    rng = rng_for("from_state refused")
    r = Ruckig1()
    refused = 0
    for _ in range(max(COUNT // 10, 50)):
        v_max, a_max, j_max, v0, a0, v1, _ = inside_state(rng, "anywhere")
        shortest = needed(str(_too_short(v_max, a_max, j_max, v0, a0, v1)))
        S = shortest * (1 - 1e-3)
        trajectory = r.plan(S, v_max, a_max, j_max, v0, a0, v1)
        assert trajectory is None or shortest - S < 1e-8, (S, v_max, a_max, j_max, v0, a0, v1)
        refused += 1
    assert refused > 0


def test_beyond_the_limits_never_slower_than_ruckig():
    rng = rng_for("from_state beyond")
    r = Ruckig1()
    faster = compared = slower = 0
    for _ in range(max(COUNT // 4, 50)):
        v_max, a_max, j_max = log_uniform(rng, 1e-2, 10), log_uniform(rng, 1e-2, 100), log_uniform(rng, 1e-1, 1e4)
        v0, a0, v1 = v_max * rng.uniform(), a_max * rng.uniform(-1, 1), v_max * rng.uniform()
        kind = rng.integers(3)
        if kind == 0:
            v0 = v_max * rng.uniform(1, 3)
        elif kind == 1:
            a0 = a_max * rng.uniform(1, 3) * rng.choice([-1.0, 1.0])
        else:
            a0 = abs(a0)
            v0 = max(0.0, v_max - a0 * a0 / j_max * rng.uniform(0, 0.5))
        if natural(v0, min(a0, 0), j_max) < 0:
            continue
        try:
            law = dispkin.Profile.from_state(log_uniform(rng, 1e-6, 10), v_max, a_max, j_max, v0, a0, v1)
            S = law.distance
        except ValueError as e:
            S = needed(str(e)) * (1 + 1e-9 + rng.uniform(0, 1))
            law = dispkin.Profile.from_state(S, v_max, a_max, j_max, v0, a0, v1)
        x = law.sample(np.linspace(0.0, law.duration, 1001))
        assert x[:, 1].min() >= -1e-9 * max(v0, v_max), "runs backwards"
        assert np.all(np.diff(x[:, 0]) >= -1e-12 * S)
        trajectory = r.plan(S, v_max, a_max, j_max, v0, a0, v1)
        if trajectory is None:
            continue
        compared += 1
        case = (S, v_max, a_max, j_max, v0, a0, v1, law.duration, trajectory.duration)
        if law.duration > trajectory.duration * (1 + REL):
            # Explained only by Ruckig's brake: it holds its deceleration a hair inside -a_max
            # (its brake ends its jerk ramp an epsilon early), so its velocity stays above ours
            # while both fall to v_max. Ours brakes at -a_max exactly.
            starts = np.concatenate([[0.0], np.cumsum([p[0] for p in law.phases])])
            holds = [k for k, p in enumerate(law.phases) if p[1] == 0.0 and p[4] == -a_max]
            assert holds and law.duration <= trajectory.duration * (1 + 5e-8), case
            middle = starts[holds[0]] + law.phases[holds[0]][0] / 2
            assert trajectory.at_time(middle)[2][0] > -a_max, case
            slower += 1
        faster += law.duration < trajectory.duration * (1 - REL)
    assert compared > 0 and faster > compared // 2 and slower < compared // 100


# --- invariants (hypothesis) -------------------------------------------------------------------

limits = st.tuples(
    st.floats(1e-2, 10),
    st.floats(1e-2, 100),
    st.floats(1e-1, 1e4),
    st.floats(0, 3),
    st.floats(-3, 3),
    st.floats(0, 1),
    st.floats(1e-6, 10),
)


@settings(max_examples=400, deadline=None, derandomize=True, suppress_health_check=[HealthCheck.filter_too_much])
@given(limits)
def test_invariants(case):
    v_max, a_max, j_max, v0_rel, a0_rel, v1_rel, extra = case
    v0, a0, v1 = v0_rel * v_max, a0_rel * a_max, v1_rel * v_max
    assume(natural(v0, min(a0, 0.0), j_max) >= 0.0)
    try:
        law = dispkin.Profile.from_state(extra, v_max, a_max, j_max, v0, a0, v1)
    except ValueError as e:
        law = dispkin.Profile.from_state(needed(str(e)) * (1 + 1e-9) + extra, v_max, a_max, j_max, v0, a0, v1)
    S, T = law.distance, law.duration
    t = np.concatenate([np.linspace(0.0, T, 2001), [p for p in np.cumsum([ph[0] for ph in law.phases])]])
    t.sort()
    x = law.sample(t)
    s, v, a, j = x.T
    a_bound = max(a_max, abs(a0))
    v_bound = max(v_max, v0, natural(v0, max(a0, 0.0), j_max))
    v_tol = 1e-9 * (v_bound + a_bound * T)
    assert (
        x[0, 0] == 0.0
        and x[0, 1] == pytest.approx(v0, rel=1e-12, abs=1e-15)
        and x[0, 2] == pytest.approx(a0, rel=1e-12)
    )
    assert tuple(law.sample([T])[0][:3]) == (S, v1, 0.0)
    end_s, end_v, end_a, lowest, highest = integrated_end(law, v0, a0)
    assert end_s == pytest.approx(S, rel=1e-9, abs=1e-9 * v_bound * T)
    assert end_v == pytest.approx(v1, abs=v_tol) and abs(end_a) <= 1e-9 * (a_bound + j_max * T)
    assert lowest >= -v_tol and highest <= v_bound + v_tol
    assert np.all(np.diff(s) >= -1e-12 * max(S, 1e-300))
    assert np.all(np.abs(j) <= j_max * (1 + 1e-12)) and np.all(np.abs(a) <= a_bound + 1e-9 * a_bound)
    # Continuity: s, v, a change by at most what the limits allow over the sample spacing.
    dt = np.diff(t)
    assert np.all(np.abs(np.diff(a)) <= j_max * dt * (1 + 1e-6) + 1e-6 * a_bound)
    assert np.all(np.abs(np.diff(v)) <= a_bound * dt * (1 + 1e-9) + v_tol)
    # Once inside the limits (v <= v_max and v_n (16) <= v_max), the velocity stays at or below
    # v_max; above it, it does not rise again after it started to fall.
    inside = np.flatnonzero((v <= v_max) & (v + np.maximum(a, 0.0) ** 2 / (2 * j_max) <= v_max))
    if inside.size:
        assert np.all(v[inside[0] :] <= v_max + v_tol)
    peak = int(np.argmax(v))
    above = v[peak:][v[peak:] > v_max + v_tol]
    assert np.all(np.diff(above) <= v_tol)
    # Pickling keeps the law bit for bit.
    again = pickle.loads(pickle.dumps(law))
    assert np.array_equal(again.sample(t), x)


# --- errors ------------------------------------------------------------------------------------


def test_too_short_names_the_shortfall():
    with pytest.raises(ValueError, match=r"^distance = 0.75: too short .* it needs at least 1, 0.25 more"):
        dispkin.Profile.from_state(0.75, 2.0, 10.0, 1.0, 1.0, 0.0, 0.0)
    with pytest.raises(ValueError, match=r"^distance = 1: too short .* it needs at least 2, 1 more"):
        dispkin.Profile.trapezoid_from_state(1.0, 1.0, 1.0, 2.0, 0.0)


@pytest.mark.parametrize(
    "call, match",
    [
        (lambda: dispkin.Profile.from_state(float("nan"), 1, 1, 1), r"^distance = nan: must be finite"),
        (lambda: dispkin.Profile.from_state(1, 1, 1, 0), r"^j_max = 0: must be finite and greater than zero"),
        (
            lambda: dispkin.Profile.from_state(1, 1, 1, 1, v_start=-1.0),
            r"^v_start = -1: must be finite and not negative",
        ),
        (lambda: dispkin.Profile.from_state(1, 1, 1, 1, a_start=float("inf")), r"^a_start = inf: must be finite"),
        (
            lambda: dispkin.Profile.from_state(1, 1, 1, 1, v_end=2.0),
            r"^v_end = 2: must be finite and within \[0, v_max = 1\]",
        ),
        (
            lambda: dispkin.Profile.from_state(1, 1, 1, 1, 0.1, -1.0),
            r"^a_start = -1: brakes too hard for v_start = 0.1",
        ),
        (lambda: dispkin.Profile.trapezoid_from_state(1, 1, 1, float("nan")), r"^v_start = nan: must be finite"),
    ],
)
def test_bad_input(call, match):
    with pytest.raises(ValueError, match=match):
        call()


def test_keyword_names():
    law = dispkin.Profile.from_state(
        distance=10.0, v_max=1.0, a_max=1.0, jerk=10.0, v_start=2.0, a_start=0.5, v_end=0.0
    )
    assert law.kind == "scurve" and law.peak_velocity >= 2.0
    trapezoid = dispkin.Profile.trapezoid_from_state(distance=10.0, v_max=1.0, a_max=1.0, v_start=2.0, v_end=0.0)
    assert trapezoid.duration == pytest.approx(1.0 + (10.0 - 2.0) / 1.0 + 1.0, rel=1e-12)
