"""The job model: a job file built into the library's objects (:class:`Job`, its :class:`Move`
and :class:`Part` lists), and :class:`JobError`, the error every mistake in a job raises.

Key paths name a place in the job's data, as a tuple of mapping keys and list indices:
``('moves', 2, 'lin', 'to')``, written ``moves[2].lin.to`` in messages.
"""

import dataclasses
import pathlib
from typing import Any, Dict, List, Optional, Sequence, Tuple, Union

import numpy as np

from .._core import Hexapod, JointPath, Limits, MetricSet, Path, WorkToolFrames

#: Default sample period of the output (s).
DEFAULT_SAMPLE_PERIOD = 0.01

KeyPath = Tuple[Union[str, int], ...]


class JobError(ValueError):
    """A job file that cannot be read, validated, built or planned; the message points at the
    offending key (``key.path[index]``) and, when known, its line and column in the file."""

    def __init__(self, message: str, key_path: KeyPath = (), line: Optional[int] = None):
        super().__init__(message)
        #: The offending key as a tuple of mapping keys and list indices (empty: the whole job).
        self.key_path = tuple(key_path)
        #: 1-based line of the key in the job file, when known.
        self.line = line


def format_key_path(key_path: Sequence[Union[str, int]]) -> str:
    """``('moves', 2, 'lin', 'to')`` -> ``moves[2].lin.to``; the empty path is ``(job)``."""
    text = ""
    for key in key_path:
        text += f"[{key}]" if isinstance(key, int) else (f".{key}" if text else str(key))
    return text or "(job)"


def value_at(data: Any, key_path: KeyPath) -> Any:
    """The value of the job's data at key_path (which must be there)."""
    for key in key_path:
        data = data[key]
    return data


@dataclasses.dataclass
class Move:
    """One move of a job as built: its kind, its Path (a JointPath for a PTP move), the blend
    with the previous move (m, or as the share `blend_weight` of both moves) and how that blend
    turns the tool (`orientation_blend`: rotation_vector or nested_slerp)."""

    kind: str
    path: Union[Path, JointPath]
    blend: Optional[float]
    blend_weight: Optional[float] = None
    orientation_blend: str = "rotation_vector"

    def blend_text(self) -> str:
        """The blend in words ('' without one), e.g. 'blend 0.02 m' or 'blend 0.3 of each move, nested SLERP'."""
        if self.blend is None and self.blend_weight is None:
            return ""
        size = f"blend {self.blend:g} m" if self.blend is not None else f"blend {self.blend_weight:g} of each move"
        return size + (", nested SLERP" if self.orientation_blend == "nested_slerp" else "")


@dataclasses.dataclass
class Part:
    """A stretch of a job planned as one: a run of Cartesian moves (lin, circ, spline) joined
    into one Path, or one PTP move (a JointPath, at rest at both ends)."""

    #: "path" or "ptp".
    kind: str
    path: Union[Path, JointPath]
    #: The arm's joints at the part's start (serial-arm jobs; None otherwise).
    q_start: Optional[np.ndarray]
    #: Indices of its moves in Job.moves.
    moves: List[int]
    #: A Cartesian run planned while the job was built (its Trajectory): a run that moves a
    #: seven-joint arm's redundancy parameter, whose end (where a PTP move after it starts) is
    #: where θ(s) of the planned path ends (doc/inverse-kinematics.md §14); None: planned with the job.
    trajectory: Optional[Any] = None


@dataclasses.dataclass
class Retime:
    """The job's `retime` section: after planning under the DISP limits, re-time the Cartesian
    moves so that the machine keeps its joint limits (``dispkin.retime``)."""

    #: "scaling" (the KUKA re-timing patent's loop; serial arms) or "optimal".
    method: str
    #: Joint acceleration limits for the optimal method ((dof,), inf where none), or None.
    joint_acceleration: Optional[np.ndarray] = None


