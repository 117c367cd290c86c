"""The summary of a planned job: its duration and length, where the motion ends (the end of
its path, or where a stop among its events left it), each metric-set group's peak point speed
against its limit, the machine's own limits (hexapod legs, serial-arm joint velocities and
efforts from the URDF or a MoveIt file), the limits the trajectory breaks (see
:mod:`~dispkin.job.violations`), the events applied (see :mod:`~dispkin.job.events`), and which
limit binds — never one that is broken; :func:`summary_text` is what ``dispkin plan`` prints.
"""

import math
from typing import Any, Dict, List, Optional, Tuple, Union

import numpy as np

from .. import _core
from .._core import Trajectory
from .events import describe_events, end_of_motion, event_text
from .model import Job
from .planning import JobTrajectory
from .sampling import JobSamples
from .violations import (
    TOLERANCE,
    JointStates,
    Violation,
    between_samples,
    check_between_samples,
    check_samples,
    hexapod_excursions,
    worst_per_joint,
)

#: A limit counts as binding when the trajectory reaches this fraction of it.
BINDING_FRACTION = 0.99

#: Sample step (s) of a PTP move's joint line when its joint-limit factors are measured.
_PTP_CHECK_STEP = 1e-3


def summarize(job: Job, trajectory: Union[Trajectory, JobTrajectory], samples: JobSamples) -> Dict[str, Any]:
    """Duration, where the motion ends, per-group peak point speed against its limit, the
    machine's own limits, the events applied, and which limit binds (the highest ratio
    peak / limit, if it reaches BINDING_FRACTION)."""
    v = job.limits.velocity
    ratios: Dict[str, float] = {}
    groups = {}
    for group, speeds in samples.group_speeds.items():
        limit = job.metric_set.group_speed(group) or v
        k = int(np.argmax(speeds))
        groups[str(group)] = {
            "peak_speed": float(speeds[k]),
            "time": float(samples.time[k]),
            "limit": float(limit),
            "ratio": float(speeds[k] / limit),
        }
        ratios[f"speed of group {group} ({limit:g} m/s)"] = float(speeds[k] / limit)
    end_position, completed = end_of_motion(trajectory)
    summary: Dict[str, Any] = {
        "job": job.name,
        "machine": job.machine,
        "moves": [m.kind + (f" ({m.blend_text()})" if m.blend_text() else "") for m in job.moves],
        "duration": float(trajectory.duration),
        "length": float(trajectory.length),
        # Where the motion ends (m of DISP arc length) and whether that is the end of the path: a
        # stop among the events may leave it at rest before.
        "end_position": end_position,
        "completed": completed,
        "rest_to_rest_pieces": int(trajectory.piece_count),
        "profile": job.profile,
        "limits": {
            "velocity": v,
            "acceleration": job.limits.acceleration,
            "jerk": job.limits.jerk,
            "angular_velocity": job.limits.angular_velocity,
            "angular_acceleration": job.limits.angular_acceleration,
            "corner_tolerance": job.corner_tolerance,
        },
        # Where a Cartesian run comes to rest inside the path, and why (corners not blended).
        # (Not those beyond where a stop among the events leaves the motion: it never gets there.)
        "stops": [
            {"s": float(s), "reason": reason}
            for s, reason in getattr(trajectory, "stops", [])
            if s <= end_position + 1e-9 * float(trajectory.length)
        ],
        # The job's stops, resumptions and speed overrides, in the order applied.
        "events": describe_events(job, trajectory),
        "sample_period": float(job.sample_period),
        "samples": int(len(samples.time)),
        "peak_path_velocity": float(np.max(samples.path_velocity)),
        "groups": groups,
    }
    violations = check_samples(job, samples)
    if job.hexapod is not None:
        summary["legs"], ratios["leg speed"], dense = _leg_report(job, trajectory)
        violations = between_samples(violations, dense)
    if job.arm is not None:
        summary["joints"], dense = _joint_report(job, trajectory)
        violations = between_samples(violations, dense)
        source = summary["joints"]["limits_from"] = job.joint_limits_from
        ratios[f"joint velocity ({source})"] = summary["joints"]["velocity_factor"]
        if summary["joints"]["acceleration_factor"] is not None:
            ratios[f"joint effort ({source})"] = summary["joints"]["acceleration_factor"]
    summary["violations"] = [broken.as_dict() for broken in violations]
    # One verdict, from the samples and the dense checks alike: the summary's lines, its JSON
    # and the exit status of `dispkin plan` all read it, so they cannot disagree.
    summary["within_machine_limits"] = not violations
    for machine in ("legs", "joints"):
        if machine in summary:
            summary[machine]["within_limits"] = not violations
    name, ratio = max(ratios.items(), key=lambda item: item[1])
    summary["highest_ratio"] = {"limit": name, "ratio": ratio}
    summary["binding"] = _binding(ratios, violations)
    return summary


