"""Planning a job: one Trajectory for a job of Cartesian moves, or a :class:`JobTrajectory` of
parts planned one after the other when the job has PTP moves.

A PTP move starts and ends at rest, so a job with PTP moves is planned part by part (each
Cartesian run as one path, each PTP move on the arm) and the parts join at rest; see
``doc/planning.md`` and ``doc/ptp.md``.
"""

from typing import Any, List, Optional, Tuple, Union

import numpy as np

from .. import _core
from .._core import Path, Trajectory, plan
from .events import apply_events
from .model import Job, JobError, Part


class JobTrajectory:
    """A job's trajectory when it has PTP moves: its parts (Cartesian runs planned as one
    Trajectory, PTP moves as a JointTrajectory) one after the other in time; every PTP move
    starts and ends at rest, so the parts join at rest. Samples like a Trajectory (poses, body
    twists, s-dot; s counts on across the parts)."""

    def __init__(self, parts: List[Tuple[Part, Any]]):
        #: (Part, its Trajectory or JointTrajectory), in order.
        self.parts = parts
        durations = [float(t.duration) for _, t in parts]
        #: When each part starts (s).
        self.start_times = np.concatenate([[0.0], np.cumsum(durations)[:-1]])
        lengths = [float(t.length) for _, t in parts]
        self._start_s = np.concatenate([[0.0], np.cumsum(lengths)[:-1]])
        #: Seconds.
        self.duration = float(np.sum(durations))
        #: The DISP arc length of all parts, m.
        self.length = float(np.sum(lengths))
        #: Rest-to-rest pieces: a Cartesian run's own, one per PTP move.
        self.piece_count = int(sum(t.piece_count if p.kind == "path" else 1 for p, t in parts))

    def part_indices(self, times: np.ndarray) -> np.ndarray:
        """The part each time belongs to (a time on a junction: the later part, both at rest there)."""
        t = np.clip(np.atleast_1d(np.asarray(times, dtype=float)), 0.0, self.duration)
        return np.clip(np.searchsorted(self.start_times, t, side="right") - 1, 0, len(self.parts) - 1)

    def _gather(self, times: Any, method: str, tail: Tuple[int, ...]) -> np.ndarray:
        t = np.clip(np.atleast_1d(np.asarray(times, dtype=float)), 0.0, self.duration)
        which = self.part_indices(t)
        out = np.zeros((len(t),) + tail)
        for k, (_, traj) in enumerate(self.parts):
            mask = which == k
            if np.any(mask):
                out[mask] = np.asarray(getattr(traj, method)(t[mask] - self.start_times[k])).reshape((-1,) + tail)
        return out

    def sample(self, times: Any) -> np.ndarray:
        """Poses at `times`, (N, 4, 4)."""
        return self._gather(times, "sample", (4, 4))

    def sample_xyzuvw(self, times: Any) -> np.ndarray:
        """Poses at `times`, (N, 6) XYZUVW (m, radians)."""
        return self._gather(times, "sample_xyzuvw", (6,))

    def body_twist(self, times: Any) -> np.ndarray:
        """Body twists (v, omega) at `times`, (N, 6)."""
        return self._gather(times, "body_twist", (6,))

    def path_velocity(self, times: Any) -> np.ndarray:
        """s-dot at `times`, (N,), m/s."""
        return self._gather(times, "path_velocity", ())

    def path_position(self, times: Any) -> np.ndarray:
        """s at `times`, (N,), m, counted from the job's start."""
        t = np.atleast_1d(np.asarray(times, dtype=float))
        return self._gather(t, "path_position", ()) + self._start_s[self.part_indices(t)]


def plan_run(job: Job, path: Path, q_start: Optional[np.ndarray]) -> Trajectory:
    """A Cartesian run planned under the DISP limits, then re-timed to the joint limits if the
    job asks (dispkin.retime: the arm from the joints at the run's start, or the hexapod)."""
    if job.retime is None:
        joint_metric = job.hexapod if job.joint_metric else None
        return plan(
            path,
            job.metric_set,
            job.limits,
            job.profile,
            joint_metric=joint_metric,
            corner_tolerance=job.corner_tolerance,
        )
    extra = {"corner_tolerance": job.corner_tolerance}
    if job.retime.joint_acceleration is not None:
        extra["joint_acceleration"] = job.retime.joint_acceleration
    if job.arm is not None:
        if job.redundancy_rule is not None:
            extra["redundancy_rule"] = job.redundancy_rule
        result = _core.retime(
            path, job.metric_set, job.limits, job.arm, q_start, profile=job.profile, method=job.retime.method, **extra
        )
    else:
        result = _core.retime(
            path, job.metric_set, job.limits, job.hexapod, profile=job.profile, method="optimal", **extra
        )
    return result.trajectory


