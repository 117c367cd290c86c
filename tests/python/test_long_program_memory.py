"""Memory in proportion to the moves: a long blended pose list planned in continuous-path mode
keeps its trajectory and its pickle within a fixed number of bytes per move, because each corner
blend is a few sections whose bounds are their exact peaks (doc/section-length.md eqs. 25–29),
not one section per milliradian of the corner's turn (doc/planning.md §9, eq. 33), and the
pieces the planner cuts are kept as parts of their sections (doc/planning.md §13)."""

import os
import subprocess
import sys
import textwrap

MOVES = 20000

# Under AddressSanitizer (`make sanitize-python` preloads it) every allocation carries red zones
# and freed blocks wait in a quarantine, so the process's resident size measures the sanitizer,
# not dispkin: there the sections and the pickle are still held to their bounds, the resident
# size is not.
SANITIZED = "libasan" in os.environ.get("LD_PRELOAD", "")

# A raster over a smooth freeform surface in 0.5 mm steps, passes 2 mm apart (corners of a few
# degrees along a pass, two of 90° at each step-over), blended within 0.1 mm; measured in a
# fresh interpreter so that nothing else of the test run is resident.
MEASURE = textwrap.dedent(
    """
    import ctypes, gc, json, math, pickle, resource, sys
    import dispkin
    from dispkin.shapes import icosahedron

    def resident():
        ctypes.CDLL("libc.so.6").malloc_trim(0)
        with open("/proc/self/statm") as f:
            return int(f.read().split()[1]) * resource.getpagesize()

    moves = int(sys.argv[1])
    poses, k = [], 0
    while len(poses) < moves + 1:
        xs = [0.0005 * i for i in range(100)]
        for x in reversed(xs) if k % 2 else xs:
            z = 0.002 * math.sin(x / 0.007) * math.cos(0.002 * k / 0.011)
            poses.append(dispkin.Pose.from_xyzuvw([x, 0.002 * k, z, 0.0, 0.0, 0.0]))
        k += 1
    path = dispkin.Path.lin(poses[0], poses[1])
    for a, b in zip(poses[1:moves], poses[2:moves + 1]):
        path.then(dispkin.Path.lin(a, b))
    tool = dispkin.MetricSet()
    tool.add_relative(icosahedron(0.01))
    gc.collect()
    before = resident()
    traj = dispkin.plan(path, tool, dispkin.Limits(0.05, 1.0, 20.0), corner_tolerance=1e-4)
    del path
    gc.collect()
    print(json.dumps({"resident": resident() - before, "pickle": len(pickle.dumps(traj, pickle.HIGHEST_PROTOCOL)),
                      "sections": len(traj.section_lengths()), "stops": len(traj.stops)}))
    """
)


def test_a_long_blended_pose_list_keeps_memory_and_pickle_per_move_bounded():
    import json

    out = subprocess.run([sys.executable, "-c", MEASURE, str(MOVES)], capture_output=True, text=True, check=True)
    m = json.loads(out.stdout)
    assert m["stops"] == 0, "every corner of the raster is blended"
    # A move is a LIN and a blend, kept once each; the pieces the planner cuts them into (the two
    # 90° step-overs of a pass, 100 moves, take about 150 each) are kept as where they lie in
    # them (doc/planning.md §13): 4.5 pieces, 1.24 kB resident and 0.83 kB pickled per move.
    # With every piece a section of its own it was 2.1 kB and 1.5 kB, and when each blend was
    # cut per milliradian of its turn 27 sections, 14 kB and 9.6 kB (benchmarks/history/
    # 2026-12-04-long-blended-pose-lists-sections-kept-once.md).
    assert m["sections"] <= 6 * MOVES, m
    if not SANITIZED:
        assert m["resident"] <= 1600 * MOVES, m
    assert m["pickle"] <= 1000 * MOVES, m
