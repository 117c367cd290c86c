"""How far the S-curve law under a staircase is from the fastest law, on long staircases.

    build/cmake/benchmarks/dispkin_scurve_staircase DIR     # writes DIR/<workload>.txt
    .venv/bin/python benchmarks/scurve_grid_optimum.py DIR [NODES]

For each staircase: the trapezoid law, dispkin's S-curve law (velocity_limited_law), the duration
no jerk-limited law can beat (jerk_limited_duration_bound, doc/profiles.md §8.5) and a numerical
optimum on a fine grid of s — all over the trapezoid law's duration.

The grid optimum (written for this benchmark, independent of dispkin's construction): nodes at
every segment boundary and at most 1/NODES (default 50 000) of the path apart; the unknowns are the squared
velocities b_i at the nodes (each at most the lower limit of the segments it touches, 0 at both
ends); over each interval the acceleration (b_{i+1} − b_i) / (2Δs) is constant and within ±a;
from one interval to the next it changes by at most j times the time between their midpoints
(Δt_i = 2Δs / (v_i + v_{i+1})); the duration Σ Δt_i is minimised. The jerk constraint is not
convex in b, so it is solved as a sequence of convex programs (cvxpy with the Clarabel interior
point solver), each with Δt linearised at the last solution — its tangent lies below the convex
Δt, so every step keeps the true constraint — inside a trust region, from dispkin's own law,
until the duration settles. A local optimum of the discretised problem: an estimate of the
fastest law, not a bound (the bound is jerk_limited_duration_bound).
"""

import pathlib
import sys
import time

import numpy as np

import dispkin

cp = None  # cvxpy, imported by main (a benchmark dependency: requirements-dev.txt)


def read_staircases(path):
    """The runs of a staircase file: lists of (length, limit) rows, each closed by '# a j'."""
    runs, rows = [], []
    for line in pathlib.Path(path).read_text().splitlines():
        if line.startswith("#"):
            a, j = map(float, line[1:].split())
            runs.append((np.array(rows), a, j))
            rows = []
        elif line.strip():
            rows.append([float(x) for x in line.split()])
    return runs


def grid(segments, spacing):
    """Nodes (every boundary, at most `spacing` apart) and each node's limit (0 at the ends)."""
    edges = np.concatenate([[0.0], np.cumsum(segments[:, 0])])
    nodes, cap = [0.0], [0.0]
    for k, (length, limit) in enumerate(segments):
        m = max(1, int(np.ceil(length / spacing)))
        for i in range(1, m + 1):
            nodes.append(edges[k] + length * i / m)
            nxt = segments[k + 1, 1] if k + 1 < len(segments) else 0.0
            cap.append(min(limit, nxt) if i == m else limit)
    return np.array(nodes), np.array(cap)


def law_on_grid(laws, nodes):
    """v² of a list of Profiles at the grid's nodes."""
    s, v, start = [], [], 0.0
    for law in laws:
        states = law.sample(np.linspace(0.0, law.duration, 64))
        s.append(start + states[:, 0])
        v.append(states[:, 1])
        start += law.distance
    s, v = np.concatenate(s), np.concatenate(v)
    order = np.argsort(s, kind="stable")
    return np.interp(nodes, s[order], v[order]) ** 2


def grid_optimum(nodes, cap, b, a, j, rounds=20):
    """The sequence of convex programs of the module's docstring, in units of the path's length
    and its highest limit (the interior point solver needs numbers near 1)."""
    length, top = nodes[-1], cap.max()
    unit_time = length / top
    ds = np.diff(nodes) / length
    cap, b = cap / top, np.minimum(b / top**2, (cap / top) ** 2)
    a, j = a * length / top**2, j * length**2 / top**3
    n = len(nodes)

    def duration(b):
        v = np.sqrt(np.maximum(b, 0.0))
        return unit_time * np.sum(2 * ds / np.maximum(v[:-1] + v[1:], 1e-300))

    current, radius, kept_slack = duration(b), 0.3, np.inf
    for _ in range(rounds):
        v = np.sqrt(np.maximum(b, 1e-6))  # tangents of Δt taken at v ≥ 1e-3 (any tangent stays below Δt)
        sums = v[:-1] + v[1:]
        B = cp.Variable(n)
        slack = cp.Variable(n, nonneg=True)  # lets the first round start from a law off the grid's jerk rule
        acc = cp.multiply(cp.diff(B), 1 / (2 * ds))
        dt = 2 * ds / sums - cp.multiply(ds / (sums**2 * v[:-1]), B[:-1] - b[:-1])
        dt -= cp.multiply(ds / (sums**2 * v[1:]), B[1:] - b[1:])
        gap = 0.5 * (dt[:-1] + dt[1:])
        jump = cp.diff(acc)
        constraints = [
            B >= 0,
            B <= cap**2,
            cp.abs(acc) <= a,
            cp.abs(jump) <= j * gap + slack[1:-1],
            cp.abs(acc[0]) <= j * 0.5 * dt[0] + slack[0],
            cp.abs(acc[-1]) <= j * 0.5 * dt[-1] + slack[-1],
            cp.abs(B - b) <= radius * np.maximum(b, 1e-4),
        ]
        time_of = cp.sum(cp.multiply(2 * ds, cp.inv_pos(cp.sqrt(B[:-1]) + cp.sqrt(B[1:]))))
        try:
            cp.Problem(cp.Minimize(time_of + 1e4 * cp.sum(slack) / j), constraints).solve(solver="CLARABEL")
        except cp.error.SolverError:
            radius /= 2  # the interior point method lost its way: a smaller step from the same law
            if radius < 0.01:
                break
            continue
        b, kept_slack = np.maximum(B.value, 0.0), slack.value.max()
        previous, current = current, duration(b)
        if kept_slack < 1e-9 and abs(previous - current) < 1e-6 * current:
            break
    assert kept_slack < 1e-6, "the grid optimum must keep its own jerk rule"
    return current


def main():
    global cp
    import cvxpy

    cp = cvxpy
    folder = pathlib.Path(sys.argv[1])
    count = int(sys.argv[2]) if len(sys.argv) > 2 else 50000
    print(f"{'staircase':58} {'segments':>8} {'S-curve':>8} {'bound':>7} {'grid':>7} {'S/grid':>7} {'grid s':>7}")
    for file in sorted(folder.glob("*.txt")):
        for segments, a, j in read_staircases(file):
            trapezoid = sum(p.duration for p in dispkin.velocity_limited_law(segments, a_max=a))
            laws = dispkin.velocity_limited_law(segments, a_max=a, j_max=j)
            law = sum(p.duration for p in laws)
            bound = dispkin.jerk_limited_duration_bound(segments, a_max=a, j_max=j)
            nodes, cap = grid(segments, segments[:, 0].sum() / count)
            start = time.process_time()
            optimum = grid_optimum(nodes, cap, law_on_grid(laws, nodes), a, j)
            seconds = time.process_time() - start
            print(
                f"{file.stem:58} {len(segments):8d} {law / trapezoid:8.3f} {bound / trapezoid:7.3f} "
                f"{optimum / trapezoid:7.3f} {law / optimum:7.3f} {seconds:7.0f}",
                flush=True,
            )


if __name__ == "__main__":
    main()