def plan_job(job: Job) -> Union[Trajectory, JobTrajectory]:
    """The job's trajectory: plan(job.path, job.metric_set, job.limits, job.profile), with the
    hexapod as joint metric when the job asks for rule (b), re-timed to the joint limits when
    it has a `retime` section, and with the job's events (stops, resumptions, speed overrides)
    applied in time order. A job with PTP moves is planned part by part (a JobTrajectory):
    each Cartesian run as one path, each PTP move on the arm (within its joint velocity limits)."""
    if not job.has_ptp:
        part = job.parts[0] if job.parts else None
        if part is not None and part.trajectory is not None:
            # A run planned while the job was read (MoveSequence.planned_end) keeps that plan.
            return apply_events(job, part.trajectory)
        planned = _planned(job, part, lambda: plan_run(job, job.path, job.q_start))
        return apply_events(job, planned)
    planned = []
    for part in job.parts:
        if part.kind == "ptp":
            planned.append(
                (
                    part,
                    _planned(
                        job, part, lambda: plan(part.path, job.metric_set, job.limits, job.profile, robot=job.arm)
                    ),
                )
            )
        elif part.trajectory is not None:
            # A run planned while the job was built (MoveSequence.planned_end) keeps that plan.
            planned.append((part, part.trajectory))
        else:
            planned.append((part, _planned(job, part, lambda: plan_run(job, part.path, part.q_start))))
    return JobTrajectory(planned)


def _planned(job: Job, part: Optional[Part], planner: Any) -> Any:
    """planner(), its ValueError / RuntimeError re-raised as a JobError at the job's key it
    comes from (see _failed_at)."""
    try:
        return planner()
    except (ValueError, RuntimeError) as error:
        at, value = _failed_at(job, part)
        message = (
            f"{value!r}: the blend has no length to plan (planning failed: {error}); give a larger one"
            if value is not None
            else f"planning failed: {error}"
        )
        if job.source is None or not at:
            raise JobError(f"{job.file}: planning failed: {error}") from error
        raise job.source.error(at, message) from error


def _failed_at(job: Job, part: Optional[Part]) -> Tuple[Tuple[Any, ...], Any]:
    """(the key path, the value there if it is a blend) of what made planning `part` fail: the
    blend of a section without length (too small for its sub-points to part from the corner),
    else the `retime` section when the part is re-timed, else the part's first move."""
    if part is None:
        return (), None
    if part.kind == "path":
        blend = _empty_blend(job, part)
        if blend is not None:
            return blend
        if job.retime is not None:
            return ("retime",), None
    return ("moves", part.moves[0]), None


def _empty_blend(job: Job, part: Part) -> Optional[Tuple[Tuple[Any, ...], Any]]:
    """(moves[i].blend_weight or .blend, its value) of the first blend section of the part
    without a positive length; None if every section has one."""
    try:
        lengths = np.asarray(part.path.section_lengths(job.metric_set, job.limits.velocity))
    except (ValueError, RuntimeError):  # then not for want of a length
        return None
    empty = np.flatnonzero(~(np.isfinite(lengths) & (lengths > 0.0)))
    if not empty.size:
        return None
    starts = list(part.path.move_starts)
    # A blend's sections end the range of the move before the one that asks for it.
    k = int(np.searchsorted(starts, int(empty[0]), side="right")) - 1
    if k + 1 >= len(part.moves):
        return None
    move = job.moves[part.moves[k + 1]]
    if move.blend_weight is not None:
        return ("moves", part.moves[k + 1], "blend_weight"), move.blend_weight
    if move.blend is not None:
        return ("moves", part.moves[k + 1], "blend"), move.blend
    return None
