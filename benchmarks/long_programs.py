"""Long blended pose lists: sections, memory and planning time per move (benchmarks/history/
2026-12-04-long-blended-pose-lists-sections-in-proportion.md).

Two workloads, each planned in continuous-path mode (plan(..., corner_tolerance=d)):
- cam: a generated 3-axis finishing program in the manner of a CAM post-processor's G64 P0.1
  output — raster passes over a smooth freeform surface z = f(x, y) in 0.5 mm steps, each pass
  joined to the next by a short step-over, so that most corners turn by a few degrees and two
  per pass by 90° (corner_tolerance 0.1 mm);
- five_axis: a noisy 5-axis list — steps of 2–6 mm turning by 10–45° at each corner, the tool
  tilting by up to 2° a move (corner_tolerance 0.5 mm).

`python benchmarks/long_programs.py --measure WORKLOAD MOVES ROUNDS` prints one JSON line for
the dispkin the interpreter imports: sections, resident growth of the kept trajectory, pickle
size, the process's peak resident growth, thread CPU time of plan() per round, duration.
`python benchmarks/long_programs.py --compare BEFORE_PYTHON AFTER_PYTHON` runs both
interpreters in alternating rounds (a fresh process each, the first one changing from round to
round) and prints a Markdown table.
"""

from __future__ import annotations

import gc
import json
import math
import pickle
import random
import resource
import statistics
import subprocess
import sys
import time


def resident_bytes():
    with open("/proc/self/statm") as f:
        return int(f.read().split()[1]) * resource.getpagesize()


def cam_poses(moves):
    """A raster over z = 2 mm · sin(x/7 mm) cos(y/11 mm), passes 2 mm apart, 0.5 mm steps."""
    import dispkin

    per_pass = 100
    poses = []
    k = 0
    while len(poses) < moves + 1:
        y = 0.002 * k
        xs = [0.0005 * i for i in range(per_pass)]
        if k % 2:
            xs.reverse()
        for x in xs:
            z = 0.002 * math.sin(x / 0.007) * math.cos(y / 0.011)
            poses.append(dispkin.Pose.from_xyzuvw([x, y, z, 0.0, 0.0, 0.0]))
        k += 1
    return poses[: moves + 1]


def five_axis_poses(moves, seed=7):
    """Steps of 2–6 mm, each turning by 10–45° from the one before; the tool tilts by ≤ 2°."""
    import dispkin

    rng = random.Random(seed)
    x = y = z = 0.0
    heading, tilt_a, tilt_b = 0.0, 0.0, 0.0
    poses = [dispkin.Pose.from_xyzuvw([x, y, z, tilt_a, tilt_b, 0.0])]
    for _ in range(moves):
        heading += math.radians(rng.uniform(10.0, 45.0)) * rng.choice((-1.0, 1.0))
        step = rng.uniform(0.002, 0.006)
        x += step * math.cos(heading)
        y += step * math.sin(heading)
        z += rng.uniform(-0.0005, 0.0005)
        tilt_a = max(-20.0, min(20.0, tilt_a + rng.uniform(-2.0, 2.0)))
        tilt_b = max(-20.0, min(20.0, tilt_b + rng.uniform(-2.0, 2.0)))
        poses.append(dispkin.Pose.from_xyzuvw([x, y, z, tilt_a, tilt_b, 0.0]))
    return poses


WORKLOADS = {"cam": (cam_poses, 1e-4), "five_axis": (five_axis_poses, 5e-4)}


def pose_list(poses):
    import dispkin

    path = dispkin.Path.lin(poses[0], poses[1])
    for a, b in zip(poses[1:], poses[2:]):
        path.then(dispkin.Path.lin(a, b))
    return path


def measure(workload, moves, rounds):
    import dispkin
    from dispkin.shapes import icosahedron

    make, corner = WORKLOADS[workload]
    tool = dispkin.MetricSet()
    tool.add_relative(icosahedron(0.01))
    limits = dispkin.Limits(0.05, 1.0, 20.0)
    path = pose_list(make(moves))
    gc.collect()
    base_peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024
    base = resident_bytes()
    start = time.thread_time_ns()
    traj = dispkin.plan(path, tool, limits, corner_tolerance=corner)
    first = (time.thread_time_ns() - start) * 1e-9
    gc.collect()
    resident = resident_bytes() - base
    peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024 - base_peak
    pickled = len(pickle.dumps(traj, protocol=pickle.HIGHEST_PROTOCOL))
    times = [first]
    for _ in range(rounds - 1):
        start = time.thread_time_ns()
        dispkin.plan(path, tool, limits, corner_tolerance=corner)
        times.append((time.thread_time_ns() - start) * 1e-9)
    return {
        "moves": moves,
        "sections": len(traj.section_lengths()),
        "resident_per_move": resident / moves,
        "peak_growth_mb": peak / 1e6,
        "pickle_per_move": pickled / moves,
        "ms_per_1000_moves": statistics.median(times) * 1e3 / moves * 1000,
        "duration": traj.duration,
    }


def compare(before, after, runs=(("cam", 4682), ("five_axis", 200)), rounds=3):
    rows = []
    for workload, moves in runs:
        results = {"before": [], "after": []}
        pythons = [("before", before), ("after", after)]
        for r in range(rounds):
            for label, python in pythons[r % 2 :] + pythons[: r % 2]:
                out = subprocess.run(
                    [python, __file__, "--measure", workload, str(moves), "1"],
                    capture_output=True,
                    text=True,
                    check=True,
                )
                results[label].append(json.loads(out.stdout))
        rows.append((workload, moves, results))
    print(
        "| workload | moves | | sections | resident B/move | pickle B/move | peak growth MB | ms / 1000 moves | duration s |"
    )
    print("|---|---:|---|---:|---:|---:|---:|---:|---:|")
    for workload, moves, results in rows:
        for label in ("before", "after"):
            rs = results[label]
            med = lambda key: statistics.median(r[key] for r in rs)  # noqa: E731
            print(
                f"| {workload} | {moves} | {label} | {rs[0]['sections']} | {med('resident_per_move'):.0f} | "
                f"{rs[0]['pickle_per_move']:.0f} | {med('peak_growth_mb'):.1f} | {med('ms_per_1000_moves'):.1f} | "
                f"{rs[0]['duration']:.4f} |"
            )


if __name__ == "__main__":
    if sys.argv[1] == "--measure":
        print(json.dumps(measure(sys.argv[2], int(sys.argv[3]), int(sys.argv[4]))))
    else:
        compare(sys.argv[2], sys.argv[3])
