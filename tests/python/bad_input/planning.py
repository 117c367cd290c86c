"""The rows of the bad-input table (tests/python/test_bad_input_table.py) of one area: Limits,
plan, Trajectory, overlaps and the motion stream."""

import numpy as np

import dispkin

from .rows import (
    A,
    INF,
    LIMITS,
    LINE,
    NAN,
    TRAPEZOID_LIMITS,
    V,
    accepted,
    collinear_set,
    good_set,
    overlapped,
    row,
    trajectory,
)

# --- Limits / plan ------------------------------------------------------------------------
row("Limits", "zero velocity", lambda: dispkin.Limits(0.0, 1.0), V, "velocity = 0")
row("Limits", "negative acceleration", lambda: dispkin.Limits(1.0, -1.0), V, "acceleration = -1")
row("Limits", "NaN velocity", lambda: dispkin.Limits(NAN, 1.0), V, "velocity = nan")
row("Limits", "+inf acceleration", lambda: dispkin.Limits(1.0, INF), V, "acceleration = inf")
row(
    "Limits",
    "velocity below the numeric range (1e-13)",
    lambda: dispkin.Limits(1e-13, 1.0),
    V,
    "velocity = 1e-13: must be in [1e-12, 1e12]",
)
row(
    "Limits",
    "jerk above the numeric range (1e13)",
    lambda: dispkin.Limits(1.0, 1.0, 1e13),
    V,
    "jerk = 1e+13: must be in [1e-12, 1e12]",
)
row("Limits", "zero jerk", lambda: dispkin.Limits(1.0, 1.0, 0.0), V, "jerk = 0")
row("Limits", "negative jerk", lambda: dispkin.Limits(1.0, 1.0, -5.0), V, "jerk = -5")
row(
    "plan",
    "empty set",
    lambda: dispkin.plan(LINE, dispkin.MetricSet(), LIMITS),
    V,
    "metric_set = \"MetricSet\": is not well-formed",
)
row(
    "plan",
    "collinear set",
    lambda: dispkin.plan(LINE, collinear_set(), LIMITS),
    V,
    "metric_set = \"MetricSet\": is not well-formed",
)
row("plan", "unknown profile", lambda: dispkin.plan(LINE, good_set(), LIMITS, profile="sine"), V, "profile = \"sine\"")
row(
    "plan",
    "scurve without jerk",
    lambda: dispkin.plan(LINE, good_set(), dispkin.Limits(0.1, 1.0), profile="scurve"),
    V,
    "jerk is missing: the S-curve profile needs a jerk limit",
)
row(
    "Trajectory.sample",
    "NaN time",
    lambda: dispkin.plan(LINE, good_set(), LIMITS).sample([NAN]),
    V,
    "times = nan: must be finite",
)
row("Trajectory.stopped_at", "NaN time", lambda: trajectory().stopped_at(NAN), V, "t = nan: must be finite")
row(
    "Trajectory.with_override",
    "factor 0",
    lambda: trajectory().with_override(0.1, 0.0),
    V,
    "factor = 0: must be in [0.001, 10]",
)
row(
    "Trajectory.with_override",
    "factor above 10",
    lambda: trajectory().with_override(0.1, 11.0),
    V,
    "factor = 11: must be in [0.001, 10]",
)
row(
    "Trajectory.with_override",
    "factor not a number",
    lambda: trajectory().with_override(0.1, "fast"),
    TypeError,
    "incompatible function arguments",
)
row(
    "Trajectory.resumed_at",
    "not stopped",
    lambda: trajectory().resumed_at(0.1),
    V,
    "t = 0.1: resumes a stopped trajectory only",
)
row(
    "plan",
    "negative start velocity",
    lambda: dispkin.plan(LINE, good_set(), LIMITS, start_velocity=-1.0),
    V,
    "start_velocity = -1: must be finite and ≥ 0",
)
row(
    "plan",
    "start velocity above the limit",
    lambda: dispkin.plan(LINE, good_set(), LIMITS, start_velocity=1e3),
    V,
    "start_velocity = 1000: must be at most the velocity limit at the start",
)
row(
    "plan",
    "NaN start acceleration",
    lambda: dispkin.plan(LINE, good_set(), LIMITS, start_acceleration=NAN),
    V,
    "start_acceleration = nan: must be finite",
)
row(
    "Trajectory.starting_from",
    "acceleration beyond the limit",
    lambda: trajectory().starting_from(0.0, 1e3),
    V,
    "acceleration = 1000: must be within the acceleration limit",
)


