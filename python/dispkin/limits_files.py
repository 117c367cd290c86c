"""Limits files people already have: MoveIt's ``joint_limits.yaml`` and the Pilz industrial motion
planner's ``cartesian_limits.yaml``.

``read_moveit_joint_limits(path)`` reads the per-joint limits MoveIt uses to override a URDF
(``has_velocity_limits`` / ``max_velocity``, accelerations, jerks, efforts, positions, and the
default scaling factors); ``apply_moveit_joint_limits(arm, limits)`` returns the arm with those
velocity, effort and position limits and the joint accelerations for
``dispkin.retime(..., method="optimal", joint_acceleration=...)``.

``read_pilz_cartesian_limits(path)`` reads ``max_trans_vel``, ``max_trans_acc``, ``max_trans_dec``
and ``max_rot_vel``. Pilz limits the tool centre's speed and, separately, the angular speed;
dispkin limits the speed of every point of a set. ``PilzCartesianLimits.limits()`` gives the
DISP limits (velocity = max_trans_vel, acceleration = the smaller of max_trans_acc and
|max_trans_dec|, angular_velocity = max_rot_vel: the tool's angular speed is limited exactly and
separately, doc/planning.md §11). ``add_rotation_sphere(metric_set)`` is the alternative that
folds the angular limit into the set: the sphere around the tool centre whose radius
r = max_trans_vel / max_rot_vel makes a pure rotation at max_rot_vel move the sphere's points at
max_trans_vel (its fastest point moves at least at |ω| r); it under-uses both limits on
combined moves, so use it with ``limits(angular=False)``.

Every mistake raises :class:`LimitsFileError` (a ValueError) naming the file, the line and
column, and the key. The files are read under the input budget of job files (size,
nesting, aliases, scalar length, UTF-8; doc/input-budget.md).
"""

import dataclasses
import math
import pathlib
from typing import Any, Dict, Optional, Sequence, Tuple, Union

import numpy as np

from ._core import Limits, MetricSet
from .job.reader import Source

#: dispkin's numeric range of speed, acceleration and jerk limits (include/dispkin/error.hpp).
LIMIT_RANGE = (1e-12, 1e12)

_PathLike = Union[str, pathlib.Path]

#: Largest magnitude of a number in a limits file: every integer within it is a double, as for
#: job files (doc/input-budget.md).
MAX_INTEGER = 2**53


class LimitsFileError(ValueError):
    """A limits file that cannot be read or has a bad entry; the message names the file, the
    line and column and the key."""


def _error(message: str, line: Optional[int] = None) -> LimitsFileError:
    return LimitsFileError(message)


class LimitsDocument:
    """A limits file read under the input budget of job files (size, nesting, aliases,
    scalar length; :mod:`dispkin.job.limits`): its data and where each key is."""

    def __init__(self, path: _PathLike):
        #: The file.
        self.file = pathlib.Path(path)
        self._source = Source(self.file, "limits file", _error)
        #: The data as YAML gives it (YAML 1.2 numbers: 1e-3 is a float).
        self.data: Any = self._source.data

    def place(self, keys: Sequence[Any]) -> str:
        """``FILE:LINE:COLUMN`` of the deepest part of `keys` in the file (``FILE`` if none)."""
        mark = self._source.mark(keys)
        return f"{self.file}:{mark[0]}:{mark[1]}" if mark else str(self.file)

    def fail(self, keys: Sequence[Any], text: str) -> LimitsFileError:
        """The error ``FILE:LINE:COLUMN: key.path<text>`` at the deepest part of `keys` in the
        file; `text` is `` = value: reason`` or ``: reason``."""
        return LimitsFileError(f"{self.place(keys)}: {'.'.join(str(k) for k in keys)}{text}")


def load_limits_file(path: Union[_PathLike, LimitsDocument]) -> LimitsDocument:
    """The limits file at `path` read under the input budget of job files (a
    LimitsDocument is returned as it is)."""
    return path if isinstance(path, LimitsDocument) else LimitsDocument(path)


def _number(doc: LimitsDocument, keys: Sequence[Any], value: Any, *, positive: bool = False) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise doc.fail(keys, f" = {echo(value)}: must be a number")
    if isinstance(value, int) and abs(value) > MAX_INTEGER:
        raise doc.fail(keys, f" = an integer of {value.bit_length()} bits: must be within ±2^53 ({MAX_INTEGER})")
    number = float(value)
    if not math.isfinite(number):
        raise doc.fail(keys, f" = {number}: must be finite")
    if positive and not number > 0:
        raise doc.fail(keys, f" = {number:g}: must be > 0")
    return number


