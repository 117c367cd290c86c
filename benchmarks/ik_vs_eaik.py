"""All-solutions analytic IK: dispkin against EAIK on the same poses, in one run.

EAIK (PyPI `eaik`, Ostermeier et al., subproblem decomposition; already the solution-count
oracle of tests/python/make_analytic_ik_reference.py) and dispkin each solve the same poses of
seeded random joint vectors, for a three-parallel arm (the UR5e of tests/data/urdf) and a
spherical-wrist arm (the KR6-like arm of tests/data/urdf). Both are timed from Python:

- dispkin `SerialArm.inverse(pose)`, one pose per call, the pose a (4, 4) float64 array (C
  order) or a dispkin Pose: the analytic IK plus the SerialArm layer (joint limits, each joint
  the 2π copy nearest 0) and the (k, n) array of the solutions;
- dispkin `SerialArm.inverse_solutions(pose)` (the InverseResult report: a list of arrays);
- dispkin `SerialArm.inverse_many(poses)` on all poses at once (a list of (k, n) arrays);
- EAIK `Robot.IK(pose)` (its C++ solver through pybind11), and `IK_batched` on all poses with
  one worker thread, which leaves out the per-call Python overhead.

`empty call` times a binding call that does no work (`arm.dof`), the Python overhead every
per-call figure contains. The C++ figures of dispkin's analytic IK alone are those of
benchmarks/bench_ik.cpp (benchmarks/history/2026-11-22-analytic-ik.md).

Timing: thread CPU time (time.thread_time_ns) around a block of calls over all poses, the
contenders' blocks alternating within each round (the first contender changes from round to
round), so that a change of machine load falls on all of them alike; per contender the median
over the rounds of the time per pose, and the median over the rounds of the ratio
dispkin inverse / EAIK IK in the same round.

EAIK loads the URDF itself (urchin) and places its tool frame at the last joint with the base
orientation, so its pose of q is dispkin's pose of q times a constant transform X⁻¹; the
script works X out at q = 0, checks it at random q, and hands each solver the pose in its own
convention. Solution counts are compared too (they must agree; a mismatch stops the script).

Run:  .venv/bin/python benchmarks/ik_vs_eaik.py [--poses 2000] [--rounds 15]
(build the binding first: make python). No timing is asserted anywhere; this only prints.
"""

from __future__ import annotations

import argparse
import math
import pathlib
import platform
import statistics

import numpy as np

import dispkin
from cpu_rounds import alternating_rounds, per_call, whole_batch

DATA = pathlib.Path(__file__).resolve().parents[1] / "tests" / "data" / "urdf"

ARMS = {
    "UR5e (three parallel)": (DATA / "arm_ur5e_dh.urdf", "base_link", "tool0"),
    "KR6-like (spherical wrist)": (DATA / "arm_kr6_like_dh.urdf", "base_link", "flange"),
}


def as_matrix(pose) -> np.ndarray:
    """A dispkin Pose as a 4×4 homogeneous matrix."""
    return np.asarray(pose.matrix(), dtype=float)


def distinct_count(solutions, tolerance=1e-6) -> int:
    """Number of solutions distinct modulo 2π by more than `tolerance` in some joint."""
    kept = []
    for q in solutions:
        q = np.asarray(q, dtype=float)
        if all(np.abs(np.remainder(q - other + math.pi, 2 * math.pi) - math.pi).max() > tolerance for other in kept):
            kept.append(q)
    return len(kept)


