"""The machine limits a planned job breaks: which limit, of which joint (a serial arm's joint or
a hexapod's leg), when, and by how much.

The written samples are checked joint by joint against the machine's limits: positions against
the range (a hexapod's leg_min .. leg_max, an arm's URDF or MoveIt position limits), velocities
against the velocity limits (leg_speed, the URDF's or MoveIt's), accelerations against the joint
accelerations of a MoveIt file or of `retime`, and a serial arm's efforts against its effort
limits. A dense check between the samples adds what falls between two samples: the same four
kinds of limits at the re-timing's check points (every characteristic point of the time laws
and ten points between two of them, :func:`dispkin.check_joint_limits`; a PTP move every
millisecond), and a hexapod's leg lengths and speeds every millisecond.

The summary's verdicts ("within limits") and the exit status of ``dispkin plan`` are both read
from the one list of violations this gives: ``dispkin plan`` fails (exit status 3) when it is
not empty, unless ``--allow-violations``.
"""

import dataclasses
import math
from typing import Any, Dict, List, Optional, Union

import numpy as np

from .model import Job
from .sampling import JobSamples

#: A value counts as beyond its limit when it exceeds it by more than this fraction of the limit
#: (of the range for positions): re-timed trajectories run at their limits, up to rounding.
TOLERANCE = 1e-6

#: The kinds of limits, in the order they are reported.
KINDS = ("position", "velocity", "acceleration", "effort")


@dataclasses.dataclass(frozen=True)
class Violation:
    """One joint beyond one of its limits: the worst value, when, and the span of time it is beyond."""

    #: "position", "velocity", "acceleration" or "effort".
    kind: str
    #: The joint (serial arm) or leg (hexapod).
    joint: str
    #: The worst value (signed; velocities, accelerations and efforts are limited in magnitude).
    value: float
    #: The limit it breaks: the bound of the range it left (position) or the magnitude limit.
    limit: float
    #: When the worst value is reached (s).
    time: float
    #: Index of that written sample; None when only the dense check between samples found it.
    sample: Optional[int]
    #: First and last time beyond the limit (s).
    start_time: float
    end_time: float
    #: Unit of value and limit.
    unit: str

    @property
    def excess(self) -> float:
        """How far beyond the limit, > 0 (same unit)."""
        if self.kind == "position":
            return self.value - self.limit if self.value > self.limit else self.limit - self.value
        return abs(self.value) - self.limit

    def describe(self) -> str:
        """One line: which limit, of which joint, when, by how much."""
        where = f"t = {self.time:.4f} s" + (
            f" (sample {self.sample})" if self.sample is not None else " (between samples)"
        )
        span = (
            f", beyond from {self.start_time:.4f} s to {self.end_time:.4f} s" if self.end_time > self.start_time else ""
        )
        ratio = f", {abs(self.value) / self.limit:.3g}x the limit" if self.kind != "position" else ""
        bound = ("upper" if self.value > self.limit else "lower") + " limit" if self.kind == "position" else "limit"
        return (
            f"{self.kind} of {self.joint}: {self.value:.6g} {self.unit} at {where}, {bound} {self.limit:.6g} {self.unit}: "
            f"beyond by {self.excess:.6g} {self.unit}{ratio}{span}"
        )

    def as_dict(self) -> Dict[str, Any]:
        """The fields and the excess, for the JSON summary."""
        return {**dataclasses.asdict(self), "excess": self.excess}


@dataclasses.dataclass
class _JointLimits:
    names: List[str]
    lower: np.ndarray
    upper: np.ndarray
    velocity: np.ndarray
    acceleration: np.ndarray
    effort: np.ndarray
    units: Dict[str, str]


def _limits_of(job: Job) -> Optional[_JointLimits]:
    """The machine's joint limits, inf where a joint has none; None without a machine."""
    n = len(job.joint_names)
    acceleration = (
        np.asarray(job.joint_acceleration, dtype=float) if job.joint_acceleration is not None else np.full(n, np.inf)
    )
    if job.hexapod is not None:
        h = job.hexapod
        return _JointLimits(
            job.joint_names,
            np.asarray(h.leg_min),
            np.asarray(h.leg_max),
            np.asarray(h.leg_speed),
            acceleration,
            np.full(n, np.inf),
            {"position": "m", "velocity": "m/s", "acceleration": "m/s²", "effort": "N"},
        )
    if job.arm is not None:
        lim = job.arm.joint_limits
        effort = np.asarray(lim.effort, dtype=float) if len(lim.effort) else np.full(n, np.inf)
        return _JointLimits(
            job.joint_names,
            np.asarray(lim.lower),
            np.asarray(lim.upper),
            np.asarray(lim.velocity),
            acceleration,
            effort,
            {"position": "rad", "velocity": "rad/s", "acceleration": "rad/s²", "effort": "N·m"},
        )
    return None


