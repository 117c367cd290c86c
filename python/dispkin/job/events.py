"""The job's `events`: stops on the path, resumptions and speed overrides applied, in time order,
to the planned Cartesian trajectory (``Trajectory.stopped_at``, ``resumed_at``,
``with_override``; doc/events.md).

Each event keeps the motion before its time bit for bit and plans the rest anew from the state
the motion is in there, so an event's `at` is a time on the clock of the motion as the events
before it left it. What ``dispkin plan`` samples, writes and summarises is the trajectory after
the last event.

What the job file says on its own is checked when the job is read (:func:`read_events`, also by
``dispkin check``): times in order, a resumption only after a stop, no second stop before it, an
override factor in range, and a job whose trajectory takes events — one Cartesian trajectory
planned under the DISP limits. What depends on the planned motion (an event after the motion
has ended, a resumption of a stop that came to rest at the path's end) is checked when the
events are applied (:func:`apply_events`).
"""

from typing import Any, Dict, List, Optional, Sequence, Tuple, Union

from .._core import Trajectory
from . import input_budget
from .model import Event, Job, JobError, KeyPath, Part, format_key_path

#: The override factors Trajectory.with_override takes (times the velocity-limit curve as planned).
OVERRIDE_RANGE = (0.001, 10.0)

#: The kinds of event, each the one key of an event beside `at`.
KINDS = ("stop", "resume", "override")


def _yaml(value: Any) -> str:
    """A value as the job file spells it: true / false for booleans, else its repr."""
    return ("true" if value else "false") if isinstance(value, bool) else repr(value)


def _number(value: float) -> str:
    """A number of an event as a job file would write it: 2 for 2.0, else its repr."""
    return repr(int(value)) if float(value).is_integer() and abs(value) < 2**53 else repr(float(value))


def read_events(builder: Any, job: Dict[str, Any], parts: Sequence[Part]) -> None:
    """events: the events in time order (job["events"]), each checked on its own and against
    the ones before it; refused for jobs whose trajectory does not take events."""
    value = builder.data.get("events")
    job["events"] = []
    if value is None:
        return
    at: KeyPath = ("events",)
    if len(value) > input_budget.MAX_EVENTS:
        raise builder.fail(
            at,
            f"{len(value)} events, more than {input_budget.MAX_EVENTS}, the most a job may have "
            "(each plans the rest of the motion anew; doc/input-budget.md)",
        )
    ptp = next((k for part in parts if part.kind == "ptp" for k in part.moves), None)
    if ptp is not None:
        raise builder.fail(
            at,
            f"events apply to a job planned as one Cartesian trajectory; moves[{ptp}] is a PTP move, so this "
            "job is planned part by part, and a stop or an override within one part would not carry over to the "
            "parts after it (each starts at rest where the one before ends): give events in jobs of lin, circ "
            "and spline moves",
        )
    if builder.data.get("retime") is not None:
        raise builder.fail(
            at,
            "a re-timed trajectory (`retime`) keeps to the joint limits, which a stop, a resumption or an "
            "override does not know (they keep to the DISP limits the trajectory was planned under; "
            "doc/events.md §4): give `events` or `retime`, not both",
        )
    low, high = OVERRIDE_RANGE
    events: List[Event] = []
    stopped_by: Optional[Event] = None
    for i, entry in enumerate(value):
        key: KeyPath = ("events", i)
        kind = next(k for k in KINDS if k in entry)
        if events and entry["at"] < events[-1].at:
            raise builder.fail(
                key + ("at",),
                f"{entry['at']!r}: before the event before it (events[{i - 1}].at = "
                f"{value[i - 1]['at']!r}): give the events in time order",
            )
        factor = None
        if kind == "override":
            factor = float(entry["override"])
            if not low <= factor <= high:
                raise builder.fail(
                    key + ("override",),
                    f"{entry['override']!r}: must be in [{low:g}, {high:g}] "
                    "(times the velocity-limit curve as planned)",
                )
        elif entry[kind] is not True:
            raise builder.fail(
                key + (kind,),
                f"{_yaml(entry[kind])}: a `{kind}` event is written `{kind}: true` "
                "(leave out an event that is not to happen)",
            )
        if kind == "stop" and stopped_by is not None:
            raise builder.fail(
                key + ("stop",),
                f"true: the motion is already stopped, by events[{stopped_by.index}] at "
                f"t = {stopped_by.at:g} s: a second stop needs a `resume` before it",
            )
        if kind == "resume" and stopped_by is None:
            raise builder.fail(
                key + ("resume",),
                "true: no stop before it: a resumption continues a motion stopped by an earlier `stop` event",
            )
        event = Event(float(entry["at"]), kind, factor, i)
        stopped_by = event if kind == "stop" else None if kind == "resume" else stopped_by
        events.append(event)
    job["events"] = events


