"""The job commands of the ``dispkin`` command line: ``check`` validates a job file and builds its
paths, ``plan`` plans it and writes the sampled trajectory (CSV, and JSON that loads as a ROS
JointTrajectory), a summary and, on request, PNG plots (see :mod:`dispkin.jobs`), and fails when
the trajectory breaks a machine limit. The demo (:mod:`dispkin.demo`) plans its job through
``run_plan`` too.
"""

import json
import os
import pathlib
import sys
from dataclasses import dataclass
from typing import Any, Dict, List, Optional, TextIO, Tuple

import numpy as np

from . import Trajectory
from .job.events import events_text
from .job.violations import Violation
from .progress import Progress


def run_check(job_file: str, out: TextIO) -> int:
    """`dispkin check`: validate and build the job, print what it holds; returns 0."""
    from . import jobs

    job = jobs.load_job(job_file)
    ms = job.metric_set
    print(f"{job.file}: valid job {job.name!r}", file=out)
    machine = {
        "hexapod": "hexapod (legs " + ", ".join(job.joint_names) + ")",
        "serial_arm": f"serial arm {job.arm.robot_name if job.arm else ''} ({job.arm.dof if job.arm else 0} joints, "
        f"family {job.arm.family if job.arm else ''})",
        "none": "none (poses only)",
    }[job.machine]
    print(f"  machine: {machine}", file=out)
    if job.arm is not None and job.arm.redundancy.kind != "none":
        r = job.arm.redundancy
        print(
            f"  redundancy: joint {r.joint_name} (range [{r.lower:g}, {r.upper:g}] rad) "
            f"{'moved from' if job.redundancy_rule is not None else 'held at'} its value in q_start, "
            f"{r.value(job.q_start):g} rad",
            file=out,
        )
    if job.hexapod is not None:
        rule = [f"leg group {job.leg_speed_group} (rule a)"] if job.leg_speed_group is not None else []
        rule += ["joint metric (rule b)"] if job.joint_metric else []
        print(f"  leg speed held by: {', '.join(rule) or 'nothing (only the metric set)'}", file=out)
    if job.frames is not None:
        work, tool = job.frames.work.to_xyzuvw(), job.frames.tool.to_xyzuvw()
        work[3:], tool[3:] = np.degrees(work[3:]), np.degrees(tool[3:])
        print(
            f"  frames: work {np.round(work, 6).tolist()}, tool {np.round(tool, 6).tolist()} (XYZUVW, m and degrees)",
            file=out,
        )
    print(f"  pivot {job.pivot.tolist()} m (platform/flange coordinates)", file=out)
    for group in ms.groups:
        limit = ms.group_speed(group)
        print(
            f"  metric set group {group}: {len(ms.relative_points(group))} relative + {len(ms.absolute_points(group))} "
            f"absolute points, {len(ms.spheres(group))} sphere(s), limit "
            f"{(str(limit) + ' m/s') if limit is not None else 'the system velocity'}",
            file=out,
        )
    if job.path is not None:
        lengths = job.path.section_lengths(ms, job.limits.velocity)
        print(
            f"  path: {len(job.moves)} move(s) -> {len(job.path)} section(s), DISP length {float(np.sum(lengths)):.6f} m "
            f"at the system velocity",
            file=out,
        )
    else:
        ptp = sum(part.kind == "ptp" for part in job.parts)
        print(
            f"  path: {len(job.moves)} move(s) in {len(job.parts)} part(s) planned one after the other "
            f"({ptp} PTP move(s) on the arm, at rest at both ends)",
            file=out,
        )
    for i, move in enumerate(job.moves):
        blend = f", {move.blend_text()}" if move.blend_text() else ""
        if move.kind == "ptp":
            print(f"    move {i}: ptp, ends at joints {np.round(move.path.end, 6).tolist()} (rad)", file=out)
            continue
        end = move.path.end.to_xyzuvw()
        end[3:] = np.degrees(end[3:])
        print(
            f"    move {i}: {move.kind}{blend}, ends at platform XYZUVW {np.round(end, 6).tolist()} (m, degrees)",
            file=out,
        )
    lim = job.limits
    jerk = f", j = {lim.jerk:g} m/s³" if lim.jerk is not None else ""
    print(f"  limits: v = {lim.velocity:g} m/s, a = {lim.acceleration:g} m/s²{jerk}, profile {job.profile}", file=out)
    for file in job.limits_files:
        print(f"  limits file: {file}", file=out)
    if job.joint_acceleration is not None:
        print(
            f"  joint accelerations: {np.round(job.joint_acceleration, 6).tolist()} (checked in the output)", file=out
        )
    if job.retime is not None:
        print(f"  re-timed to the joint limits: method {job.retime.method}", file=out)
    if job.events:
        print(f"  events: {events_text(job.events)} (applied in this order to the planned trajectory)", file=out)
    print(
        f"  output: every {job.sample_period:g} s -> {job.outputs['csv']}, {job.outputs['json']}, {job.outputs['summary']}",
        file=out,
    )
    return 0


