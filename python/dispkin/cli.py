"""The ``dispkin`` command line.

``dispkin check JOB.yaml`` validates a job file and builds its paths; ``dispkin plan JOB.yaml``
plans it and writes the sampled trajectory (CSV, JSON with ROS JointTrajectory field names),
a summary and, with ``--plot``, PNG plots (see :mod:`dispkin.jobs`).

``dispkin demo`` plans one LIN move of a built-in tool under a point-set speed limit and
compares it with a conventional controller that limits the TCP speed and the angular speed
separately (Orocos KDL's ``Path_Line`` with an equivalent radius), then measures, over many
random LIN moves, how much faster than commanded such a controller lets the points of a tool
sphere move (progress on stderr when it is a terminal). Then it plans a job: ``OUTDIR/job.yaml``, written from the built-in demo job (a
hexapod carrying a 120 mm tool through blended moves) the first time; edit it and run the demo
again to plan your version. The outputs (CSV, JSON, summary, plot) go next to it.
"""

import argparse
import json
import math
import pathlib
import sys
from typing import List, Optional, TextIO, Tuple

import numpy as np

from . import Limits, MetricSet, Path, Pose, Trajectory, __version__, disp_distance, max_point_speed, plan, section_length

#: Commanded speed of the demo (m/s), and the acceleration (m/s²) and jerk (m/s³) of its plan.
SYSTEM_VELOCITY = 0.1
DEMO_ACCELERATION = 0.5
DEMO_JERK = 5.0
#: KDL Path_Line's equivalent radius (m): rotation by θ counts as a path of length eqradius·θ.
EQRADIUS = 0.1
#: The built-in tool: its tip (body coordinates, m) and a ball of this radius around the TCP.
TOOL_TIP = (0.0, 0.0, 0.3)
TCP_SPHERE_RADIUS = 0.1
#: The built-in move, XYZUVW in metres and radians (pivot = TCP).
MOVE_START = (0.0, 0.0, 0.0, 0.0, 0.0, 0.0)
MOVE_END = (0.05, 0.02, 0.0, math.radians(10.0), 0.0, math.radians(30.0))
#: The random moves of the sweep: translation up to this length (m), rotation up to this angle.
SWEEP_MAX_TRANSLATION = 0.2
SWEEP_MAX_ANGLE = math.radians(90.0)


def demo_tool() -> MetricSet:
    """The demo's tool: its tip as a relative point and a 0.1 m ball around the TCP."""
    tool = MetricSet()
    tool.add_relative(TOOL_TIP)
    tool.add_sphere((0.0, 0.0, 0.0), TCP_SPHERE_RADIUS)
    return tool


def demo_move() -> Tuple[Pose, Pose]:
    """The demo's move as (start, end) poses."""
    return Pose.from_xyzuvw(MOVE_START), Pose.from_xyzuvw(MOVE_END)


def kdl_path_length(pose_a: Pose, pose_b: Pose, eqradius: float = EQRADIUS) -> float:
    """Path length of KDL's ``Path_Line`` (single-axis rotation) from pose_a to pose_b, metres.

    KDL moves the TCP on a straight line and turns about one axis by θ, and parameterises both
    by one path length ``max(|Δp|, eqradius·θ)``: at path speed v the TCP moves at most at v and
    the orientation turns at most at v / eqradius.
    """
    dp = float(np.linalg.norm(pose_b.translation - pose_a.translation))
    theta = float(np.linalg.norm((pose_a.inverse() * pose_b).log()[3:]))
    return max(dp, eqradius * theta)


def random_lin_moves(count: int, seed: int) -> List[Pose]:
    """End poses of `count` random LIN moves from the identity: uniformly random translation
    direction with length uniform in [0, 0.2] m, uniformly random rotation axis with angle
    uniform in [0, 90°]."""
    rng = np.random.default_rng(seed)
    direction = rng.normal(size=(count, 3))
    direction /= np.linalg.norm(direction, axis=1, keepdims=True)
    translation = direction * rng.uniform(0.0, SWEEP_MAX_TRANSLATION, size=(count, 1))
    axis = rng.normal(size=(count, 3))
    axis /= np.linalg.norm(axis, axis=1, keepdims=True)
    rotation_vector = axis * rng.uniform(0.0, SWEEP_MAX_ANGLE, size=(count, 1))
    moves = []
    for t, w in zip(translation, rotation_vector):
        turn = Pose.exp(np.concatenate(([0.0, 0.0, 0.0], w)))
        moves.append(Pose(quaternion=turn.quaternion, translation=t))
    return moves


