"""Sampling a planned job at its output period: the machine's joints (hexapod legs by inverse
kinematics, serial-arm joints along the branch followed from the start joints), their velocities,
accelerations and efforts, the commanded pose, the path velocity and the speed of the fastest
point of each metric-set group.

Joint velocities are analytic (the leg Jacobian, or the arm's body Jacobian solved for q-dot);
joint accelerations are central differences of those velocities over ACCELERATION_STEP; PTP
parts give their joint line's own q, q-dot and q-double-dot.
"""

import dataclasses
import math
from typing import Callable, Dict, List, Optional, Tuple, Union

import numpy as np

from .. import _core
from .._core import MetricSet, Pose, Trajectory, max_point_speed
from . import input_budget
from .model import Job, JobError
from .planning import JobTrajectory

#: Time step (s) of the central differences that give joint accelerations from joint velocities.
ACCELERATION_STEP = 1e-4

#: Samples between two progress reports.
_PROGRESS_CHUNK = 500

JointStates = Tuple[np.ndarray, np.ndarray, np.ndarray]


def sample_times(duration: float, period: float) -> np.ndarray:
    """0, period, 2 period, ... and the end `duration` itself (a last gap shorter than
    period / 1000 is merged into the end)."""
    count = int(math.floor(duration / period + 1e-9))
    times = np.arange(count + 1) * period
    if duration - times[-1] > period * 1e-3:
        times = np.append(times, duration)
    else:
        times[-1] = duration
    return times


@dataclasses.dataclass
class JobSamples:
    """The sampled trajectory of a job, row k at time[k]. Joint arrays are (N, dof) and empty
    (N, 0) without a machine; effort is (N, 0) for hexapods (no leg dynamics in the model)."""

    time: np.ndarray
    joint_names: List[str]
    #: Leg lengths (m) or joint values (rad / m).
    positions: np.ndarray
    #: Their time derivatives: analytic (leg Jacobian / body Jacobian times the body twist).
    velocities: np.ndarray
    #: Central differences of the analytic velocities over ACCELERATION_STEP.
    accelerations: np.ndarray
    #: Joint torques / forces (N·m, N) by recursive Newton–Euler for serial arms.
    effort: np.ndarray
    #: XYZUVW of the commanded pose (the tool frame in the work frame with frames, else the
    #: platform/flange pose): metres and DEGREES.
    xyzuvw: np.ndarray
    #: The same poses as (N, 7) rows x, y, z (m), qx, qy, qz, qw (a unit quaternion in ROS order).
    poses: np.ndarray
    #: Path velocity s-dot (m/s).
    path_velocity: np.ndarray
    #: Speed of the fastest point of the whole metric set (m/s, not scaled by group limits).
    fastest_point_speed: np.ndarray
    #: Per group: the speed of its fastest point (m/s).
    group_speeds: Dict[int, np.ndarray]


def group_sets(metric_set: MetricSet) -> Dict[int, MetricSet]:
    """Each group of the metric set on its own (group 0 in each, no speed limit)."""
    out = {}
    for group in metric_set.groups:
        one = MetricSet()
        relative, absolute = metric_set.relative_points(group), metric_set.absolute_points(group)
        if len(relative):
            one.add_relative(relative)
        if len(absolute):
            one.add_absolute(absolute)
        for center, radius, is_absolute in metric_set.spheres(group):
            one.add_sphere(center, radius, is_absolute)
        out[group] = one
    return out


def _leg_velocities(job: Job, poses: np.ndarray, twists: np.ndarray) -> np.ndarray:
    return np.array([job.hexapod.leg_jacobian(m) @ xi for m, xi in zip(poses, twists)])


def _cartesian_joint_states(
    job: Job, trajectory: Trajectory, t: np.ndarray, q_reference: Optional[np.ndarray]
) -> JointStates:
    """Joint positions, velocities and accelerations along a Cartesian trajectory at `t`."""
    if job.arm is not None and job.redundancy_rule is not None:
        # The redundancy parameter moved along the run: the joints of θ(s) with its own rates
        # (FollowedTrajectory, doc/inverse-kinematics.md §14), as the check and re-timing see them.
        try:
            followed = _core.FollowedTrajectory.from_start(
                trajectory, job.arm, q_reference, redundancy_rule=job.redundancy_rule
            )
        except (ValueError, RuntimeError) as error:
            raise JobError(f"{job.file}: the serial arm cannot follow the trajectory: {error}") from error
        return followed.joint_positions(t), followed.joint_velocities(t), followed.joint_accelerations(t)
    if job.arm is not None:
        # The branch followed from q_reference, q-dot by the body Jacobian, q-double-dot by central
        # differences of q-dot, each neighbour on its sample's branch (SerialArm.follow_trajectory).
        try:
            states = job.arm.follow_trajectory(trajectory, t, q_reference, ACCELERATION_STEP)
        except (ValueError, RuntimeError) as error:
            raise JobError(f"{job.file}: the serial arm cannot follow the trajectory: {error}") from error
        return tuple(np.asarray(x) for x in states)
    poses, twists = np.asarray(trajectory.sample(t)), np.asarray(trajectory.body_twist(t))
    positions = np.asarray(job.hexapod.inverse(poses))
    velocities = _leg_velocities(job, poses, twists)
    # Accelerations: central differences of the analytic velocity, one-sided at the ends.
    before, after = np.maximum(t - ACCELERATION_STEP, 0.0), np.minimum(t + ACCELERATION_STEP, trajectory.duration)
    rates = [
        _leg_velocities(job, np.asarray(trajectory.sample(times)), np.asarray(trajectory.body_twist(times)))
        for times in (before, after)
    ]
    accelerations = (rates[1] - rates[0]) / (after - before)[:, None]
    return positions, velocities, accelerations