def _in_limit_range(doc: LimitsDocument, keys: Sequence[Any], value: float) -> None:
    """A speed, acceleration, jerk or effort limit: within dispkin's numeric range in magnitude
    (as the path limits of a job are; 1e300 rad/s is no limit the library can compute with)."""
    if not LIMIT_RANGE[0] <= abs(value) <= LIMIT_RANGE[1]:
        raise doc.fail(
            keys,
            f" = {value:g}: must be in [{LIMIT_RANGE[0]:g}, {LIMIT_RANGE[1]:g}] in magnitude "
            "(dispkin's numeric range of limits)",
        )


def _flag(doc: LimitsDocument, keys: Sequence[Any], value: Any) -> bool:
    if not isinstance(value, bool):
        raise doc.fail(keys, f" = {echo(value)}: must be true or false")
    return value


def echo(value: Any) -> str:
    """A value of the file for a message: its repr, at most 200 characters of it."""
    text = repr(value)
    return text if len(text) <= 200 else f"{text[:200]}… ({len(text)} characters)"


@dataclasses.dataclass(frozen=True)
class JointLimitEntry:
    """One joint's entry of joint_limits.yaml; None where the file states no limit (its
    ``has_*_limits`` flag is false or absent)."""

    max_velocity: Optional[float] = None
    max_acceleration: Optional[float] = None
    max_jerk: Optional[float] = None
    max_effort: Optional[float] = None
    min_position: Optional[float] = None
    max_position: Optional[float] = None


@dataclasses.dataclass(frozen=True)
class MoveItJointLimits:
    """A joint_limits.yaml: the entries by joint name and MoveIt's default scaling factors (read
    and reported; dispkin does not apply them: scale the limits yourself if you want them)."""

    joints: Dict[str, JointLimitEntry]
    default_velocity_scaling_factor: float = 1.0
    default_acceleration_scaling_factor: float = 1.0
    source: str = ""
    #: "FILE:LINE:COLUMN" of each joint's entry, for messages about it.
    places: Dict[str, str] = dataclasses.field(default_factory=dict, compare=False, repr=False)


_LIMIT_KEYS = {  # has_*_limits flag -> the values it enables
    "has_velocity_limits": ("max_velocity",),
    "has_acceleration_limits": ("max_acceleration",),
    "has_jerk_limits": ("max_jerk",),
    "has_effort_limits": ("max_effort",),
    "has_position_limits": ("min_position", "max_position"),
}


def read_moveit_joint_limits(path: Union[_PathLike, LimitsDocument]) -> MoveItJointLimits:
    """Reads MoveIt's joint_limits.yaml (the ``joint_limits:`` mapping of joint name to
    ``has_*_limits`` flags and values, plus the optional default scaling factors)."""
    doc = load_limits_file(path)
    data = doc.data
    if not isinstance(data, dict) or not isinstance(data.get("joint_limits"), dict):
        raise doc.fail(("joint_limits",), ": missing; expected a mapping of joint names to their limits")
    factors = {}
    for name in ("default_velocity_scaling_factor", "default_acceleration_scaling_factor"):
        factor = _number(doc, (name,), data.get(name, 1.0), positive=True)
        if factor > 1.0:
            raise doc.fail((name,), f" = {factor:g}: must be in (0, 1]")
        factors[name] = factor
    joints = {}
    for joint, entry in data["joint_limits"].items():
        where = ("joint_limits", joint)
        if not isinstance(entry, dict):
            raise doc.fail(where, f" = {echo(entry)}: expected a mapping of has_*_limits flags and values")
        joints[str(joint)] = _joint_entry(doc, where, entry)
    places = {name: doc.place(("joint_limits", name)) for name in joints}
    return MoveItJointLimits(joints, source=str(doc.file), places=places, **factors)


def _joint_entry(doc: LimitsDocument, where: Tuple[Any, ...], entry: Dict[Any, Any]) -> JointLimitEntry:
    """One joint's limits: the values its has_*_limits flags enable."""
    values: Dict[str, Optional[float]] = {}
    for flag, keys in _LIMIT_KEYS.items():
        if not _flag(doc, where + (flag,), entry.get(flag, False)):
            continue
        for key in keys:
            if key not in entry:
                raise doc.fail(where + (key,), f": missing although {flag} is true")
            values[key] = _number(doc, where + (key,), entry[key], positive=key not in ("min_position", "max_position"))
            if key not in ("min_position", "max_position"):
                _in_limit_range(doc, where + (key,), values[key])
    if values.get("min_position") is not None and not values["min_position"] < values["max_position"]:
        raise doc.fail(
            where + ("min_position",),
            f" = {values['min_position']:g}: must have min_position < max_position "
            f"(max_position = {values['max_position']:g})",
        )
    return JointLimitEntry(**values)


