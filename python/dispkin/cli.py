"""The ``dispkin`` command line: it parses the arguments and runs the command.

``dispkin check JOB.yaml`` validates a job file and builds its paths; ``dispkin plan JOB.yaml``
plans it and writes the sampled trajectory (CSV, JSON with ROS JointTrajectory field names),
a summary and, with ``--plot``, PNG plots (see :mod:`dispkin.jobs`).

``dispkin demo`` compares a point-set speed limit with a controller that limits the TCP speed
and the angular speed separately, then plans the demo job (see :mod:`dispkin.demo`; its names
can be imported from this module too).
"""

import argparse
import json
import pathlib
import sys
from typing import List, Optional, TextIO

import numpy as np

from . import Trajectory, __version__
# The demo's names, importable from here too: callers of dispkin.cli.demo_tool & co. keep working.
from .demo import (  # noqa: F401
    DEMO_ACCELERATION,
    DEMO_JERK,
    DEMO_JOB,
    EQRADIUS,
    MOVE_END,
    MOVE_START,
    SWEEP_MAX_ANGLE,
    SWEEP_MAX_TRANSLATION,
    SYSTEM_VELOCITY,
    TCP_SPHERE_RADIUS,
    TOOL_TIP,
    demo_move,
    demo_tool,
    kdl_path_length,
    peak_point_speed,
    random_lin_moves,
    run_demo,
    sweep_ratios,
)


def run_check(job_file: str, out: TextIO) -> int:
    """`dispkin check`: validate and build the job, print what it holds; returns 0."""
    from . import jobs

    job = jobs.load_job(job_file)
    ms = job.metric_set
    print(f"{job.file}: valid job {job.name!r}", file=out)
    machine = {"hexapod": "hexapod (legs " + ", ".join(job.joint_names) + ")",
               "serial_arm": f"serial arm {job.arm.robot_name if job.arm else ''} ({job.arm.dof if job.arm else 0} joints, "
               f"family {job.arm.family if job.arm else ''})", "none": "none (poses only)"}[job.machine]
    print(f"  machine: {machine}", file=out)
    if job.hexapod is not None:
        rule = [f"leg group {job.leg_speed_group} (rule a)"] if job.leg_speed_group is not None else []
        rule += ["joint metric (rule b)"] if job.joint_metric else []
        print(f"  leg speed held by: {', '.join(rule) or 'nothing (only the metric set)'}", file=out)
    if job.frames is not None:
        work, tool = job.frames.work.to_xyzuvw(), job.frames.tool.to_xyzuvw()
        work[3:], tool[3:] = np.degrees(work[3:]), np.degrees(tool[3:])
        print(f"  frames: work {np.round(work, 6).tolist()}, tool {np.round(tool, 6).tolist()} (XYZUVW, m and degrees)", file=out)
    print(f"  pivot {job.pivot.tolist()} m (platform/flange coordinates)", file=out)
    for group in ms.groups:
        limit = ms.group_speed(group)
        print(f"  metric set group {group}: {len(ms.relative_points(group))} relative + {len(ms.absolute_points(group))} "
              f"absolute points, {len(ms.spheres(group))} sphere(s), limit "
              f"{(str(limit) + ' m/s') if limit is not None else 'the system velocity'}", file=out)
    if job.path is not None:
        lengths = job.path.section_lengths(ms, job.limits.velocity)
        print(f"  path: {len(job.moves)} move(s) -> {len(job.path)} section(s), DISP length {float(np.sum(lengths)):.6f} m "
              f"at the system velocity", file=out)
    else:
        ptp = sum(part.kind == "ptp" for part in job.parts)
        print(f"  path: {len(job.moves)} move(s) in {len(job.parts)} part(s) planned one after the other "
              f"({ptp} PTP move(s) on the arm, at rest at both ends)", file=out)
    for i, move in enumerate(job.moves):
        blend = f", blend {move.blend:g} m" if move.blend else ""
        if move.kind == "ptp":
            print(f"    move {i}: ptp, ends at joints {np.round(move.path.end, 6).tolist()} (rad)", file=out)
            continue
        end = move.path.end.to_xyzuvw()
        end[3:] = np.degrees(end[3:])
        print(f"    move {i}: {move.kind}{blend}, ends at platform XYZUVW {np.round(end, 6).tolist()} (m, degrees)", file=out)
    lim = job.limits
    jerk = f", j = {lim.jerk:g} m/s³" if lim.jerk is not None else ""
    print(f"  limits: v = {lim.velocity:g} m/s, a = {lim.acceleration:g} m/s²{jerk}, profile {job.profile}", file=out)
    print(f"  output: every {job.sample_period:g} s -> {job.outputs['csv']}, {job.outputs['json']}, {job.outputs['summary']}", file=out)
    return 0