#: Exit status of `dispkin plan` when the written trajectory breaks a machine limit.
EXIT_LIMITS_BROKEN = 3


def run_plan(
    job_file: str,
    outdir: str,
    plot: bool,
    out: TextIO,
    allow_violations: bool = False,
    progress: Optional[Progress] = None,
    errors: Optional[TextIO] = None,
) -> int:
    """`dispkin plan`: plan the job, write CSV, JSON, the summary and (plot) PNGs. Returns 0, or
    EXIT_LIMITS_BROKEN when the trajectory breaks a machine limit (each one is described on
    `errors`, default stderr) unless `allow_violations`; the files are written either way."""
    progress = progress or Progress(None, "")
    errors = errors or sys.stderr
    planned = plan_to_files(job_file, outdir, plot, progress)
    if progress.enabled:
        progress.finish(f"{planned.samples} samples")
    out.write(planned.text)
    print("wrote " + ", ".join(str(p) for p in planned.written), file=out)
    broken = planned.violations
    if not broken:
        return 0
    verdict = "allowed by --allow-violations" if allow_violations else "use --allow-violations to accept it"
    print(
        f"dispkin plan: {planned.job_file}: the trajectory breaks {len(broken)} machine limit(s) ({verdict}):",
        file=errors,
    )
    for line in broken:
        print("  " + line, file=errors)
    return 0 if allow_violations else EXIT_LIMITS_BROKEN


@dataclass
class PlannedJob:
    """What planning one job wrote (see :func:`plan_to_files`); plain data, so that it pickles
    back from a worker process of ``dispkin batch``."""

    #: The job file, as the job reader names it in its messages.
    job_file: str
    #: The summary of :func:`dispkin.jobs.summarize` (duration, binding limit, violations, ...).
    summary: Dict[str, Any]
    #: The summary as text (the summary file, what `dispkin plan` prints).
    text: str
    #: The files written, in the order `dispkin plan` lists them.
    written: List[pathlib.Path]
    #: How many samples the trajectory has.
    samples: int

    @property
    def violations(self) -> List[str]:
        """Each machine limit the trajectory breaks, described on one line."""
        return [
            Violation(**{k: v[k] for k in Violation.__dataclass_fields__}).describe()
            for v in self.summary["violations"]
        ]


def plan_to_files(job_file: str, outdir: str, plot: bool, progress: Optional[Progress] = None) -> PlannedJob:
    """Load, plan, sample and summarize a job and write its files into `outdir` (CSV, JSON, the
    summary and, with `plot`, PNGs): the work of `dispkin plan` and of each job of `dispkin batch`.
    Every mistake raises a JobError; the outputs are checked before planning and again before
    writing."""
    from . import jobs

    progress = progress or Progress(None, "")
    if plot:
        require_matplotlib()  # before the work, not after it
    job = jobs.load_job(job_file)
    check_outputs(job, outdir, plot)  # before the work too: planning may take minutes
    progress.stage("planning")
    trajectory = jobs.plan_job(job)
    samples = jobs.sample_job(
        job, trajectory, progress=lambda stage, done, total: progress.step(f"sampling ({stage})", done, total)
    )
    progress.stage("checking the limits")
    summary = jobs.summarize(job, trajectory, samples)
    progress.stage("writing")
    directory = pathlib.Path(outdir)
    check_outputs(job, outdir, plot)  # again: planning took time, and the files may have changed
    try:
        directory.mkdir(parents=True, exist_ok=True)
    except OSError as error:
        raise jobs.JobError(f"-o OUTDIR = {outdir!r}: cannot be made: {error.strerror or error}") from error
    written = [directory / job.outputs["csv"], directory / job.outputs["json"], directory / job.outputs["summary"]]
    jobs.write_csv(samples, written[0])
    written[1].write_text(json.dumps(jobs.trajectory_json(job, samples, summary), indent=1) + "\n", encoding="utf-8")
    text = jobs.summary_text(summary)
    written[2].write_text(text, encoding="utf-8")
    if plot:
        written += write_plots(job, trajectory, samples, directory)
    return PlannedJob(str(job.file), summary, text, written, len(samples.time))


def output_files(job, directory: pathlib.Path, plot: bool) -> Dict[str, pathlib.Path]:
    """The files `dispkin plan` writes, by the key that names them (output.csv, .json, .summary;
    with --plot the PNG, named after the CSV)."""
    files = {key: directory / name for key, name in job.outputs.items()}
    if plot:
        files["png"] = directory / f"{pathlib.Path(job.outputs['csv']).stem}.png"
    return files