def _binding(ratios: Dict[str, float], violations: List[Violation]) -> str:
    """The limit the trajectory runs at: the highest ratio that reaches BINDING_FRACTION without
    going beyond the limit. A broken limit does not bind the trajectory: then none does."""
    if violations:
        return "none: the trajectory breaks limits (" + ", ".join(f"{x.kind} of {x.joint}" for x in violations) + ")"
    kept = {k: r for k, r in ratios.items() if r <= 1.0 + TOLERANCE}
    name, ratio = max(kept.items(), key=lambda item: item[1], default=("", 0.0))
    if ratio >= BINDING_FRACTION:
        return name
    return "acceleration / jerk of the path (no speed limit is reached: the moves are too short to cruise)"


def _leg_report(job: Job, trajectory: Trajectory) -> Tuple[Dict[str, Any], float, List[Violation]]:
    """(the hexapod's leg lengths and speeds against its limits, the fastest leg's ratio to its
    speed limit, what the dense checks between samples find broken): leg lengths and speeds from
    a check at the sample period or 1 ms, whichever is finer; every limit, leg accelerations
    included, at the check points of check_joint_limits."""
    check = job.hexapod.check_trajectory(trajectory, min(job.sample_period, 1e-3))
    leg_ratio = float(np.max(check.max_speed / job.hexapod.leg_speed))
    legs = {
        "min_length": check.min_length.tolist(),
        "max_length": check.max_length.tolist(),
        "max_speed": check.max_speed.tolist(),
        "leg_speed": job.hexapod.leg_speed.tolist(),
    }
    report = _core.check_joint_limits(trajectory, job.hexapod)
    dense = hexapod_excursions(job, check) + check_between_samples(job, _states(report, 0.0))
    return legs, leg_ratio, dense


def _states(report: Any, start_time: float) -> JointStates:
    """The joint states at a JointLimitReport's check points, its times shifted by start_time;
    the effort is the whole torque, static and dynamic."""
    s = report.samples
    return JointStates(
        np.asarray(s["time"]) + start_time,
        np.asarray(s["q"]),
        np.asarray(s["qd"]),
        np.asarray(s["qdd"]),
        np.asarray(s["static_torque"]) + np.asarray(s["dynamic_torque"]),
    )


def _without_effort_limits(arm: Any) -> Any:
    """The arm with no effort limits, for the dense check: check_joint_limits refuses a path
    where a static torque reaches its effort limit, where the summary reports that limit as
    broken instead. The efforts are checked against the arm's own limits afterwards."""
    return arm.with_joint_limits(effort=np.full(arm.dof, np.inf))


def _effort_factor(job: Job, report: Any) -> Optional[float]:
    """FACC = max |tau_dyn,i| / (tau-max_i - |tau_sta,i|) over a report's check points against
    the arm's effort limits (0 without any); None where a static torque alone reaches its limit
    (the factor is not defined there: no speed keeps that joint within its limit)."""
    effort = np.asarray(job.arm.joint_limits.effort, dtype=float)
    s = report.samples
    holding, dynamic = np.abs(np.asarray(s["static_torque"])), np.abs(np.asarray(s["dynamic_torque"]))
    limited = np.isfinite(effort) if effort.size == job.arm.dof else np.zeros(job.arm.dof, dtype=bool)
    if not np.any(limited) or holding.shape[0] == 0:
        return 0.0
    spare = effort[limited] - holding[:, limited]
    if np.any(spare <= 0.0):
        return None
    return float(np.max(dynamic[:, limited] / spare))


def _max_factor(a: Optional[float], b: Optional[float]) -> Optional[float]:
    return None if a is None or b is None else max(a, b)


def _joint_report(job: Job, trajectory: Union[Trajectory, JobTrajectory]) -> Tuple[Dict[str, Any], List[Violation]]:
    """(the arm's joint-limit factors over the job, what the dense check between samples finds
    broken): check_joint_limits, or part by part."""
    if isinstance(trajectory, JobTrajectory):
        return _joint_report_of_parts(job, trajectory)
    report = _core.check_joint_limits(
        trajectory, _without_effort_limits(job.arm), job.q_start, redundancy_rule=job.redundancy_rule
    )
    return (
        {
            "velocity_factor": float(report.velocity_factor),
            "acceleration_factor": _effort_factor(job, report),
            "position_excess": float(report.position_excess),
        },
        check_between_samples(job, _states(report, 0.0)),
    )