def run_plan(job_file: str, outdir: str, plot: bool, out: TextIO) -> int:
    """`dispkin plan`: plan the job, write CSV, JSON, the summary and (plot) PNGs; returns 0."""
    from . import jobs

    job = jobs.load_job(job_file)
    trajectory = jobs.plan_job(job)
    samples = jobs.sample_job(job, trajectory)
    summary = jobs.summarize(job, trajectory, samples)
    directory = pathlib.Path(outdir)
    directory.mkdir(parents=True, exist_ok=True)
    written = [directory / job.outputs["csv"], directory / job.outputs["json"], directory / job.outputs["summary"]]
    jobs.write_csv(samples, written[0])
    written[1].write_text(json.dumps(jobs.trajectory_json(job, samples, summary), indent=1) + "\n", encoding="utf-8")
    text = jobs.summary_text(summary)
    written[2].write_text(text, encoding="utf-8")
    if plot:
        written += write_plots(job, trajectory, samples, directory)
    out.write(text)
    print("wrote " + ", ".join(str(p) for p in written), file=out)
    return 0


def write_plots(job, trajectory: Trajectory, samples, directory: pathlib.Path) -> List[pathlib.Path]:
    """PNGs of the job's trajectory: path velocity and point speeds; with a machine also its
    joints (hexapod legs or arm joints) against their position ranges and velocity limits."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from . import plots

    stem = pathlib.Path(job.outputs["csv"]).stem
    machine = job.hexapod is not None or job.arm is not None
    rows = 3 if machine else 1
    figure, axes = plt.subplots(rows, 1, figsize=(7, 3.2 * rows), sharex=True, constrained_layout=True, squeeze=False)
    plots.point_speed(trajectory, job.metric_set, system_velocity=job.limits.velocity, ax=axes[0][0])
    axes[0][0].set_title(f"{job.name}: path velocity and the fastest point (limit dashed)")
    if job.hexapod is not None:
        h = job.hexapod
        plots.joint_limits(samples.time, samples.joint_names, samples.positions, samples.velocities,
                           np.asarray(h.leg_min), np.asarray(h.leg_max), np.asarray(h.leg_speed),
                           axes=(axes[1][0], axes[2][0]))
    elif job.arm is not None:
        limits = job.arm.joint_limits
        plots.joint_limits(samples.time, samples.joint_names, samples.positions, samples.velocities,
                           np.asarray(limits.lower), np.asarray(limits.upper), np.asarray(limits.velocity),
                           axes=(axes[1][0], axes[2][0]))
    path = directory / f"{stem}.png"
    plots.save([axes[0][0]], str(path))
    plt.close(figure)
    return [path]


def _positive_int(text: str) -> int:
    # Not-a-number is reported here too: argparse would name this function in its message.
    try:
        value = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"must be a positive integer, got {text!r}") from None
    if value < 1:
        raise argparse.ArgumentTypeError(f"must be a positive integer, got {value}")
    return value


def build_parser() -> argparse.ArgumentParser:
    """The argument parser of ``dispkin`` with its commands demo, check and plan (``--help``
    documents every option)."""
    parser = argparse.ArgumentParser(
        prog="dispkin",
        description="Robot trajectories under a point-set speed limit (the Euclidean DISP metric).",
    )
    parser.add_argument("--version", action="version", version=f"dispkin {__version__}")
    commands = parser.add_subparsers(dest="command", metavar="COMMAND")
    commands.required = True
    demo = commands.add_parser(
        "demo",
        help="compare with a TCP + angular speed controller (KDL), then plan the demo job with plots",
        description="Plan a built-in LIN move of a tool under a point-set speed limit, compare it "
        "with KDL's Path_Line (eqradius 0.1 m), and sweep random LIN moves (progress on stderr). Then plan "
        "OUTDIR/job.yaml - written from the built-in demo job the first time; edit it and run again - and "
        "write its trajectory, summary and plot into OUTDIR.",
    )
    demo.add_argument("--moves", type=_positive_int, default=10000, help="random moves in the sweep (default 10000)")
    demo.add_argument("--seed", type=int, default=1, help="seed of the random moves (default 1)")
    demo.add_argument("-o", "--outdir", metavar="OUTDIR", default="dispkin-demo",
                      help="directory of the demo job (OUTDIR/job.yaml, written from the built-in job when missing: "
                      "edit it and re-run) and of its outputs: CSV, JSON, summary, PNG (default: dispkin-demo)")
    demo.add_argument("--no-job", action="store_true", help="only the comparison and the sweep, no job")
    demo.add_argument("-q", "--quiet", action="store_true", help="no progress display on stderr")
    check = commands.add_parser(
        "check",
        help="validate a job file and print what it holds",
        description="Validate JOB (YAML, see python/dispkin/job.schema.json and README.md) against the schema, "
        "build its machine, metric set and paths, and print what was found. Errors name the offending key "
        "and its line; the exit status is 1 for an invalid job.",
    )
    check.add_argument("job", metavar="JOB.yaml", help="the job file")
    plan_ = commands.add_parser(
        "plan",
        help="plan a job file and write the sampled trajectory, a summary and plots",
        description="Plan JOB (YAML) and write, into OUTDIR: the sampled trajectory as CSV and as JSON with the "
        "ROS JointTrajectory field names (joint_names, points[].positions/velocities/accelerations/effort/"
        "time_from_start; hexapod legs or serial-arm joints are the joints), plus poses as XYZUVW (m, degrees), the "
        "path velocity and the fastest point's speed per sample; and a summary (duration, peak point speed "
        "per group, which limit binds), also printed. File names and the sample period come from the job's "
        "`output` section.",
    )
    plan_.add_argument("job", metavar="JOB.yaml", help="the job file")
    plan_.add_argument("-o", "--outdir", metavar="OUTDIR", default=".",
                       help="directory for the output files, created if missing (default: the current directory)")
    plan_.add_argument("--plot", action="store_true",
                       help="also write a PNG: path velocity and point speeds against the limit (and leg lengths "
                       "for a hexapod); needs matplotlib")
    return parser


def main(argv: Optional[List[str]] = None) -> int:
    """Entry point of the ``dispkin`` command; returns the exit status."""
    args = build_parser().parse_args(argv)
    from .jobs import JobError

    try:
        if args.command == "demo":
            return run_demo(args.moves, args.seed, sys.stdout, None if args.no_job else args.outdir,
                            None if args.quiet else sys.stderr)
        if args.command == "check":
            return run_check(args.job, sys.stdout)
        if args.command == "plan":
            return run_plan(args.job, args.outdir, args.plot, sys.stdout)
    except JobError as error:
        print(f"dispkin {args.command}: {error}", file=sys.stderr)
        return 1
    return 2  # unreachable: argparse requires a command


if __name__ == "__main__":
    sys.exit(main())
