"""atheris target for __setstate__ (fuzz_loaders.py ``pickles``, run as ``py_fuzz_pickles``): the
bytes choose a valid pickled state of one of dispkin's types and corrupt it — numbers replaced
by NaN, ±inf, ±1e308, 0, or scaled and shifted; items replaced by values of another type; tuples
cut short, lengthened or emptied — then the state is unpickled as pickle.loads would.

A finding is anything but the documented outcome: a ValueError or TypeError whose message names
the type (``<Type>.__setstate__: ...``), or an object whose samples are finite (a trajectory's
path speed also within its own velocity-limit curve). Another exception, a crash of the extension
or a hang is a finding too. Seeds: tests/fuzz/corpus/fuzz_pickles.
"""

import math
import pathlib

import atheris
import numpy as np

import dispkin

DATA = pathlib.Path(__file__).resolve().parents[1] / "data"


def _pose(*xyzuvw):
    return dispkin.Pose.from_xyzuvw(list(xyzuvw[:3]) + [math.radians(a) for a in xyzuvw[3:]])


def _tool():
    ms = dispkin.MetricSet()
    ms.add_relative([[0.0, 0.0, 0.15], [0.02, 0.0, 0.1]])
    ms.add_sphere([0.0, 0.0, 0.0], 0.04)
    return ms


def _objects():
    """One valid object of every type with a py::pickle (the fuzzer corrupts their states)."""
    a, b, c = _pose(0, 0, 0, 0, 0, 0), _pose(0.3, 0, 0, 0, 0, 10), _pose(0.3, 0.2, 0, 0, 0, 30)
    path = dispkin.Path.lin(a, b, pivot=(0, 0, 0.1))
    path.then(dispkin.Path.circ(b, _pose(0.45, 0.1, 0, 0, 0, 20), c, pivot=(0, 0, 0.1)), blend=0.03)
    path.then(
        dispkin.Path.spline([c, _pose(0.15, 0.25, 0.02, 2, 0, 35), _pose(0, 0.2, 0.05, 5, 0, 40)], pivot=(0, 0, 0.1)),
        blend=0.02,
    )
    trajectory = dispkin.plan(path, _tool(), dispkin.Limits(0.25, 1.0, 10.0))
    arm = dispkin.SerialArm.from_urdf(str(DATA / "urdf" / "arm_ur5e_dh.urdf"), "base_link", "tool0")
    q0 = np.array([0.0, -1.9, 1.9, -1.57, -1.57, 0.0])
    lin = dispkin.Path.lin(arm.forward(q0), arm.forward(q0) * _pose(0, 0, 0, 0, 0, 90))
    scaled = dispkin.retime(lin, _tool(), dispkin.Limits(0.25, 1.0, 10.0), arm, q0)
    optimal = dispkin.retime(lin, _tool(), dispkin.Limits(0.25, 1.0), arm, q0, profile="trapezoid", method="optimal")
    hexapod = dispkin.Hexapod.symmetric(0.15, math.radians(20), 0.10, math.radians(20), 0.20, 0.15, 0.32, 0.01)
    far = hexapod.home * dispkin.Pose(translation=(0, 0, 0.2))
    legs = dispkin.MetricSet()
    hexapod.add_leg_speed_group(legs, 0)
    checked = hexapod.check_trajectory(
        dispkin.plan(dispkin.Path.lin(hexapod.home, far), legs, dispkin.Limits(0.05, 0.5), "trapezoid"), 1e-3
    )
    return [
        _pose(0.1, 0.2, 0.3, 10, 20, 30),
        dispkin.WorkToolFrames(_pose(0, 0, 0.2, 0, 0, 10), _pose(0, 0, 0.05, 5, 0, 0)),
        _tool(),
        dispkin.Limits(0.25, 1.0, 10.0, angular_velocity=2.0),
        dispkin.Path.ptp(q0, q0 + 0.3),
        path,
        dispkin.Profile.scurve(0.3, 0.25, 1.0, 10.0, 0.05, 0.1),
        dispkin.Profile.trapezoid(0.3, 0.25, 1.0),
        trajectory,
        hexapod.check(far).violations[0],
        hexapod.check(far),
        checked.excursions[0],
        checked,
        hexapod,
        arm.joint_limits,
        arm.inverse_solutions(arm.forward(q0)),
        arm,
        optimal.report,
        scaled,
        optimal,
    ]


def _plain(x):
    """A state as nested tuples (arrays as tuples of floats); dispkin objects inside it (a
    RetimeResult's Limits, a WorkToolFrames' Poses) stay objects, as pickle hands them over."""
    if isinstance(x, np.ndarray):
        return _plain(x.tolist())
    if isinstance(x, (list, tuple)):
        return tuple(_plain(v) for v in x)
    return x


OBJECTS = _objects()
STATES = [(type(o), _plain(o.__getstate__())) for o in OBJECTS]
HOSTILE_NUMBERS = [math.nan, math.inf, -math.inf, 1e308, -1e308, 0.0, -1.0, 5e-324, 1e300, 2.0**63]
OTHER_TYPES = [None, "x", b"\xff", (), [], 1, True, 1.5, ((),)]


