"""All-solutions analytic IK: dispkin against EAIK on the same poses, in one run.

EAIK (PyPI `eaik`, Ostermeier et al., subproblem decomposition; already the solution-count
oracle of tests/python/make_analytic_ik_reference.py) and dispkin each solve the same poses of
seeded random joint vectors, for a three-parallel arm (the UR5e of tests/data/urdf) and a
spherical-wrist arm (the KR6-like arm of tests/data/urdf). Both are timed from Python, one
pose per call:

- dispkin `SerialArm.inverse_solutions(pose, offer_equivalents=False)`: the analytic IK plus
  the SerialArm layer (joint limits, a KDL forward-kinematics check of every returned
  solution, the conversion of the result to numpy arrays);
- dispkin `SerialArm.inverse(pose)`: the same with the 2π-equivalent copies inside the limits
  (the UR5e's ±2π limits turn 8 solutions into up to 512);
- EAIK `Robot.IK(pose)` (its C++ solver through pybind11), and `IK_batched` on all poses with
  one worker thread, which leaves out the per-call Python overhead.

`empty call` times a binding call that does no work (`arm.dof`), the Python overhead every
per-call figure contains. The C++ figures of dispkin's analytic IK alone are those of
benchmarks/bench_ik.cpp (benchmarks/RESULTS.md, "Analytic IK").

EAIK loads the URDF itself (urchin) and places its tool frame at the last joint with the base
orientation, so its pose of q is dispkin's pose of q times a constant transform X⁻¹; the
script works X out at q = 0, checks it at random q, and hands each solver the pose in its own
convention. Solution counts are compared too (they must agree; a mismatch stops the script).

Run:  .venv/bin/python benchmarks/ik_vs_eaik.py [--poses 2000] [--repeat 5]
(build the binding first: make python). No timing is asserted anywhere; this only prints.
"""

from __future__ import annotations

import argparse
import math
import pathlib
import platform
import statistics
import time

import numpy as np

import dispkin

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


def per_call(function, items, repeat: int) -> float:
    """Median over `repeat` passes of the mean time per item (seconds) of function(item)."""
    passes = []
    for _ in range(repeat):
        start = time.process_time()
        for item in items:
            function(item)
        passes.append((time.process_time() - start) / len(items))
    return statistics.median(passes)


def whole_batch(function, items, repeat: int) -> float:
    """Median over `repeat` passes of the time per item (seconds) of one call function(items)."""
    passes = []
    for _ in range(repeat):
        start = time.process_time()
        function(items)
        passes.append((time.process_time() - start) / len(items))
    return statistics.median(passes)


def compare(name: str, path: pathlib.Path, base: str, tip: str, poses: int, repeat: int, seed: int) -> None:
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
    ours = [as_matrix(arm.forward(q)) for q in qs]
    theirs = [pose @ np.linalg.inv(x) for pose in ours]
    for q, pose in zip(qs[:20], theirs[:20]):
        if np.abs(eaik_robot.fwdKin(q) - pose).max() > 1e-9:
            raise RuntimeError(f"{name}: EAIK's forward kinematics differs from dispkin's by more than a tool frame")

    # Same problem: the same number of exact solutions per pose (checked on the first 200).
    for pose, their_pose in zip(ours[:200], theirs[:200]):
        mine = arm.inverse_solutions(pose, keep_outside_limits=True, offer_equivalents=False).solutions
        solution = eaik_robot.IK(their_pose)
        exact = [q for q, least_squares in zip(solution.Q, solution.is_LS)
                 if not least_squares and np.abs(eaik_robot.fwdKin(q) - their_pose).max() <= 1e-9]
        if distinct_count(mine) != distinct_count(exact):
            raise RuntimeError(f"{name}: {distinct_count(mine)} solutions from dispkin, {distinct_count(exact)} from EAIK")

    mean_solutions = statistics.mean(len(arm.inverse_solutions(p, offer_equivalents=False).solutions) for p in ours)
    mean_copies = statistics.mean(len(arm.inverse(p)) for p in ours)
    rows = [
        ("dispkin inverse_solutions(pose, offer_equivalents=False)",
         per_call(lambda p: arm.inverse_solutions(p, offer_equivalents=False), ours, repeat), mean_solutions),
        ("dispkin inverse(pose) (2π copies inside the limits)", per_call(arm.inverse, ours, repeat), mean_copies),
        ("EAIK IK(pose)", per_call(eaik_robot.IK, theirs, repeat), None),
        ("EAIK IK_batched(all poses, 1 thread)",
         whole_batch(lambda batch: eaik_robot.IK_batched(batch, 1), theirs, repeat), None),
        ("empty call (arm.dof)", per_call(lambda p: arm.dof, ours, repeat), None),
    ]
    print(f"\n{name}: {poses} poses, family {arm.family!r} / EAIK {eaik_robot.getKinematicFamily()!r}")
    for label, seconds, solutions in rows:
        extra = f"   {solutions:.2f} solutions per pose" if solutions is not None else ""
        print(f"  {label:58s} {seconds * 1e6:9.2f} µs{extra}")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--poses", type=int, default=2000, help="poses per arm (default 2000)")
    parser.add_argument("--repeat", type=int, default=5, help="timed passes, the median is printed (default 5)")
    parser.add_argument("--seed", type=int, default=20261122)
    args = parser.parse_args()
    import eaik  # noqa: F401  (fail early with a clear ImportError)
    from importlib.metadata import version

    print(f"dispkin {dispkin.__version__}, eaik {version('eaik')}, numpy {np.__version__}, "
          f"Python {platform.python_version()}, {platform.machine()}; CPU time (time.process_time), "
          f"median of {args.repeat} passes, per pose")
    for name, (path, base, tip) in ARMS.items():
        compare(name, path, base, tip, args.poses, args.repeat, args.seed)


if __name__ == "__main__":
    main()
