"""Profile computation time and durations: dispkin.Profile against Ruckig, same cases, same run.

Ruckig's C++ library is not installed here (its PyPI wheel is the Python module), so both are
timed through Python: each figure includes one Python -> C++ call (dispkin: pybind11; Ruckig:
nanobind/pybind11 plus the InputParameter set-up, which is part of using Ruckig from Python).
The C++-only figures of dispkin are in RESULTS.md (bench_profile.cpp).

    .venv/bin/python benchmarks/profile_vs_ruckig.py [--count 10000] [--rounds 11]

Timing: thread CPU time of a pass over all cases, dispkin's and Ruckig's passes alternating
within each round (benchmarks/cpu_rounds.py); per contender the median over the rounds of the
time per profile, and the median over the rounds of the ratio Ruckig / dispkin in the same round.
Prints those and the duration agreement:
the largest relative difference, and how many cases differ by more than 1e-9 together with
Ruckig's own end-position error in those cases (its p_precision is 1e-8 absolute).
"""

import argparse
import math
import platform
import statistics

import numpy as np
import ruckig

import dispkin
from cpu_rounds import alternating_rounds, median_ratio, per_call


def cases(count, seed=20261122):
    rng = np.random.default_rng(seed)

    def log_uniform(lo, hi):
        return 10.0 ** rng.uniform(math.log10(lo), math.log10(hi), count)

    return [
        tuple(x)
        for x in zip(
            log_uniform(1e-6, 10.0).tolist(),
            log_uniform(1e-2, 10.0).tolist(),
            log_uniform(1e-2, 100.0).tolist(),
            log_uniform(1e-1, 1e4).tolist(),
        )
    ]


def ruckig_planner():
    otg, trajectory, inp = ruckig.Ruckig(1), ruckig.Trajectory(1), ruckig.InputParameter(1)
    inp.current_position, inp.current_velocity, inp.current_acceleration = [0.0], [0.0], [0.0]
    inp.target_velocity, inp.target_acceleration = [0.0], [0.0]

    def plan(S, v, a, j):
        inp.target_position = [S]
        inp.max_velocity, inp.max_acceleration, inp.max_jerk = [v], [a], [j]
        otg.calculate(inp, trajectory)
        return trajectory

    return plan


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--count", type=int, default=10000)
    parser.add_argument("--rounds", type=int, default=11)
    args = parser.parse_args()
    all_cases = cases(args.count)
    plan = ruckig_planner()
    inf = math.inf

    runs = {
        "scurve": (
            lambda S, v, a, j: dispkin.Profile.scurve(S, v, a, j),
            lambda S, v, a, j: plan(S, v, a, j),
            lambda S, v, a, j: dispkin.Profile.scurve(S, v, a, j).duration,
            lambda S, v, a, j: plan(S, v, a, j),
        ),
        "trapezoid": (
            lambda S, v, a, j: dispkin.Profile.trapezoid(S, v, a),
            lambda S, v, a, j: plan(S, v, a, inf),
            lambda S, v, a, j: dispkin.Profile.trapezoid(S, v, a).duration,
            lambda S, v, a, j: plan(S, v, a, inf),
        ),
    }
    print(
        f"{platform.processor() or platform.machine()}, Python {platform.python_version()}, "
        f"ruckig {getattr(ruckig, '__version__', '?')}, dispkin {dispkin.__version__}, {args.count} rest-to-rest cases, "
        f"thread CPU time, medians of {args.rounds} alternating rounds"
    )
    print(
        "| kind | dispkin µs/profile | Ruckig µs/profile | ratio | max rel. duration diff | cases > 1e-9 (Ruckig end-position error there) |"
    )
    print("|---|---:|---:|---:|---:|---|")
    for kind, (ours, theirs, our_duration, their_plan) in runs.items():
        times = alternating_rounds(
            {"dispkin": lambda: per_call(ours, all_cases), "ruckig": lambda: per_call(theirs, all_cases)}, args.rounds
        )
        t_ours, t_theirs = statistics.median(times["dispkin"]), statistics.median(times["ruckig"])
        ratio = median_ratio(times["ruckig"], times["dispkin"])
        worst, off = 0.0, []
        for c in all_cases:
            d = our_duration(*c)
            trajectory = their_plan(*c)
            rel = abs(d - trajectory.duration) / trajectory.duration
            worst = max(worst, rel)
            if rel > 1e-9:
                off.append((rel, abs(trajectory.at_time(trajectory.duration)[0][0] - c[0]) / c[0]))
        detail = "; ".join(f"{r:.1e} ({p:.1e} rel.)" for r, p in off[:5]) or "none"
        print(
            f"| {kind} | {t_ours * 1e6:.2f} | {t_theirs * 1e6:.2f} | {ratio:.2f}× | {worst:.1e} | {len(off)}: {detail} |"
        )


if __name__ == "__main__":
    main()