def _paths(state, path=()):
    """Every position in a nested tuple (its items, and items of items)."""
    yield path
    if isinstance(state, tuple):
        for k, v in enumerate(state):
            yield from _paths(v, path + (k,))


def _at(state, path):
    for k in path:
        state = state[k]
    return state


def _replaced(state, path, value):
    if not path:
        return value
    items = list(state)
    items[path[0]] = _replaced(items[path[0]], path[1:], value)
    return tuple(items)


def _corrupt(fdp, state):
    """One corruption chosen by the bytes."""
    paths = list(_paths(state))
    path = paths[fdp.ConsumeIntInRange(0, len(paths) - 1)]
    old = _at(state, path)
    how = fdp.ConsumeIntInRange(0, 5)
    if how == 0 and isinstance(old, (int, float)) and not isinstance(old, bool):
        new = fdp.PickValueInList(HOSTILE_NUMBERS + [old * 1000.0, old * (1 + 1e-6), old + 8.6, -old, old * 1e-300])
    elif how == 1:
        new = fdp.ConsumeRegularFloat() if fdp.ConsumeBool() else fdp.ConsumeInt(8)
    elif how == 2:
        new = fdp.PickValueInList(OTHER_TYPES)
    elif how == 3 and isinstance(old, tuple) and old:
        new = old[: fdp.ConsumeIntInRange(0, len(old) - 1)]  # cut short
    elif how == 4 and isinstance(old, tuple) and old:
        new = old + (old[fdp.ConsumeIntInRange(0, len(old) - 1)],)  # an item repeated
    else:
        new = fdp.ConsumeRegularFloat()
    return _replaced(state, path, new)


def _finite(x):
    return bool(np.all(np.isfinite(np.asarray(x, dtype=float))))


def _require_usable(obj):
    """What an accepted object promises: finite samples; a trajectory within its velocity-limit curve."""
    if isinstance(obj, (dispkin.RetimeResult, dispkin.OptimalRetimeResult)):
        _require_usable(obj.trajectory)
        _require_usable(obj.report)
        return
    if isinstance(obj, dispkin.Trajectory):
        if not (math.isfinite(obj.duration) and obj.duration >= 0.0):
            raise AssertionError(f"an unpickled trajectory lasts {obj.duration} s")
        t = np.linspace(0.0, obj.duration, 101)
        for method in (
            "sample",
            "body_twist",
            "path_position",
            "path_velocity",
            "path_acceleration",
            "body_acceleration",
        ):
            if not _finite(getattr(obj, method)(t)):
                raise AssertionError(f"an unpickled trajectory gives non-finite {method}")
        limits = obj.speed_limits()
        if len(limits) and np.max(obj.path_velocity(t)) > limits[:, 2].max() * (1 + 1e-8):
            raise AssertionError("an unpickled trajectory is faster than its own velocity-limit curve")
    elif isinstance(obj, dispkin.Profile):
        x = obj.sample(np.linspace(-0.1, obj.duration + 0.1, 101))
        if not (_finite(x) and math.isfinite(obj.duration)):
            raise AssertionError("an unpickled profile gives non-finite states")
        if np.max(x[:, 1]) > obj.peak_velocity * (1 + 1e-7) + 1e-12:
            raise AssertionError("an unpickled profile is faster than its peak velocity")
    elif isinstance(obj, dispkin.Path):
        if not _finite(obj.sample(np.linspace(0.0, 1.0, 51))):
            raise AssertionError("an unpickled path gives non-finite poses")
    elif isinstance(obj, dispkin.JointLimitReport):
        if not all(_finite(v) for v in obj.samples.values()) or not _finite([obj.velocity_time, obj.torque_time]):
            raise AssertionError("an unpickled report gives non-finite samples")
    elif isinstance(obj, dispkin.Pose):
        if not _finite(obj.matrix()):
            raise AssertionError("an unpickled pose is not finite")
    elif isinstance(obj, dispkin.SerialArm):
        q = np.zeros(obj.dof)
        if not (_finite(obj.forward(q).matrix()) and _finite(obj.static_torques(q))):
            raise AssertionError("an unpickled arm gives non-finite kinematics")
    elif isinstance(obj, dispkin.Hexapod):
        if not _finite(obj.inverse(obj.home)):
            raise AssertionError("an unpickled hexapod gives non-finite legs")


def pickles(data: bytes) -> None:
    fdp = atheris.FuzzedDataProvider(data)
    cls, state = STATES[fdp.ConsumeIntInRange(0, len(STATES) - 1)]
    for _ in range(fdp.ConsumeIntInRange(0, 3)):
        state = _corrupt(fdp, state)
    obj = cls.__new__(cls)
    try:
        obj.__setstate__(state)
    except (ValueError, TypeError) as error:
        message = str(error)
        message.encode("utf-8")  # the message is text
        if not message.startswith(cls.__name__ + ".__setstate__: "):
            raise AssertionError(f"the message does not name the type: {message[:300]}") from error
        return
    _require_usable(obj)