def sweep_ratios(count: int, seed: int, eqradius: float = EQRADIUS, progress: Optional[TextIO] = None) -> np.ndarray:
    """For random LIN moves (see random_lin_moves), the ratio exact LIN section length of the
    ball of radius `eqradius` around the TCP / KDL path length: how many times the commanded
    speed the fastest point of that ball moves under KDL's Path_Line."""
    sphere = MetricSet()
    sphere.add_sphere((0.0, 0.0, 0.0), eqradius)
    start = Pose()
    ratios = []
    step = max(1, count // 10)
    for k, end in enumerate(random_lin_moves(count, seed), start=1):
        if progress is not None and progress.isatty() and (k % step == 0 or k == count):
            print(f"\rsweep: {k}/{count} moves", end="\n" if k == count else "", file=progress, flush=True)
        kdl = kdl_path_length(start, end, eqradius)
        if kdl > 0.0:  # a move of length zero has no speed to compare
            ratios.append(section_length(sphere, start, end, interpolation="decoupled") / kdl)
    return np.asarray(ratios)


def peak_point_speed(traj: Trajectory, tool: MetricSet, step: float = 1e-3) -> Tuple[float, float]:
    """The largest speed of any point or sphere of `tool` along `traj`, sampled every `step`
    seconds from the trajectory's own body twist, and the time it occurs."""
    times = np.arange(0.0, traj.duration + step, step)
    poses = traj.sample(times)
    twists = traj.body_twist(times)
    speeds = [max_point_speed(tool, Pose.from_matrix(m), xi) for m, xi in zip(poses, twists)]
    i = int(np.argmax(speeds))
    return float(speeds[i]), float(times[i])


#: The built-in demo job, written to OUTDIR/job.yaml by `dispkin demo` when that file is missing.
DEMO_JOB = """\
# The dispkin demo job. `dispkin demo` (and `make demo`) wrote this file and plans it; edit it
# and run the demo again to plan your version. Every key: python/dispkin/job.schema.json and
# README.md ("Job files and the command line"). Units: m, m/s, degrees for XYZUVW angles.
#
# A hexapod carries a 120 mm tool. The tool frame sits at the tool tip, so XYZUVW moves turn
# about the tip. No point of the tool - the icosahedra around the tip and around the platform
# centre - may exceed 20 mm/s, and no leg its 10 mm/s (rule (a): the upper leg joints as group 1).
name: demo
machine:
  hexapod:
    symmetric: {base_radius: 0.12, base_gap: 20, platform_radius: 0.08, platform_gap: 20,
                height: 0.15, leg_min: 0.12, leg_max: 0.20, leg_speed: 0.01}
    leg_speed_group: 1
frames:
  tool: {xyzuvw: [0, 0, 0.12, 0, 0, 0]}      # the tool tip, platform coordinates
metric_set:
  points:
    - {shape: icosahedron, radius: 0.01, center: [0, 0, 0.12]}   # around the tool tip
    - {shape: icosahedron, radius: 0.03, center: [0, 0, 0]}      # around the platform centre
start: {xyzuvw: [0, 0, 0, 0, 0, 0]}          # the tool frame in the work frame (here: the base)
moves:
  - lin: {to: {xyzuvw: [0.01, 0, 0, 0, 4, 0]}}
  - lin: {to: {xyzuvw: [0.01, 0.01, 0.005, -3, 4, 0]}}
    blend: 0.004                             # round the via point instead of stopping there
  - circ:
      via: {xyzuvw: [0, 0.015, 0.005, -3, 0, 10]}
      to: {xyzuvw: [-0.01, 0.01, 0.005, 0, -3, 20]}
    blend: 0.004
  - lin: {to: {xyzuvw: [0, 0, 0, 0, 0, 0]}}
limits: {velocity: 0.02, acceleration: 0.1, jerk: 2.0, profile: scurve}
output: {sample_period: 0.01, csv: demo.csv, json: demo.json, summary: demo_summary.txt}
"""


def run_demo(moves: int, seed: int, out: TextIO, outdir: Optional[str] = None, progress: Optional[TextIO] = None) -> int:
    """Print the demo (see the module docstring) to `out`, with the sweep's progress on
    `progress`; then plan OUTDIR/job.yaml (if `outdir`). Returns the exit status 0."""
    tool = demo_tool()
    start, end = demo_move()
    chord = disp_distance(tool, start, end)
    lin = section_length(tool, start, end, interpolation="decoupled")
    screw = section_length(tool, start, end, interpolation="screw")
    kdl = kdl_path_length(start, end)
    v = SYSTEM_VELOCITY
    x, y, z, u, vv, w = MOVE_END
    print(f"dispkin {__version__} demo: one LIN move under a point-set speed limit", file=out)
    print(
        f"tool: tip {TOOL_TIP} m (relative point) + ball r = {TCP_SPHERE_RADIUS} m around the TCP",
        file=out,
    )
    print(
        f"move: XYZUVW 0 -> ({x} m, {y} m, {z} m, {math.degrees(u):g}°, {math.degrees(vv):g}°, "
        f"{math.degrees(w):g}°), LIN (TCP on a straight line)",
        file=out,
    )
    print(f"  chord distance (DISP)           {chord:.6f} m", file=out)
    print(f"  section length, LIN (exact)     {lin:.6f} m -> {lin / v:.4f} s at {v} m/s", file=out)
    print(f"  section length, screw (exact)   {screw:.6f} m -> {screw / v:.4f} s at {v} m/s", file=out)
    print(
        f"  KDL Path_Line (eqradius {EQRADIUS} m) {kdl:.6f} m -> {kdl / v:.4f} s; its fastest tool point "
        f"moves at {lin / kdl:.3f}x the commanded {v} m/s",
        file=out,
    )
    limits = Limits(velocity=v, acceleration=DEMO_ACCELERATION, jerk=DEMO_JERK)
    traj = plan(Path.lin(start, end), tool, limits, profile="scurve")
    peak, at = peak_point_speed(traj, tool)
    print(
        f"  planned (S-curve, a = {DEMO_ACCELERATION} m/s², j = {DEMO_JERK} m/s³): {traj.duration:.4f} s; "
        f"fastest point of the set at any 1 ms sample {peak:.6f} m/s (t = {at:.3f} s) <= {v} m/s",
        file=out,
    )
    ratios = sweep_ratios(moves, seed, progress=progress)
    print(
        f"sweep: {moves} random LIN moves (seed {seed}; translation <= {SWEEP_MAX_TRANSLATION} m, "
        f"rotation <= {math.degrees(SWEEP_MAX_ANGLE):g}°), set = ball r = {EQRADIUS} m around the TCP",
        file=out,
    )
    print(
        f"  under KDL Path_Line the points of the tool sphere move {ratios.mean():.3f}x the commanded "
        f"speed on average and up to {ratios.max():.3f}x",
        file=out,
    )
    print(
        "computed: DISP chord distance, exact LIN/screw section lengths and an S-curve plan of the move "
        "(dispkin), and the ratio exact section length / KDL Path_Line path length for the built-in "
        "move and the sweep.",
        file=out,
    )
    if outdir is None:
        return 0
    job_file = pathlib.Path(outdir) / "job.yaml"
    if not job_file.exists():
        job_file.parent.mkdir(parents=True, exist_ok=True)
        job_file.write_text(DEMO_JOB, encoding="utf-8")
        print(f"\nwrote the demo job to {job_file}", file=out)
    print(f"\nplanning {job_file} (dispkin plan {job_file} -o {outdir} --plot):", file=out)
    status = run_plan(str(job_file), outdir, True, out)
    print(f"\nEdit {job_file} (moves, limits, tool points, machine) and run the demo again to plan your version.",
          file=out)
    return status


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