def compare(name: str, path: pathlib.Path, base: str, tip: str, poses: int, rounds: int, seed: int) -> None:
    from eaik.IK_URDF import UrdfRobot

    arm = dispkin.SerialArm.from_urdf(str(path), base, tip)
    eaik_robot = UrdfRobot(str(path))
    if not eaik_robot.hasKnownDecomposition():
        raise RuntimeError(f"{name}: EAIK knows no decomposition")

    # T_dispkin(q) = T_eaik(q) X for every q (the same joint screws, different tool frames).
    x = np.linalg.inv(eaik_robot.fwdKin(np.zeros(arm.dof))) @ as_matrix(arm.forward(np.zeros(arm.dof)))
    rng = np.random.default_rng(seed)
    lower = np.maximum(np.array(arm.joint_limits.lower), -math.pi)
    upper = np.minimum(np.array(arm.joint_limits.upper), math.pi)
    qs = rng.uniform(lower, upper, size=(poses, arm.dof))
    ours = [np.ascontiguousarray(as_matrix(arm.forward(q))) for q in qs]
    theirs = [pose @ np.linalg.inv(x) for pose in ours]
    for q, pose in zip(qs[:20], theirs[:20]):
        if np.abs(eaik_robot.fwdKin(q) - pose).max() > 1e-9:
            raise RuntimeError(f"{name}: EAIK's forward kinematics differs from dispkin's by more than a tool frame")

    # Same problem: the same number of exact solutions per pose (checked on the first 200).
    for pose, their_pose in zip(ours[:200], theirs[:200]):
        mine = arm.inverse_solutions(pose, keep_outside_limits=True, offer_equivalents=False).solutions
        solution = eaik_robot.IK(their_pose)
        exact = [
            q
            for q, least_squares in zip(solution.Q, solution.is_LS)
            if not least_squares and np.abs(eaik_robot.fwdKin(q) - their_pose).max() <= 1e-9
        ]
        if distinct_count(mine) != distinct_count(exact):
            raise RuntimeError(
                f"{name}: {distinct_count(mine)} solutions from dispkin, {distinct_count(exact)} from EAIK"
            )

    mean_solutions = statistics.mean(len(arm.inverse(p)) for p in ours)
    as_poses = [dispkin.Pose.from_matrix(p) for p in ours]
    blocks = {
        "dispkin inverse(pose), pose a (4, 4) array": lambda: per_call(arm.inverse, ours),
        "dispkin inverse(pose), pose a Pose": lambda: per_call(arm.inverse, as_poses),
        "dispkin inverse_solutions(pose)": lambda: per_call(arm.inverse_solutions, ours),
        "dispkin inverse_many(all poses)": lambda: whole_batch(arm.inverse_many, ours_batch),
        "EAIK IK(pose)": lambda: per_call(eaik_robot.IK, theirs),
        "EAIK IK_batched(all poses, 1 thread)": lambda: whole_batch(
            lambda batch: eaik_robot.IK_batched(batch, 1), theirs
        ),
        "empty call (arm.dof)": lambda: per_call(lambda p: arm.dof, ours),
    }
    ours_batch = np.array(ours)
    times = alternating_rounds(blocks, rounds)
    ratios = [d / e for d, e in zip(times["dispkin inverse(pose), pose a (4, 4) array"], times["EAIK IK(pose)"])]
    print(
        f"\n{name}: {poses} poses, {mean_solutions:.2f} solutions per pose, family {arm.family!r} / EAIK "
        f"{eaik_robot.getKinematicFamily()!r}"
    )
    for label, seconds in times.items():
        print(
            f"  {label:48s} {statistics.median(seconds) * 1e6:8.2f} µs   "
            f"(rounds: {min(seconds) * 1e6:.2f} – {max(seconds) * 1e6:.2f})"
        )
    print(
        f"  ratio dispkin inverse(array) / EAIK IK, median over rounds: {statistics.median(ratios):.3f} "
        f"({min(ratios):.3f} – {max(ratios):.3f})"
    )


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--poses", type=int, default=2000, help="poses per arm (default 2000)")
    parser.add_argument("--rounds", type=int, default=15, help="alternating rounds, medians are printed (default 15)")
    parser.add_argument("--seed", type=int, default=20261122)
    args = parser.parse_args()
    import eaik  # noqa: F401  (fail early with a clear ImportError)
    from importlib.metadata import version

    print(
        f"dispkin {dispkin.__version__}, eaik {version('eaik')}, numpy {np.__version__}, "
        f"Python {platform.python_version()}, {platform.machine()}; thread CPU time (time.thread_time_ns) "
        f"per pose, median of {args.rounds} alternating rounds"
    )
    for name, (path, base, tip) in ARMS.items():
        compare(name, path, base, tip, args.poses, args.rounds, args.seed)


if __name__ == "__main__":
    main()