def apply_moveit_joint_limits(
    arm: Any, limits: Union[MoveItJointLimits, _PathLike]
) -> Tuple[Any, Optional[np.ndarray]]:
    """The arm with the file's velocity, effort and position limits replacing its URDF's (joints
    the file does not mention keep theirs), and the joint accelerations ((dof,) array, inf where
    a joint states none; None if no joint does) for ``retime(..., joint_acceleration=...)``.
    A joint of the file that the arm does not have is an error (a misspelt name would otherwise
    silently keep the URDF's limits)."""
    if not isinstance(limits, MoveItJointLimits):
        limits = read_moveit_joint_limits(limits)
    names = list(arm.joint_names)
    unknown = sorted(set(limits.joints) - set(names))
    if unknown:
        raise LimitsFileError(
            f"{limits.places.get(unknown[0], limits.source)}: joint_limits.{unknown[0]}: not a joint of the arm "
            f"(its joints: {', '.join(names)})"
        )
    current = arm.joint_limits
    lower, upper = np.array(current.lower, dtype=float), np.array(current.upper, dtype=float)
    velocity = np.array(current.velocity, dtype=float)
    effort = np.array(current.effort, dtype=float) if len(current.effort) else np.full(len(names), np.inf)
    acceleration = np.full(len(names), np.inf)
    for i, name in enumerate(names):
        entry = limits.joints.get(name)
        if entry is None:
            continue
        if entry.max_velocity is not None:
            velocity[i] = entry.max_velocity
        if entry.max_effort is not None:
            effort[i] = entry.max_effort
        if entry.min_position is not None:
            lower[i], upper[i] = entry.min_position, entry.max_position
        if entry.max_acceleration is not None:
            acceleration[i] = entry.max_acceleration
    updated = arm.with_joint_limits(lower=lower, upper=upper, velocity=velocity, effort=effort)
    return updated, (acceleration if np.isfinite(acceleration).any() else None)


@dataclasses.dataclass(frozen=True)
class PilzCartesianLimits:
    """The Pilz industrial motion planner's Cartesian limits: m/s, m/s², m/s² (negative), rad/s."""

    max_trans_vel: float
    max_trans_acc: float
    max_trans_dec: float
    max_rot_vel: float

    def limits(self, jerk: Optional[float] = None, angular: bool = True) -> Limits:
        """The DISP limits: velocity max_trans_vel, acceleration min(max_trans_acc, |max_trans_dec|)
        (dispkin's laws brake as hard as they accelerate), `jerk` for S-curves if given, and the
        angular velocity max_rot_vel unless `angular` is False (then add_rotation_sphere)."""
        acceleration = min(self.max_trans_acc, abs(self.max_trans_dec))
        return Limits(self.max_trans_vel, acceleration, jerk, angular_velocity=self.max_rot_vel if angular else None)

    @property
    def rotation_sphere_radius(self) -> float:
        """r = max_trans_vel / max_rot_vel (m): the sphere around the tool centre whose points move
        at max_trans_vel when the tool turns at max_rot_vel."""
        return self.max_trans_vel / self.max_rot_vel

    def add_rotation_sphere(self, metric_set: MetricSet, center: Any = (0.0, 0.0, 0.0)) -> None:
        """Adds that sphere (moving with the tool, centred at `center` in tool coordinates) to
        `metric_set`, so that its speed limit also keeps the angular speed ≤ max_rot_vel."""
        metric_set.add_sphere(center, self.rotation_sphere_radius)


def read_pilz_cartesian_limits(path: Union[_PathLike, LimitsDocument]) -> PilzCartesianLimits:
    """Reads cartesian_limits.yaml: the four values under ``cartesian_limits:`` (or at the top
    level, as in older files). max_trans_dec must be negative (a deceleration), the others > 0,
    and each within dispkin's numeric range of limits, [1e-12, 1e12] in magnitude."""
    doc = load_limits_file(path)
    data = doc.data
    prefix: Tuple[str, ...] = ()
    if isinstance(data, dict) and isinstance(data.get("cartesian_limits"), dict):
        data, prefix = data["cartesian_limits"], ("cartesian_limits",)
    if not isinstance(data, dict):
        raise doc.fail(
            ("cartesian_limits",), ": missing; expected max_trans_vel, max_trans_acc, max_trans_dec and max_rot_vel"
        )
    values = {}
    for key in ("max_trans_vel", "max_trans_acc", "max_trans_dec", "max_rot_vel"):
        if key not in data:
            raise doc.fail(prefix + (key,), ": missing")
        values[key] = _number(doc, prefix + (key,), data[key], positive=key != "max_trans_dec")
        if values[key] != 0:  # a deceleration of 0 is refused below, for what it is
            _in_limit_range(doc, prefix + (key,), values[key])
    if not values["max_trans_dec"] < 0:
        raise doc.fail(prefix + ("max_trans_dec",), f" = {values['max_trans_dec']:g}: must be < 0 (a deceleration)")
    return PilzCartesianLimits(**values)
