"""The rows of the bad-input table (tests/python/test_bad_input_table.py) of one area: Profile:
trapezoid, S-curve, from a state, sampling."""

import numpy as np

import dispkin

from .rows import INF, NAN, V, row

# --- Profile ------------------------------------------------------------------------------
row("Profile.trapezoid", "NaN distance", lambda: dispkin.Profile.trapezoid(NAN, 1, 1), V, "distance = nan")
row("Profile.trapezoid", "negative distance", lambda: dispkin.Profile.trapezoid(-1, 1, 1), V, "distance = -1")
row("Profile.trapezoid", "+inf distance", lambda: dispkin.Profile.trapezoid(INF, 1, 1), V, "distance = inf")
row("Profile.trapezoid", "zero v_max", lambda: dispkin.Profile.trapezoid(1, 0, 1), V, "v_max = 0")
row("Profile.trapezoid", "negative a_max", lambda: dispkin.Profile.trapezoid(1, 1, -1), V, "a_max = -1")
row("Profile.trapezoid", "+inf v_max", lambda: dispkin.Profile.trapezoid(1, INF, 1), V, "v_max = inf")
row(
    "Profile.trapezoid",
    "negative v_start",
    lambda: dispkin.Profile.trapezoid(1, 1, 1, v_start=-0.5),
    V,
    "v_start = -0.5",
)
row("Profile.trapezoid", "v_end above v_max", lambda: dispkin.Profile.trapezoid(1, 1, 1, v_end=2.0), V, "v_end = 2")
row("Profile.scurve", "zero j_max", lambda: dispkin.Profile.scurve(1, 1, 1, 0), V, "j_max = 0")
row("Profile.scurve", "NaN j_max", lambda: dispkin.Profile.scurve(1, 1, 1, NAN), V, "j_max = nan")
row("Profile.scurve", "negative v_max", lambda: dispkin.Profile.scurve(1, -1, 1, 1), V, "v_max = -1")
row("Profile.scurve", "NaN distance", lambda: dispkin.Profile.scurve(NAN, 1, 1, 1), V, "distance = nan")
row(
    "Profile.from_state",
    "NaN v_start",
    lambda: dispkin.Profile.from_state(1, 1, 1, 10, v_start=NAN),
    V,
    "v_start = nan",
)
row(
    "Profile.from_state",
    "+inf a_start",
    lambda: dispkin.Profile.from_state(1, 1, 1, 10, a_start=INF),
    V,
    "a_start = inf",
)
row(
    "Profile.from_state",
    "v_end above v_max",
    lambda: dispkin.Profile.from_state(1, 1, 1, 10, v_end=2.0),
    V,
    "v_end = 2",
)
row("Profile.from_state", "negative jerk", lambda: dispkin.Profile.from_state(1, 1, 1, -1), V, "j_max = -1")
row(
    "Profile.from_state",
    "too short to stop (names the shortfall)",
    lambda: dispkin.Profile.from_state(0.001, 1, 1, 10, v_start=1.0),
    V,
    "distance = 0.001: too short",
)
row(
    "Profile.from_state",
    "braking that turns the velocity negative",
    lambda: dispkin.Profile.from_state(1, 1, 1, 10, v_start=0.01, a_start=-1.0),
    V,
    "a_start = -1: brakes too hard",
)
row(
    "Profile.trapezoid_from_state",
    "negative v_start",
    lambda: dispkin.Profile.trapezoid_from_state(1, 1, 1, v_start=-1.0),
    V,
    "v_start = -1",
)
row(
    "Profile.trapezoid_from_state",
    "too short to brake",
    lambda: dispkin.Profile.trapezoid_from_state(0.001, 1, 1, v_start=1.0),
    V,
    "distance = 0.001: too short",
)
row(
    "velocity_limited_chain",
    "segments of the wrong shape",
    lambda: dispkin.velocity_limited_chain(np.ones((2, 3)), 1.0),
    V,
    "segments: expected an array of shape (N, 2)",
)
row(
    "velocity_limited_law",
    "negative limit in a segment",
    lambda: dispkin.velocity_limited_law(np.array([[1.0, 1.0], [1.0, -1.0]]), 1.0, 10.0),
    V,
    "segments[1].limit = -1",
)
row("Profile.sample", "NaN time", lambda: dispkin.Profile.trapezoid(1, 1, 1).sample([NAN]), V, "times[0] = nan")
