"""Seven-joint arms without a closed form (family general) solved from a known start
(doc/inverse-kinematics.md §13), and following with the redundancy parameter moved (§12).

- general: a random 7R arm (the test's random_7r_urdf, seeded); N random joint vectors q in 0.7 of
  the ranges, poses T(q), starts q_ref = q + U(−0.05, 0.05) per joint. Timed by thread CPU time
  per call, the contenders alternating round by round (cpu_rounds.py): `inverse_solutions(T,
  q_ref=q_ref)` (Newton first) and `inverse_solutions(T)` (the search from random starts, its
  default budget of 64 starts / 50 ms). Counted: calls that return a solution, and the largest
  pose error.
- following: `follow` of a Panda LIN of 26 poses with the parameter moved (the default rule) and
  kept (move_redundancy=False), per path.

Run:  .venv/bin/python benchmarks/ik_general_from_start.py [--count 200] [--rounds 5]
(build the binding first: make python). No timing is asserted anywhere; this only prints.
"""

from __future__ import annotations

import argparse
import pathlib
import platform
import statistics
import sys

import numpy as np

import dispkin

ROOT = pathlib.Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tests" / "python"))
sys.path.insert(0, str(ROOT / "benchmarks"))

import cpu_rounds  # noqa: E402
from test_serial_seven_joints import lin_poses, panda, random_7r_urdf  # noqa: E402


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--count", type=int, default=200)
    parser.add_argument("--rounds", type=int, default=5)
    args = parser.parse_args()
    print(
        f"# {platform.processor() or platform.machine()}, Python {platform.python_version()}, dispkin {dispkin.__version__}"
    )
    rng = np.random.default_rng(20261204 + 7)
    arm = dispkin.SerialArm.from_urdf(random_7r_urdf(rng), "l0", "l7")
    limits = arm.joint_limits
    qs = 0.7 * rng.uniform(limits.lower, limits.upper, size=(args.count, 7))
    poses = [arm.forward(q).matrix() for q in qs]
    starts = qs + rng.uniform(-0.05, 0.05, qs.shape)
    found, worst = 0, 0.0
    for p, s in zip(poses, starts):
        solutions = arm.inverse_solutions(p, q_ref=s).solutions
        found += bool(solutions)
        for x in solutions:
            worst = max(worst, np.abs(arm.forward(x).matrix() - p).max())
    print(f"random 7R ({arm.family}): {found} of {args.count} from q_ref solved, worst pose error {worst:.1e}")
    items_start = list(zip(poses, starts))
    blocks = {
        "Newton from q_ref": lambda: cpu_rounds.per_call(lambda p, s: arm.inverse_solutions(p, q_ref=s), items_start),
        "search (64 starts, 50 ms)": lambda: cpu_rounds.per_call(lambda p: arm.inverse_solutions(p), poses[:20]),
    }
    times = cpu_rounds.alternating_rounds(blocks, args.rounds)
    for label, seconds in times.items():
        print(f"  {label}: {statistics.median(seconds) * 1e6:.1f} µs per call (median of {args.rounds} rounds)")
    print(
        f"  ratio search / Newton: {cpu_rounds.median_ratio(times['search (64 starts, 50 ms)'], times['Newton from q_ref']):.0f}"
    )

    a = panda()
    q = np.array([0.1, -0.4, 0.2, -2.0, 0.1, 1.8, 0.7])
    path = lin_poses(a, q, np.array([0.05, 0.03, -0.04]), 26)
    blocks = {
        "follow, parameter moved": lambda: cpu_rounds.repeated(lambda: a.follow(path, q), 20),
        "follow, parameter kept": lambda: cpu_rounds.repeated(lambda: a.follow(path, q, move_redundancy=False), 20),
    }
    times = cpu_rounds.alternating_rounds(blocks, args.rounds)
    for label, seconds in times.items():
        print(f"  Panda LIN of 26 poses, {label}: {statistics.median(seconds) * 1e3:.3f} ms per path")


if __name__ == "__main__":
    main()