def _joint_report_of_parts(job: Job, trajectory: JobTrajectory) -> Tuple[Dict[str, Any], List[Violation]]:
    """The joint-limit factors of the KUKA re-timing patent over a job with PTP moves:
    check_joint_limits on each Cartesian run (from the joints at its start); for a PTP move
    FVEL = max |q-dot_i| / q-dot-max_i and FACC = max |tau_dyn,i| / (tau-max_i - |tau_sta,i|) at
    1 ms samples of its joint line (SerialArm.check_joint_limits; the line stays inside the
    position limits: both ends do, and the range is a box). See doc/retiming.md. The same
    check points are the dense check between samples."""
    arm = _without_effort_limits(job.arm)
    velocity_factor = position_excess = 0.0
    acceleration_factor: Optional[float] = 0.0
    dense: List[Violation] = []
    for (part, traj), start_time in zip(trajectory.parts, trajectory.start_times):
        if part.kind == "path":
            report = _core.check_joint_limits(traj, arm, part.q_start, redundancy_rule=job.redundancy_rule)
            position_excess = max(position_excess, float(report.position_excess))
        else:
            t = np.linspace(0.0, traj.duration, max(2, int(math.ceil(traj.duration / _PTP_CHECK_STEP)) + 1))
            report = arm.check_joint_limits(traj, t)
        dense += check_between_samples(job, _states(report, float(start_time)))
        velocity_factor = max(velocity_factor, float(report.velocity_factor))
        acceleration_factor = _max_factor(acceleration_factor, _effort_factor(job, report))
    return (
        {
            "velocity_factor": velocity_factor,
            "acceleration_factor": acceleration_factor,
            "position_excess": position_excess,
        },
        worst_per_joint(dense),
    )


def _angular_text(lim: Dict[str, Any]) -> str:
    """The angular limits in the summary's units (deg/s, deg/s²), when given."""
    text = ""
    if lim["angular_velocity"] is not None:
        text += f", ω = {math.degrees(lim['angular_velocity']):g} °/s"
    if lim["angular_acceleration"] is not None:
        text += f", ω̇ = {math.degrees(lim['angular_acceleration']):g} °/s²"
    return text


#: Moves listed by name in the summary's first line.
SUMMARY_MOVES = 20
#: Events described line by line in the summary text (the JSON summary has all of them).
SUMMARY_EVENTS = 50


def summary_text(summary: Dict[str, Any]) -> str:
    """The summary as lines of text (what `dispkin plan` prints)."""
    s = summary
    lim = s["limits"]
    jerk = f", j = {lim['jerk']:g} m/s³" if lim["jerk"] is not None else ""
    # The moves one by one up to SUMMARY_MOVES, then how many more: a job of 10⁴ moves is not a
    # line of 200 kB.
    moves = ", ".join(s["moves"][:SUMMARY_MOVES]) + (
        f", … {len(s['moves']) - SUMMARY_MOVES} more" if len(s["moves"]) > SUMMARY_MOVES else ""
    )
    lines = [
        f"job {s['job']}: {len(s['moves'])} move(s) ({moves}), machine: {s['machine']}",
        f"  duration {s['duration']:.4f} s, {s['rest_to_rest_pieces']} rest-to-rest piece(s), path length {s['length']:.6f} m",
    ]
    if not s.get("completed", True):
        share = 100.0 * s["end_position"] / s["length"] if s["length"] > 0.0 else 0.0
        lines.append(
            f"  ends STOPPED at s = {s['end_position']:.6f} m of the path's {s['length']:.6f} m ({share:.1f} %): "
            "the motion does not reach the end of its path"
        )
    lines += [
        f"  limits: v = {lim['velocity']:g} m/s, a = {lim['acceleration']:g} m/s²{jerk}{_angular_text(lim)}, "
        f"profile {s['profile']}, corner tolerance {lim['corner_tolerance']:g} m",
        f"  peak path velocity {s['peak_path_velocity']:.6f} m/s ({s['samples']} samples, every {s['sample_period']:g} s)",
    ]
    for group, g in s["groups"].items():
        lines.append(
            f"  group {group}: peak point speed {g['peak_speed']:.6f} m/s at t = {g['time']:.3f} s, "
            f"limit {g['limit']:g} m/s ({100 * g['ratio']:.1f} %)"
        )
    if "legs" in s:
        legs = s["legs"]
        lines.append(
            f"  legs: {1000 * min(legs['min_length']):.3f} .. {1000 * max(legs['max_length']):.3f} mm, fastest "
            f"{1000 * max(legs['max_speed']):.4f} mm/s (limit {1000 * min(legs['leg_speed']):g} mm/s); "
            f"within limits: {legs['within_limits']}"
        )
    if "joints" in s:
        j = s["joints"]
        effort = (
            f"{j['acceleration_factor']:.4f}"
            if j["acceleration_factor"] is not None
            else "undefined (a static torque alone reaches its effort limit)"
        )
        lines.append(
            f"  joints: velocity factor {j['velocity_factor']:.4f}, effort factor {effort} "
            f"(<= 1 is within the {j.get('limits_from', 'URDF')} limits); within limits: {j['within_limits']}"
        )
    for v in s.get("violations", []):
        lines.append("  LIMIT BROKEN: " + Violation(**{k: v[k] for k in Violation.__dataclass_fields__}).describe())
    events = s.get("events", [])
    for k, record in enumerate(events[:SUMMARY_EVENTS]):
        lines.append("  " + event_text(k, record))
    if len(events) > SUMMARY_EVENTS:
        lines.append(f"  … {len(events) - SUMMARY_EVENTS} more event(s) (all of them in the JSON summary)")
    for stop in s["stops"]:
        lines.append(f"  stops at s = {stop['s']:.6f} m: {stop['reason']}")
    lines.append(f"  binding limit: {s['binding']}")
    return "\n".join(lines) + "\n"
