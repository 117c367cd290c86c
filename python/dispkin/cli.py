"""The ``dispkin`` command line: it parses the arguments and runs the command.

``dispkin check JOB.yaml`` validates a job file and builds its paths; ``dispkin plan JOB.yaml``
plans it and writes the sampled trajectory (CSV, JSON with ROS JointTrajectory field names),
a summary and, with ``--plot``, PNG plots (see :mod:`dispkin.jobs`); ``dispkin batch JOB...``
plans many jobs on local processes or a Dask cluster (see :mod:`dispkin.batches`).

``dispkin demo`` compares a point-set speed limit with a controller that limits the TCP speed
and the angular speed separately, then plans the demo job (see :mod:`dispkin.demo`; its names
can be imported from this module too).
"""

import argparse
import sys
from typing import List, Optional

from . import __version__
from .progress import Progress

# The check and plan commands, importable from here too.
from .commands import run_check, run_plan, write_plots  # noqa: F401

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
    """The argument parser of ``dispkin`` with its commands demo, check, plan and batch (``--help``
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
    demo.add_argument(
        "-o",
        "--outdir",
        metavar="OUTDIR",
        default="dispkin-demo",
        help="directory of the demo job (OUTDIR/job.yaml, written from the built-in job when missing: "
        "edit it and re-run) and of its outputs: CSV, JSON, summary, PNG (default: dispkin-demo)",
    )
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
        "`output` section; they are checked before planning (never the job file or a file it reads). Exit status: "
        "0 done, every limit held; 1 invalid job, an output that cannot be written, or planning failed; 2 bad "
        "arguments; 3 the trajectory breaks a machine limit at a sample or between samples (hexapod leg range or "
        "speed, joint position, velocity, acceleration or effort: each one is printed on stderr with the joint, the "
        "time and by how much) - the files are written all the same; --allow-violations exits 0.",
    )
    plan_.add_argument("job", metavar="JOB.yaml", help="the job file")
    plan_.add_argument(
        "-o",
        "--outdir",
        metavar="OUTDIR",
        default=".",
        help="directory for the output files, created if missing (default: the current directory)",
    )
    plan_.add_argument(
        "--plot",
        action="store_true",
        help="also write a PNG: path velocity and point speeds against the limit (and leg lengths "
        "for a hexapod); needs matplotlib (pip install 'dispkin[plot]')",
    )
    plan_.add_argument(
        "--allow-violations",
        action="store_true",
        help="exit 0 even when the trajectory breaks a machine limit (the broken limits are still "
        "printed on stderr and listed in the summary)",
    )
    shown = plan_.add_mutually_exclusive_group()
    shown.add_argument(
        "--progress",
        action="store_true",
        help="progress on stderr even when it is not a terminal (by default only on a terminal)",
    )
    shown.add_argument("-q", "--quiet", action="store_true", help="no progress on stderr")
    _add_batch(commands)
    return parser


def _add_batch(commands) -> None:
    """The `dispkin batch` command and its options."""
    batch = commands.add_parser(
        "batch",
        help="plan many job files at once, on local processes or a Dask cluster, with one summary table",
        description="Plan every JOB as `dispkin plan JOB -o DIR/NAME` plans it alone (NAME: the job file's name "
        "without .yaml; -2, -3... when two jobs share one), on --workers local processes or on the Dask cluster of "
        "--scheduler, and write DIR/batch_summary.csv: one row per job with its folder, status (planned, limits "
        "broken, failed), duration (s), binding limit, the machine limits it breaks and, for a failed job, the error. "
        "A failed job does not stop the others; each is reported on stderr. On a cluster the job files and DIR must "
        "be at the same paths on every worker (a shared file system). Exit status: 0 every job planned within its "
        "limits; 1 a job failed (how many is printed), DIR cannot be made or the scheduler cannot be reached; 2 "
        "bad arguments; 3 a trajectory breaks a machine limit (--allow-violations exits 0).",
    )
    batch.add_argument("jobs", nargs="+", metavar="JOB.yaml", help="the job files")
    batch.add_argument(
        "-o",
        "--outdir",
        metavar="DIR",
        required=True,
        help="directory of the summary table and of one folder per job, created if missing",
    )
    where = batch.add_mutually_exclusive_group()
    where.add_argument(
        "--workers",
        metavar="N",
        type=_positive_int,
        help="local worker processes (default: one per core, at most one per job)",
    )
    where.add_argument(
        "--scheduler",
        metavar="ADDRESS",
        help="plan on the Dask cluster of the scheduler at ADDRESS (e.g. tcp://host:8786); needs "
        "pip install 'dispkin[distributed]'",
    )
    batch.add_argument("--plot", action="store_true", help="also write each job's PNG, as `dispkin plan --plot` does")
    batch.add_argument(
        "--allow-violations",
        action="store_true",
        help="exit 0 even when a trajectory breaks a machine limit (still reported and in the table)",
    )
    shown = batch.add_mutually_exclusive_group()
    shown.add_argument(
        "--progress",
        action="store_true",
        help="a line per finished job on stderr even when it is not a terminal (by default only on a terminal)",
    )
    shown.add_argument("-q", "--quiet", action="store_true", help="no progress on stderr")


def main(argv: Optional[List[str]] = None) -> int:
    """Entry point of the ``dispkin`` command; returns the exit status."""
    args = build_parser().parse_args(argv)
    from .jobs import JobError

    try:
        if args.command == "demo":
            return run_demo(
                args.moves,
                args.seed,
                sys.stdout,
                None if args.no_job else args.outdir,
                None if args.quiet else sys.stderr,
            )
        if args.command == "check":
            return run_check(args.job, sys.stdout)
        if args.command == "plan":
            progress = Progress.for_stderr(sys.stderr, "dispkin plan", force=args.progress, quiet=args.quiet)
            return run_plan(args.job, args.outdir, args.plot, sys.stdout, args.allow_violations, progress)
        if args.command == "batch":
            from .batches import run_batch

            progress = Progress.for_stderr(sys.stderr, "dispkin batch", force=args.progress, quiet=args.quiet)
            return run_batch(
                args.jobs,
                args.outdir,
                args.workers,
                args.scheduler,
                args.plot,
                sys.stdout,
                args.allow_violations,
                progress,
            )
    except JobError as error:
        print(f"dispkin {args.command}: {error}", file=sys.stderr)
        return 1
    return 2  # unreachable: argparse requires a command


if __name__ == "__main__":
    sys.exit(main())
