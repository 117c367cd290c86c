"""Seven-joint arms (doc/inverse-kinematics.md §11): round trips and the time per call from Python.

For the Franka Panda (example-robot-data, fingers removed) and the iiwa14 of tests/data/urdf,
N seeded random joint vectors inside the limits q are turned into poses T(q), and

- round trips: `arm.inverse(T(q), q_ref=q)` must hold q (every joint within 1e-9) — a miss is a
  q that is not among the solutions at its own q₇;
- timing: thread CPU time (time.thread_time_ns) of `arm.inverse(pose, redundancy=q[6])` (the pose a
  (4, 4) float64 array) and of `arm.inverse(pose, q_ref=q)` over all poses, per call; one
  parameter value per call. The median over `--rounds` rounds, the contenders alternating.

Run:  .venv/bin/python benchmarks/ik_seven_joints.py [--count 100000] [--rounds 5]
(build the binding first: make python). No timing is asserted anywhere; this only prints.
"""

from __future__ import annotations

import argparse
import pathlib
import platform
import sys
import time

import numpy as np

import dispkin

ROOT = pathlib.Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tests" / "python"))


def arms():
    from test_serial_seven_joints import iiwa, panda  # the test fixtures, one source of the arms

    return {"panda": panda(), "iiwa14": iiwa()}


def random_q(rng, arm, n):
    limits = arm.joint_limits
    return rng.uniform(limits.lower, limits.upper, size=(n, arm.dof))


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--count", type=int, default=100_000)
    parser.add_argument("--rounds", type=int, default=5)
    parser.add_argument("--timed", type=int, default=2000, help="poses per timing block")
    args = parser.parse_args()
    print(
        f"# {platform.processor() or platform.machine()}, Python {platform.python_version()}, dispkin {dispkin.__version__}"
    )
    for name, arm in arms().items():
        rng = np.random.default_rng(20261204)
        qs = random_q(rng, arm, args.count)
        misses, worst, total = 0, 0.0, 0
        for q in qs:
            solutions = arm.inverse(arm.forward(q).matrix(), q_ref=q)
            total += len(solutions)
            if len(solutions) == 0 or np.abs(solutions[0] - q).max() > 1e-9:
                misses += 1
            else:
                worst = max(worst, np.abs(solutions[0] - q).max())
        print(
            f"{name}: {args.count} round trips, {misses} misses, worst joint error {worst:.2e} rad, "
            f"{total / args.count:.2f} solutions per value on average"
        )
        poses = [arm.forward(q).matrix() for q in qs[: args.timed]]
        timed = qs[: args.timed]
        calls = {
            "inverse(pose, redundancy=q7)": lambda: [arm.inverse(p, redundancy=q[6]) for p, q in zip(poses, timed)],
            "inverse(pose, q_ref=q)": lambda: [arm.inverse(p, q_ref=q) for p, q in zip(poses, timed)],
        }
        per_call = {key: [] for key in calls}
        for r in range(args.rounds):
            keys = list(calls)
            for key in keys[r % len(keys) :] + keys[: r % len(keys)]:
                start = time.thread_time_ns()
                calls[key]()
                per_call[key].append((time.thread_time_ns() - start) / len(poses) / 1e3)
        for key, times in per_call.items():
            print(f"  {key}: {np.median(times):.2f} µs per call (median of {args.rounds} rounds of {len(poses)})")


if __name__ == "__main__":
    main()
