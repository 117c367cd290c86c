"""What the pickle tests share (test_pickle_invariants.py, test_pickle_properties.py): an object
of every pickled type, states taken apart and put back with one value replaced, and the check
that a state is refused with the type, field and value named.
"""

import functools

import numpy as np
import pytest

import dispkin

from test_python_objects import Q0, arm, blended_path, hexapod, pose, tool


def fresh(cls, state):
    """What unpickling does: a new, empty instance made from `state`."""
    obj = cls.__new__(cls)
    obj.__setstate__(state)
    return obj


def plain(x):
    """A state as nested tuples of Python values (arrays as tuples, dispkin objects as their state)."""
    if isinstance(x, np.ndarray):
        return plain(x.tolist())
    if isinstance(x, (list, tuple)):
        return tuple(plain(v) for v in x)
    if hasattr(x, "__getstate__") and type(x).__module__.startswith("dispkin"):
        return (type(x).__name__, plain(x.__getstate__()))
    return x


def replaced(state, path, value):
    """`state` with the item at `path` (indices into nested tuples) replaced by `value`."""
    if not path:
        return value
    items = list(state)
    items[path[0]] = replaced(items[path[0]], path[1:], value)
    return tuple(items)


def item(state, path):
    for k in path:
        state = state[k]
    return state


def number_paths(state, path=()):
    """The paths of every float (not int, not bool) in a plain state."""
    if isinstance(state, tuple):
        for k, v in enumerate(state):
            yield from number_paths(v, path + (k,))
    elif isinstance(state, float):
        yield path


# --- objects of every pickled type --------------------------------------------------------------


@functools.lru_cache(maxsize=None)
def trajectory():
    return dispkin.plan(blended_path(), tool(), dispkin.Limits(0.25, 1.0, 10.0))


@functools.lru_cache(maxsize=None)
def retimed():
    a = arm()
    lin = dispkin.Path.lin(a.forward(Q0), a.forward(Q0) * pose(0, 0, 0, 0, 0, 90))
    scaled = dispkin.retime(lin, tool(), dispkin.Limits(0.25, 1.0, 10.0), a, Q0)
    optimal = dispkin.retime(lin, tool(), dispkin.Limits(0.25, 1.0), a, Q0, profile="trapezoid", method="optimal")
    return scaled, optimal


@functools.lru_cache(maxsize=None)
def hexapod_checks():
    h = hexapod()
    far = h.home * dispkin.Pose(translation=(0, 0, 0.2))
    ms = dispkin.MetricSet()
    h.add_leg_speed_group(ms, 0)
    traj = dispkin.plan(dispkin.Path.lin(h.home, far), ms, dispkin.Limits(0.05, 0.5), "trapezoid")
    return h.check(far), h.check_trajectory(traj, 1e-3)


def objects():
    """(name, object) for every type with a py::pickle."""
    scaled, optimal = retimed()
    workspace, checked = hexapod_checks()
    a = arm()
    return [
        ("Pose", pose(0.1, 0.2, 0.3, 10, 20, 30)),
        ("WorkToolFrames", dispkin.WorkToolFrames(pose(0, 0, 0.2, 0, 0, 10), pose(0, 0, 0.05, 5, 0, 0))),
        ("MetricSet", tool()),
        ("Limits", dispkin.Limits(0.25, 1.0, 10.0, angular_velocity=2.0)),
        ("JointPath", dispkin.Path.ptp(Q0, Q0 + 0.3)),
        ("Path", blended_path()),
        ("Profile", dispkin.Profile.scurve(0.3, 0.25, 1.0, 10.0, 0.05, 0.1)),
        ("Trajectory", trajectory()),
        ("LegViolation", workspace.violations[0]),
        ("WorkspaceCheck", workspace),
        ("LegExcursion", checked.excursions[0]),
        ("TrajectoryCheck", checked),
        ("Hexapod", hexapod()),
        ("JointLimits", a.joint_limits),
        ("InverseResult", a.inverse_solutions(a.forward(Q0))),
        ("SerialArm", a),
        ("JointLimitReport", optimal.report),
        ("RetimeResult", scaled),
        ("OptimalRetimeResult", optimal),
    ]


NAMES = [name for name, _ in objects()]


def named(name):
    return dict(objects())[name]


def assert_refused(cls, state, error, *fragments):
    """`cls.__setstate__(state)` on a fresh instance raises exactly `error`, whose message names the
    type and contains each fragment."""
    with pytest.raises(Exception) as caught:
        fresh(cls, state)
    assert type(caught.value) is error, f"{type(caught.value).__name__}: {caught.value}"
    message = str(caught.value)
    assert message.startswith(cls.__name__ + ".__setstate__: "), message
    for fragment in fragments:
        assert fragment in message, message
    return message