def _violation(
    kind: str,
    joint: str,
    values: np.ndarray,
    beyond: np.ndarray,
    excess: np.ndarray,
    limit: Any,
    time: np.ndarray,
    unit: str,
) -> Violation:
    """The violation of one joint's samples `beyond` its limit (excess: how far, per sample)."""
    worst = int(np.argmax(np.where(beyond, excess, -np.inf)))
    bound = limit(values[worst]) if callable(limit) else float(limit)
    span = time[beyond]
    return Violation(
        kind, joint, float(values[worst]), bound, float(time[worst]), worst, float(span[0]), float(span[-1]), unit
    )


@dataclasses.dataclass
class JointStates:
    """The machine's joints at the instants of a dense check, row k at time[k]: the arrays of
    :class:`~dispkin.job.sampling.JobSamples` that :func:`check_samples` reads (effort (N, 0)
    without a dynamics model)."""

    time: np.ndarray
    positions: np.ndarray
    velocities: np.ndarray
    accelerations: np.ndarray
    effort: np.ndarray


def check_samples(job: Job, samples: Union[JobSamples, JointStates]) -> List[Violation]:
    """Every (limit, joint) the written samples break, one Violation each (its worst sample)."""
    lim = _limits_of(job)
    if lim is None:
        return []
    found = []
    t = samples.time
    for k, name in enumerate(lim.names):
        q = samples.positions[:, k]
        lower, upper = float(lim.lower[k]), float(lim.upper[k])
        width = upper - lower if math.isfinite(upper - lower) else 1.0
        excess = np.maximum(q - upper, lower - q)
        beyond = excess > TOLERANCE * width
        if np.any(beyond):
            found.append(
                _violation(
                    "position",
                    name,
                    q,
                    beyond,
                    excess,
                    lambda v, lo=lower, up=upper: up if v > up else lo,
                    t,
                    lim.units["position"],
                )
            )
        for kind, values, bounds in (
            ("velocity", samples.velocities, lim.velocity),
            ("acceleration", samples.accelerations, lim.acceleration),
            ("effort", samples.effort, lim.effort),
        ):
            bound = float(bounds[k])
            if not math.isfinite(bound) or values.shape[1] == 0:
                continue
            excess = np.abs(values[:, k]) - bound
            beyond = excess > TOLERANCE * bound
            if np.any(beyond):
                found.append(_violation(kind, name, values[:, k], beyond, excess, bound, t, lim.units[kind]))
    return found


def check_between_samples(job: Job, states: JointStates) -> List[Violation]:
    """Every (limit, joint) the joint states of a dense check break, its worst instant marked as
    between samples (sample None)."""
    return [dataclasses.replace(v, sample=None) for v in check_samples(job, states)]


def worst_per_joint(violations: List[Violation]) -> List[Violation]:
    """The worst violation of each (kind, joint), in the order they first appear."""
    worst: Dict[Any, Violation] = {}
    for v in violations:
        key = (v.kind, v.joint)
        if key not in worst or v.excess > worst[key].excess:
            worst[key] = v
    return list(worst.values())


def between_samples(found: List[Violation], dense: List[Violation]) -> List[Violation]:
    """`found` and the worst violation of each (kind, joint) of the dense checks that no
    sample showed."""
    seen = {(v.kind, v.joint) for v in found}
    return found + worst_per_joint([v for v in dense if (v.kind, v.joint) not in seen])


def hexapod_excursions(job: Job, check: Any) -> List[Violation]:
    """A hexapod's TrajectoryCheck excursions as violations (sample None: between samples)."""
    names = job.joint_names
    out = []
    for e in check.excursions:
        leg = names[e.leg]
        if e.kind == "length":
            limit = (
                float(job.hexapod.leg_max[e.leg])
                if e.worst_value > job.hexapod.leg_max[e.leg]
                else float(job.hexapod.leg_min[e.leg])
            )
            kind, unit = "position", "m"
        else:
            limit, kind, unit = float(job.hexapod.leg_speed[e.leg]), "velocity", "m/s"
        violation = Violation(
            kind,
            leg,
            float(e.worst_value),
            limit,
            float(e.worst_time),
            None,
            float(e.start_time),
            float(e.end_time),
            unit,
        )
        if violation.excess > TOLERANCE * (
            limit if kind == "velocity" else float(job.hexapod.leg_max[e.leg] - job.hexapod.leg_min[e.leg])
        ):
            out.append(violation)
    return out
