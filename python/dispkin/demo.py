"""``dispkin demo``: a point-set speed limit against a controller that limits the TCP speed
and the angular speed separately.

The demo plans one LIN move of a built-in tool under a point-set speed limit and compares it
with Orocos KDL's ``Path_Line`` with an equivalent radius (modelled here by its path length;
KDL itself is not called), then measures, over many random LIN moves, how much faster than
commanded such a controller lets the points of a tool sphere move (progress on stderr when it
is a terminal). Then it plans a job: ``OUTDIR/job.yaml``, written from the built-in demo job (a
hexapod carrying a 120 mm tool through blended moves) the first time; edit it and run the demo
again to plan your version. The outputs (CSV, JSON, summary, plot) go next to it.
"""

import math
import pathlib
from typing import List, Optional, TextIO, Tuple

import numpy as np

from .commands import run_plan
from . import (
    Limits,
    MetricSet,
    Path,
    Pose,
    Trajectory,
    __version__,
    disp_distance,
    max_point_speed,
    plan,
    section_length,
)

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
limits: {velocity: 0.02, acceleration: 0.1, jerk: 2.0, profile: scurve,
         corner_tolerance: 0.002}            # blend every other corner within 2 mm: one continuous run
output: {sample_period: 0.01, csv: demo.csv, json: demo.json, summary: demo_summary.txt}
"""


def _print_move_comparison(out: TextIO) -> None:
    """The built-in move: its DISP chord, exact section lengths, KDL's path length and the
    planned S-curve's fastest point."""
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


def _print_sweep(moves: int, seed: int, out: TextIO, progress: Optional[TextIO]) -> None:
    """The sweep over random LIN moves: how much faster than commanded KDL's Path_Line lets the
    points of the ball around the TCP move, on average and at most."""
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


def _plan_demo_job(outdir: str, out: TextIO) -> int:
    """Plan OUTDIR/job.yaml as `dispkin plan --plot` does, writing it from DEMO_JOB first when it
    is missing (an edited file is kept); returns the exit status."""

    job_file = pathlib.Path(outdir) / "job.yaml"
    if not job_file.exists():
        job_file.parent.mkdir(parents=True, exist_ok=True)
        job_file.write_text(DEMO_JOB, encoding="utf-8")
        print(f"\nwrote the demo job to {job_file}", file=out)
    print(f"\nplanning {job_file} (dispkin plan {job_file} -o {outdir} --plot):", file=out)
    status = run_plan(str(job_file), outdir, True, out)
    print(
        f"\nEdit {job_file} (moves, limits, tool points, machine) and run the demo again to plan your version.",
        file=out,
    )
    return status


def run_demo(
    moves: int, seed: int, out: TextIO, outdir: Optional[str] = None, progress: Optional[TextIO] = None
) -> int:
    """Print the demo (see the module docstring) to `out`, with the sweep's progress on
    `progress`; then plan OUTDIR/job.yaml (if `outdir`). Returns the exit status 0."""
    _print_move_comparison(out)
    _print_sweep(moves, seed, out, progress)
    print(
        "computed: DISP chord distance, exact LIN/screw section lengths and an S-curve plan of the move "
        "(dispkin), and the ratio exact section length / KDL Path_Line path length for the built-in "
        "move and the sweep.",
        file=out,
    )
    if outdir is None:
        return 0
    return _plan_demo_job(outdir, out)