def stream(*requests):
    """A MotionStream of LINE's tool and limits after `requests` (callables on it)."""
    s = dispkin.MotionStream(good_set(), LIMITS)
    for request in requests:
        request(s)
    return s


row(
    "MotionStream",
    "negative corner tolerance",
    lambda: dispkin.MotionStream(good_set(), LIMITS, corner_tolerance=-1.0),
    V,
    "corner_tolerance = -1: must be finite and not negative",
)
row(
    "MotionStream",
    "S-curve without jerk",
    lambda: dispkin.MotionStream(good_set(), TRAPEZOID_LIMITS),
    V,
    "jerk is missing",
)
row(
    "MotionStream.append",
    "a move that does not start where the last ends",
    lambda: stream(lambda s: s.append(LINE, 0.0), lambda s: s.append(LINE, 1.0)),
    V,
    "path.start",
)
row(
    "MotionStream.append",
    "a request before the last one",
    lambda: stream(lambda s: s.append(LINE, 2.0), lambda s: s.set_override(1.0, 0.5)),
    V,
    "t = 1: must be finite and not before the last request",
)
row("MotionStream.append", "NaN time", lambda: stream(lambda s: s.append(LINE, NAN)), V, "t = nan")
row("MotionStream.stop", "nothing appended", lambda: stream(lambda s: s.stop(0.0)), V, "nothing was appended yet")
row(
    "MotionStream.stop",
    "stopped already",
    lambda: stream(lambda s: s.append(LINE, 0.0), lambda s: s.stop(0.1), lambda s: s.stop(0.2)),
    V,
    "it is stopped already",
)
row(
    "MotionStream.resume",
    "not stopped",
    lambda: stream(lambda s: s.append(LINE, 0.0), lambda s: s.resume(0.1)),
    V,
    "resumes a stopped motion only",
)
row(
    "MotionStream.set_override",
    "factor 0",
    lambda: stream(lambda s: s.set_override(0.0, 0.0)),
    V,
    "factor = 0: must be in [0.001, 10]",
)
row("Trajectory.sample", "+inf time", lambda: dispkin.plan(LINE, good_set(), LIMITS).sample([INF]), V, "times = inf")
accepted(
    "Trajectory.sample",
    "negative time",
    lambda: dispkin.plan(LINE, good_set(), LIMITS).sample([-1.0]),
    lambda m: np.allclose(m[0], A.matrix(), atol=0),
    "clamped to t = 0, the start pose, as t beyond the duration gives the end (documented: times clamped)",
)