def check_outputs(job, outdir: str, plot: bool) -> None:
    """Raise a JobError unless `dispkin plan` can write its files into OUTDIR: OUTDIR is a
    directory or can be made one, each output is a new or regular file, the PNG of --plot is
    none of the others, and no output is the job file or a file it reads (URDF, hexapod file,
    limits files), however named: compared by resolved path and by inode (symlinks, hard links)."""
    from .jobs import JobError

    directory = pathlib.Path(outdir)
    existing = next((p for p in (directory, *directory.parents) if os.path.lexists(p)), None)
    if existing is not None and not existing.is_dir():
        where = (
            "is not a directory" if existing == directory else f"cannot be made: {str(existing)!r} is not a directory"
        )
        raise JobError(f"-o OUTDIR = {outdir!r}: {where}")
    inputs = [("the job file", job.file)] + [("a file the job reads", p) for p in job.inputs]
    files = output_files(job, directory, plot)
    for key, path in files.items():
        problem = _output_problem(path, inputs)
        if key == "png" and problem is None:
            problem = next(
                (f"is also output.{other}" for other, p in files.items() if other != "png" and p == path), None
            )
        if problem is not None:
            raise _output_error(job, key, path, problem)


def _output_problem(path: pathlib.Path, inputs: List[Tuple[str, pathlib.Path]]) -> Optional[str]:
    """Why `dispkin plan` must not write `path` (None: it may)."""
    for what, source in inputs:
        if path.resolve() == source.resolve() or (path.exists() and source.exists() and os.path.samefile(path, source)):
            return f"is {what} ({source}): an input is never overwritten"
    if path.is_dir():
        return "is a directory"
    if path.exists() and not path.is_file():
        return "is not a regular file (a FIFO, a device or a socket)"
    return None


def _output_error(job, key: str, path: pathlib.Path, problem: str):
    """The JobError of an output file `dispkin plan` must not write, at the job's key that
    names it (the PNG: the --plot option)."""
    from .jobs import JobError

    if key == "png":
        return JobError(f"--plot: {str(path)!r} {problem}")
    message = f"{job.outputs[key]!r}: {str(path)!r} {problem}"
    if job.source is not None:
        return job.source.error(("output", key), message)
    return JobError(f"{job.file}: output.{key}: {message}")


def require_matplotlib() -> None:
    """Raise a JobError saying how to install matplotlib when it is missing (plots need it)."""
    from .jobs import JobError

    try:
        import matplotlib  # noqa: F401
    except ImportError as error:
        raise JobError(
            "--plot needs matplotlib, which is not installed: pip install 'dispkin[plot]' (or pip install matplotlib)"
        ) from error


#: Most points of the path-velocity and point-speed curves of `dispkin plan --plot`.
PLOT_POINTS = 100_000


def write_plots(job, trajectory: Trajectory, samples, directory: pathlib.Path) -> List[pathlib.Path]:
    """PNGs of the job's trajectory: path velocity and point speeds, with the times of the job's
    events as vertical lines; with a machine also its joints (hexapod legs or arm joints)
    against their position ranges and velocity limits."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from . import plots

    stem = pathlib.Path(job.outputs["csv"]).stem
    machine = job.hexapod is not None or job.arm is not None
    rows = 3 if machine else 1
    figure, axes = plt.subplots(rows, 1, figsize=(7, 3.2 * rows), sharex=True, constrained_layout=True, squeeze=False)
    # Every millisecond, at most PLOT_POINTS times (a long wait at rest between a stop and its
    # resumption would otherwise make 10⁸ points).
    step = max(1e-3, trajectory.duration / PLOT_POINTS)
    plots.point_speed(trajectory, job.metric_set, system_velocity=job.limits.velocity, step=step, ax=axes[0][0])
    axes[0][0].set_title(f"{job.name}: path velocity and the fastest point (limit dashed)")
    if job.events:
        _mark_events(axes[0][0], job.events)
    if job.hexapod is not None:
        h = job.hexapod
        plots.joint_limits(
            samples.time,
            samples.joint_names,
            samples.positions,
            samples.velocities,
            np.asarray(h.leg_min),
            np.asarray(h.leg_max),
            np.asarray(h.leg_speed),
            axes=(axes[1][0], axes[2][0]),
        )
    elif job.arm is not None:
        limits = job.arm.joint_limits
        plots.joint_limits(
            samples.time,
            samples.joint_names,
            samples.positions,
            samples.velocities,
            np.asarray(limits.lower),
            np.asarray(limits.upper),
            np.asarray(limits.velocity),
            axes=(axes[1][0], axes[2][0]),
        )
    path = directory / f"{stem}.png"
    plots.save([axes[0][0]], str(path))
    plt.close(figure)
    return [path]


#: Colours of the event lines in the plots, by kind.
_EVENT_COLOURS = {"stop": "tab:red", "resume": "tab:green", "override": "tab:purple"}


def _mark_events(ax, events) -> None:
    """The times of the events as dotted vertical lines, one legend entry per kind, an
    override's factor written at the top of its line."""
    labelled = set()
    for event in events:
        label = None if event.kind in labelled else event.kind
        labelled.add(event.kind)
        ax.axvline(event.at, color=_EVENT_COLOURS[event.kind], ls=":", lw=1.2, label=label)
        if event.kind == "override":
            ax.annotate(
                f"×{event.factor:g}",
                (event.at, 1.0),
                xycoords=("data", "axes fraction"),
                xytext=(2, -10),
                textcoords="offset points",
                fontsize="small",
                color=_EVENT_COLOURS["override"],
            )
    ax.legend(loc="lower center", fontsize="small", ncol=2)