def _error(job: Job, key_path: KeyPath, message: str) -> JobError:
    """The JobError of an event at key_path (FILE:LINE:COLUMN when the job file is known)."""
    if job.source is not None:
        return job.source.error(key_path, message)
    return JobError(f"{job.file}: {format_key_path(key_path)}: {message}", key_path)


def _stop_before(job: Job, event: Event) -> Event:
    """The stop a resumption continues (read_events made sure there is one)."""
    return next(e for e in reversed(job.events[: event.index]) if e.kind == "stop")


def apply_events(job: Job, trajectory: Trajectory) -> Trajectory:
    """The trajectory after the job's events, applied one after the other in time order; a
    JobError at the event's key where an event finds nothing to act on (the motion has ended
    before it, or the stop it resumes came to rest at the end of the path)."""
    for event in job.events:
        key: KeyPath = ("events", event.index)
        if event.kind != "resume" and not trajectory.stopped and event.at >= trajectory.duration:
            later = " with the events before it" if event.index > 0 else ""
            raise _error(
                job,
                key + ("at",),
                f"{_number(event.at)}: the motion ends at t = {trajectory.duration:.6g} s{later}; "
                f"a {'stop' if event.kind == 'stop' else 'speed override'} at or after its end "
                "changes nothing: give a time before it",
            )
        if event.kind == "resume" and not trajectory.stopped:
            stop = _stop_before(job, event)
            raise _error(
                job,
                key + ("resume",),
                f"true: nothing to resume: the stop of events[{stop.index}] (t = {stop.at:g} s) "
                f"comes to rest at the end of the path (s = {trajectory.end_position:.6g} m), "
                "where the motion ends anyway",
            )
        try:
            if event.kind == "stop":
                trajectory = trajectory.stopped_at(event.at)
            elif event.kind == "resume":
                trajectory = trajectory.resumed_at(event.at)
            else:
                trajectory = trajectory.with_override(event.at, event.factor)
        except (ValueError, RuntimeError) as error:
            if (
                event.kind == "stop"
                and trajectory.path_velocity(event.at) == 0.0
                and trajectory.path_acceleration(event.at) == 0.0
            ):
                raise _error(
                    job,
                    key + ("at",),
                    f"{_number(event.at)}: the motion rests at this instant (s = "
                    f"{float(trajectory.path_position(event.at)):.6g} m) between two rest-to-rest "
                    f"laws, where Trajectory.stopped_at fails ({error}): give the stop a time at "
                    "which the motion moves",
                ) from error
            raise _error(job, key, f"{event.kind} at t = {event.at:g} s failed: {error}") from error
        count = trajectory.duration / job.sample_period
        if count > input_budget.MAX_SAMPLES:
            at = key + (("override",) if event.kind == "override" else ("at",))
            value = event.factor if event.kind == "override" else event.at
            raise _error(
                job,
                at,
                f"{_number(value)}: with this event the motion lasts {trajectory.duration:.6g} s, {count:.3g} samples "
                f"of {job.sample_period:g} s (output.sample_period), more than {input_budget.MAX_SAMPLES} "
                "(doc/input-budget.md)",
            )
    if job.events and trajectory.duration == 0.0:
        stop = next(e for e in reversed(job.events) if e.kind == "stop")
        raise _error(
            job,
            ("events", stop.index, "at"),
            f"{_number(stop.at)}: the stop comes before the motion starts and no resumption "
            "follows: the job has no motion to write",
        )
    return trajectory