row(
    "Trajectory.sample",
    "out of dtype int64",
    lambda: dispkin.plan(LINE, good_set(), LIMITS).sample([0.0, 0.1], out=np.zeros((2, 4, 4), dtype=np.int64)),
    V,
    "out: expected a writeable C-contiguous float64 array of shape (2, 4, 4), got dtype int64",
)
row(
    "Trajectory.sample",
    "out of one sample for two times",
    lambda: dispkin.plan(LINE, good_set(), LIMITS).sample([0.0, 0.1], out=np.zeros((4, 4))),
    V,
    "out: expected a writeable C-contiguous float64 array of shape (2, 4, 4), got shape (4, 4)",
)
row(
    "Trajectory.sample_xyzuvw",
    "out a list",
    lambda: dispkin.plan(LINE, good_set(), LIMITS).sample_xyzuvw(0.1, out=[0.0] * 6),
    V,
    "out: expected a writeable C-contiguous float64 array of shape (6,), got list",
)
row(
    "Trajectory.body_twist",
    "out not contiguous (every other row)",
    lambda: dispkin.plan(LINE, good_set(), LIMITS).body_twist([0.0, 0.1], out=np.zeros((4, 6))[::2]),
    V,
    "out: expected a writeable C-contiguous float64 array of shape (2, 6), got a non-contiguous array (strides (96, 8))",
)
row(
    "Trajectory.path_velocity",
    "read-only out",
    lambda: dispkin.plan(LINE, good_set(), LIMITS).path_velocity([0.0, 0.1], out=np.frombuffer(bytes(16))),
    V,
    "out: expected a writeable C-contiguous float64 array of shape (2,), got a read-only array",
)
row(
    "Trajectory.path_position",
    "out of shape (2,) for a number",
    lambda: dispkin.plan(LINE, good_set(), LIMITS).path_position(0.1, out=np.zeros(2)),
    V,
    "out: expected a writeable C-contiguous float64 array of shape () or (1,), got shape (2,)",
)
row(
    "Trajectory.body_acceleration",
    "out of dtype float32",
    lambda: dispkin.plan(LINE, good_set(), LIMITS).body_acceleration(0.1, out=np.zeros(6, dtype=np.float32)),
    V,
    "out: expected a writeable C-contiguous float64 array of shape (6,), got dtype float32",
)
row(
    "OverlappedTrajectory.sample",
    "out of dtype float32",
    lambda: overlapped().sample(0.1, out=np.zeros((4, 4), dtype=np.float32)),
    V,
    "out: expected a writeable C-contiguous float64 array of shape (4, 4), got dtype float32",
)
row(
    "TrajectoryCursor.sample",
    "NaN time",
    lambda: dispkin.plan(LINE, good_set(), LIMITS).cursor().sample(NAN, np.zeros(15)),
    V,
    "t = nan: must be finite",
)
row(
    "TrajectoryCursor.sample",
    "+inf time",
    lambda: dispkin.plan(LINE, good_set(), LIMITS).cursor().sample(INF, np.zeros(15)),
    V,
    "t = inf: must be finite",
)
row(
    "TrajectoryCursor.sample",
    "out of shape (17,)",
    lambda: dispkin.plan(LINE, good_set(), LIMITS).cursor().sample(0.1, np.zeros(17)),
    V,
    "out: expected a writeable C-contiguous float64 array of shape (15,), got shape (17,)",
)
row(
    "TrajectoryCursor.sample",
    "out of dtype int64",
    lambda: dispkin.plan(LINE, good_set(), LIMITS).cursor().sample(0.1, np.zeros(15, dtype=np.int64)),
    V,
    "out: expected a writeable C-contiguous float64 array of shape (15,), got dtype int64",
)
row(
    "TrajectoryCursor.sample",
    "read-only out",
    lambda: dispkin.plan(LINE, good_set(), LIMITS).cursor().sample(0.1, np.frombuffer(bytes(120))),
    V,
    "out: expected a writeable C-contiguous float64 array of shape (15,), got a read-only array",
)

row(
    "OverlappedTrajectory",
    "negative overlap",
    lambda: dispkin.OverlappedTrajectory(trajectory(), trajectory(), -0.5),
    V,
    "overlap = -0.5",
)
row(
    "OverlappedTrajectory",
    "overlap longer than a move",
    lambda: dispkin.OverlappedTrajectory(trajectory(), trajectory(), 1e3),
    V,
    "overlap = 1000: must be between 0 and the shorter move's duration",
)
row(
    "OverlappedTrajectory",
    "moves not joining",
    lambda: dispkin.OverlappedTrajectory(trajectory(), trajectory(), 0.1),
    V,
    "must start where `before` ends",
)
row(
    "OverlappedTrajectory",
    "wrong size pivot (2)",
    lambda: dispkin.OverlappedTrajectory(trajectory(), trajectory(), 0.1, pivot=[0, 0]),
    V,
    "pivot: expected an array of shape (3,), got shape (2,)",
)
