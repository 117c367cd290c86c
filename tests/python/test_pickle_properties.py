"""Pickles of random objects round-trip exactly, and a state with one number corrupted (NaN,
±inf, ±1e308, 0, -1, the smallest subnormal) is refused or gives an object that samples finite
numbers within its own limits (hypothesis)."""

import functools
import math
import pickle

import numpy as np
from hypothesis import HealthCheck, given, settings, strategies as st

import dispkin


from _pickled import fresh, item, named, number_paths, plain, replaced, trajectory


# --- properties ---------------------------------------------------------------------------------

FINITE = st.floats(allow_nan=False, allow_infinity=False)


@settings(max_examples=60, deadline=None)
@given(
    distance=st.floats(1e-3, 10.0),
    v=st.floats(1e-2, 5.0),
    a=st.floats(1e-2, 50.0),
    j=st.floats(0.1, 500.0),
    ends=st.tuples(st.floats(0.0, 1.0), st.floats(0.0, 1.0)),
    scurve=st.booleans(),
)
def test_random_profiles_round_trip_exactly(distance, v, a, j, ends, scurve):
    v_start, v_end = ends[0] * v, ends[1] * v
    try:
        law = (
            dispkin.Profile.scurve(distance, v, a, j, v_start, v_end)
            if scurve
            else dispkin.Profile.trapezoid(distance, v, a, v_start, v_end)
        )
    except ValueError:
        return  # too short for the boundary velocities
    copied = pickle.loads(pickle.dumps(law))
    assert copied.__getstate__() == law.__getstate__()
    t = np.linspace(0.0, law.duration, 101)
    np.testing.assert_array_equal(copied.sample(t), law.sample(t))


@settings(max_examples=60, deadline=None)
@given(
    xyzuvw=st.tuples(*[st.floats(-1e3, 1e3)] * 3, *[st.floats(-math.pi, math.pi)] * 3),
    limits=st.tuples(st.floats(1e-3, 1e3), st.floats(1e-3, 1e3), st.none() | st.floats(1e-3, 1e3)),
)
def test_random_poses_and_limits_round_trip_exactly(xyzuvw, limits):
    p = dispkin.Pose.from_xyzuvw(list(xyzuvw))
    assert pickle.loads(pickle.dumps(p)).__getstate__() == p.__getstate__()
    lim = dispkin.Limits(*limits)
    assert pickle.loads(pickle.dumps(lim)) == lim


CORRUPTIONS = [math.nan, math.inf, -math.inf, 1e308, -1e308, 0.0, -1.0, 5e-324]


@functools.lru_cache(maxsize=None)
def plain_state(name):
    """The plain state of the object `name` (the planned trajectory, or one of objects()) and the
    paths of its floats, computed once: every example corrupts a copy of the same state."""
    obj = trajectory() if name == "Trajectory" else named(name)
    state = plain(obj.__getstate__())
    return state, tuple(number_paths(state))


def corrupted(name, data):
    """The plain state of `name` with one of its floats replaced by a hostile or slightly moved value."""
    state, paths = plain_state(name)
    path = data.draw(st.sampled_from(paths), label="path")
    old = item(state, path)
    value = data.draw(st.sampled_from(CORRUPTIONS + [old * 1000.0, old * (1 + 1e-6), old + 8.6, -old]), label="value")
    return replaced(state, path, value)


def accepted_or_refused(cls, state):
    try:
        return fresh(cls, state)
    except (ValueError, TypeError):
        return None


@settings(max_examples=300, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(data=st.data())
def test_a_corrupted_trajectory_is_refused_or_finite_within_its_limits(data):
    copy_ = accepted_or_refused(dispkin.Trajectory, corrupted("Trajectory", data))
    if copy_ is None:
        return
    assert math.isfinite(copy_.duration) and copy_.duration >= 0.0
    t = np.linspace(0.0, copy_.duration, 301)
    for method in ("sample", "body_twist", "path_position", "path_velocity", "path_acceleration", "body_acceleration"):
        assert np.all(np.isfinite(getattr(copy_, method)(t))), method
    fastest = copy_.speed_limits()[:, 2].max()
    assert np.all(copy_.path_velocity(t) <= fastest * (1 + 1e-8))
    assert np.all(copy_.path_velocity(t) >= -1e-9 * fastest)


@settings(max_examples=200, deadline=None)
@given(data=st.data())
def test_a_corrupted_profile_is_refused_or_a_law_within_its_peak(data):
    copy_ = accepted_or_refused(dispkin.Profile, corrupted("Profile", data))
    if copy_ is None:
        return
    x = copy_.sample(np.linspace(-0.1, copy_.duration + 0.1, 501))
    assert np.all(np.isfinite(x)) and math.isfinite(copy_.duration)
    assert np.all(x[:, 1] <= copy_.peak_velocity * (1 + 1e-7) + 1e-12)
    assert np.all(x[:, 1] >= -1e-7 * copy_.peak_velocity - 1e-12)


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(data=st.data())
def test_a_corrupted_report_is_refused_or_reads_finite_arrays(data):
    copy_ = accepted_or_refused(dispkin.JointLimitReport, corrupted("JointLimitReport", data))
    if copy_ is None:
        return
    for key, value in copy_.samples.items():
        assert np.all(np.isfinite(value)), key
    assert math.isfinite(copy_.velocity_time) and math.isfinite(copy_.torque_time)