def _joint_states_of_parts(job: Job, trajectory: JobTrajectory, t: np.ndarray) -> JointStates:
    """Joint positions, velocities and accelerations of a job with PTP moves at `t`: a PTP part
    gives its joint line's own, a Cartesian run follows the branch from the joints at its start."""
    n, dof = len(t), job.arm.dof
    positions, velocities, accelerations = np.zeros((n, dof)), np.zeros((n, dof)), np.zeros((n, dof))
    which = trajectory.part_indices(t)
    for k, (part, traj) in enumerate(trajectory.parts):
        mask = which == k
        if not np.any(mask):
            continue
        local = np.clip(t[mask] - trajectory.start_times[k], 0.0, traj.duration)
        if part.kind == "ptp":
            states = (traj.joint_positions(local), traj.joint_velocities(local), traj.joint_accelerations(local))
        else:
            states = _cartesian_joint_states(job, traj, local, part.q_start)
        positions[mask], velocities[mask], accelerations[mask] = states
    return positions, velocities, accelerations


def _joint_samples(job: Job, trajectory: Union[Trajectory, JobTrajectory], t: np.ndarray) -> Tuple[np.ndarray, ...]:
    """(positions, velocities, accelerations, effort) of the machine's joints at `t`."""
    n = len(t)
    if job.machine == "none":
        empty = np.zeros((n, 0))
        return empty, empty, empty, empty
    if isinstance(trajectory, JobTrajectory):
        positions, velocities, accelerations = _joint_states_of_parts(job, trajectory, t)
    else:
        positions, velocities, accelerations = _cartesian_joint_states(
            job, trajectory, t, job.q_start if job.arm is not None else None
        )
    if job.arm is not None:
        effort = np.array([job.arm.torques(q, qd, qdd) for q, qd, qdd in zip(positions, velocities, accelerations)])
    else:
        effort = np.zeros((n, 0))
    return positions, velocities, accelerations, effort


def sample_job(
    job: Job,
    trajectory: Union[Trajectory, JobTrajectory],
    period: Optional[float] = None,
    progress: Optional[Callable[[str, int, int], None]] = None,
) -> JobSamples:
    """Sample the job's trajectory every `period` seconds (default: the job's sample_period).
    PTP moves give their joints directly (q, q-dot, q-double-dot of the joint line); Cartesian
    moves follow the inverse-kinematics branch continuous from the joints at their start.
    `progress(stage, done, total)` is called as the samples are worked through."""
    report = progress or (lambda stage, done, total: None)
    period = period or job.sample_period
    count = trajectory.duration / period
    if not count <= input_budget.MAX_SAMPLES:
        message = (
            f"{period!r}: the {trajectory.duration:g} s trajectory would be {count:.3g} samples, more than "
            f"{input_budget.MAX_SAMPLES} (doc/input-budget.md)"
        )
        if job.source is not None:
            raise job.source.error(("output", "sample_period"), message)
        raise JobError(f"{job.file}: output.sample_period: {message}")
    t = sample_times(trajectory.duration, period)
    poses, twists = np.asarray(trajectory.sample(t)), np.asarray(trajectory.body_twist(t))
    report("joints", 0, len(t))
    positions, velocities, accelerations, effort = _joint_samples(job, trajectory, t)
    report("joints", len(t), len(t))
    commanded = [Pose.from_matrix(m) for m in poses]
    if job.frames is not None:
        xyzuvw = np.array([job.frames.xyzuvw(p) for p in commanded])
        commanded = [job.frames.tool_in_work(p) for p in commanded]
    else:
        xyzuvw = np.array([p.to_xyzuvw() for p in commanded])
    xyzuvw[:, 3:] = np.degrees(xyzuvw[:, 3:])
    # (w, x, y, z) -> ROS order (x, y, z, w).
    quaternions = np.array([p.quaternion for p in commanded])[:, [1, 2, 3, 0]]
    positions_xyz = np.array([p.translation for p in commanded])
    groups = group_sets(job.metric_set)
    group_speeds = {group: np.zeros(len(t)) for group in groups}
    for start in range(0, len(t), _PROGRESS_CHUNK):
        chunk = range(start, min(start + _PROGRESS_CHUNK, len(t)))
        for group, one in groups.items():
            group_speeds[group][chunk.start : chunk.stop] = [
                max_point_speed(one, Pose.from_matrix(poses[k]), twists[k]) for k in chunk
            ]
        report("point speeds", chunk.stop, len(t))
    fastest = np.max(np.vstack(list(group_speeds.values())), axis=0)
    return JobSamples(
        t,
        job.joint_names,
        positions,
        velocities,
        accelerations,
        effort,
        xyzuvw,
        np.hstack([positions_xyz, quaternions]),
        np.asarray(trajectory.path_velocity(t)),
        fastest,
        group_speeds,
    )