def describe_events(job: Job, trajectory: Union[Trajectory, Any]) -> List[Dict[str, Any]]:
    """What each of the job's events did, from the trajectory after all of them: the time, the
    kind, the path position and velocity at the event; for a stop where it comes to rest
    (`stop_position`, m), how long it brakes (`stop_duration`, s) and whether it came to rest
    before a resumption (`came_to_rest`); for an override its factor and whether it came while
    the motion was stopped (then it holds from the resumption on); for a resumption the factor
    it resumes at.

    The motion before an event is the same in the trajectory after all events (each event keeps
    the motion before its time bit for bit), so a stop is measured by stopping the final
    trajectory at the same time, from the same state."""
    records: List[Dict[str, Any]] = []
    factor, stopped = 1.0, False
    for k, event in enumerate(job.events):
        t = event.at
        record: Dict[str, Any] = {
            "at": t,
            "kind": event.kind,
            "path_position": float(trajectory.path_position(t)),
            "path_velocity": float(trajectory.path_velocity(t)),
        }
        if event.kind == "stop":
            if record["path_velocity"] == 0.0 and float(trajectory.path_acceleration(t)) == 0.0:
                rest, braking = record["path_position"], 0.0  # at rest already: it stays there
            else:
                try:
                    stop = trajectory.stopped_at(t)
                except (ValueError, RuntimeError) as error:
                    raise _error(
                        job, ("events", event.index), f"the stop at t = {t:g} s cannot be measured again: {error}"
                    ) from error
                rest, braking = float(stop.end_position), max(float(stop.duration) - t, 0.0)
            resume = next((e for e in job.events[k + 1 :] if e.kind == "resume"), None)
            record.update(
                stop_position=rest, stop_duration=braking, came_to_rest=resume is None or resume.at >= t + braking
            )
            stopped = True
        elif event.kind == "resume":
            record["factor"] = factor
            stopped = False
        else:
            factor = float(event.factor)
            record.update(factor=factor, while_stopped=stopped)
        records.append(record)
    return records


def event_text(index: int, record: Dict[str, Any]) -> str:
    """One event of the summary as a line of text."""
    head = f"event {index} at t = {record['at']:.4f} s: "
    where = f"s = {record['path_position']:.6f} m at {record['path_velocity']:.6f} m/s"
    if record["kind"] == "stop":
        text = (
            f"stop from {where}, at rest at s = {record['stop_position']:.6f} m after {record['stop_duration']:.4f} s"
        )
        return head + text + ("" if record["came_to_rest"] else " (resumed before it came to rest)")
    if record["kind"] == "resume":
        return head + f"resume from {where}, at speed override {record['factor']:g}"
    text = f"speed override {record['factor']:g} × the velocity-limit curve as planned, from {where}"
    return (
        head + text + (" (the motion is stopped: it holds from the resumption on)" if record["while_stopped"] else "")
    )


def events_text(events: Sequence[Event]) -> str:
    """The events in a few words each, in order, e.g. 'stop at t = 2.5 s, override 0.5 at t = 6 s'."""
    return ", ".join(
        f"override {e.factor:g} at t = {e.at:g} s" if e.kind == "override" else f"{e.kind} at t = {e.at:g} s"
        for e in events
    )


def end_of_motion(trajectory: Any) -> Tuple[float, bool]:
    """(where the motion ends, m of DISP arc length; whether that is the end of its path)."""
    if getattr(trajectory, "stopped", False):
        return float(trajectory.end_position), False
    return float(trajectory.length), True