@dataclasses.dataclass
class Event:
    """One entry of the job's `events`: at `at` seconds of the motion, a stop on the path
    (Trajectory.stopped_at), a resumption of the stopped motion (resumed_at) or a speed
    override (with_override) of `factor` times the velocity-limit curve as planned."""

    #: Seconds from the start of the motion, on the clock of the events before it.
    at: float
    #: "stop", "resume" or "override".
    kind: str
    #: The override factor (None for a stop or a resumption).
    factor: Optional[float]
    #: Its index in the job's `events` list (the key path of messages is ("events", index)).
    index: int


@dataclasses.dataclass
class Job:
    """A validated job, built into the library's objects (see :func:`dispkin.jobs.load_job`)."""

    #: The job file.
    file: pathlib.Path
    #: The job's name (default: the file's stem).
    name: str
    #: The points whose speed is limited, including a hexapod's leg group (rule (a)).
    metric_set: MetricSet
    #: The moves joined into one path (platform / flange poses in base coordinates); None when
    #: the job has PTP moves (then see `parts`).
    path: Optional[Path]
    #: The moves one by one.
    moves: List[Move]
    limits: Limits
    #: "scurve" or "trapezoid".
    profile: str
    #: The point of the platform/flange (its coordinates, m) that moves on lines and arcs.
    pivot: np.ndarray
    frames: Optional[WorkToolFrames] = None
    hexapod: Optional[Hexapod] = None
    #: Rule (b): plan with the hexapod as joint metric.
    joint_metric: bool = False
    #: Rule (a): the metric-set group holding the upper leg joints to the leg speed.
    leg_speed_group: Optional[int] = None
    arm: Optional[Any] = None
    q_start: Optional[np.ndarray] = None
    #: A seven-joint arm's redundancy parameter moved along the Cartesian runs (``redundancy: moved``):
    #: the RedundancyRule the followers take; None: held at its value where each run starts.
    redundancy_rule: Optional[Any] = None
    #: Output period (s) and file names (relative to the output directory).
    sample_period: float = DEFAULT_SAMPLE_PERIOD
    outputs: Dict[str, str] = dataclasses.field(default_factory=dict)
    #: The job in stretches planned as one: Cartesian runs and PTP moves, in order.
    parts: List[Part] = dataclasses.field(default_factory=list)
    #: limits.corner_tolerance (m): corners blended within it (0: every corner stops).
    corner_tolerance: float = 0.0
    #: Re-timing against the joint limits (None: the DISP limits only).
    retime: Optional[Retime] = None
    #: Joint acceleration limits ((dof,), inf where none) from a MoveIt limits file or
    #: retime.joint_acceleration; None when no joint has one. The written joint accelerations
    #: are checked against them.
    joint_acceleration: Optional[np.ndarray] = None
    #: The limits files read (MoveIt joint_limits.yaml, Pilz cartesian_limits.yaml).
    limits_files: List[pathlib.Path] = dataclasses.field(default_factory=list)
    #: Where a serial arm's joint limits come from: "URDF", or "MoveIt <file name>".
    joint_limits_from: str = "URDF"
    #: The job file as read (dispkin.job.reader.Source): where a key is, for later messages.
    source: Optional[Any] = None
    #: The files the job reads besides itself: URDF, hexapod file, limits files (never written).
    inputs: List[pathlib.Path] = dataclasses.field(default_factory=list)
    #: Stops, resumptions and speed overrides applied, in time order, to the planned
    #: Cartesian trajectory (doc/events.md); empty: the trajectory as planned.
    events: List[Event] = dataclasses.field(default_factory=list)

    @property
    def has_ptp(self) -> bool:
        """Whether a move is a PTP move (the job is then planned part by part)."""
        return any(part.kind == "ptp" for part in self.parts)

    @property
    def machine(self) -> str:
        """ "hexapod", "serial_arm" or "none"."""
        return "hexapod" if self.hexapod is not None else "serial_arm" if self.arm is not None else "none"

    @property
    def joint_names(self) -> List[str]:
        """The joints of the output: the legs, the arm's joints, or none."""
        if self.hexapod is not None:
            return list(self.hexapod.joint_names)
        if self.arm is not None:
            return list(self.arm.joint_names)
        return []
