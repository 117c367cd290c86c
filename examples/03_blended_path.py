"""03 — a blended LIN–CIRC–LIN path: through both via points without stopping.

A tool 0.2 m long (an icosahedron of points around its tip and its flange) moves along a
LIN, a CIRC and a LIN. Unblended, the planner must stop at both via points (the direction of motion
jumps there). With blends of 30 mm the corners become smooth pose curves (the boundary smoothing of
the Mamezou trajectory article, Ishii, "Algorithm 2 for Robot Manipulator Control"), the whole path
is one rest-to-rest move, and it is done sooner — with no point of the tool ever faster than the
limit. (The C++ twin is 03_blended_path.cpp.)
"""

import math

import numpy as np

import dispkin


def pose(x, y, yaw_degrees):
    return dispkin.Pose.from_xyzuvw([x, y, 0.0, 0.0, 0.0, math.radians(yaw_degrees)])


start, p1, via, p2, end = pose(0, 0, 0), pose(0.3, 0, 10), pose(0.45, 0.1, 20), pose(0.3, 0.2, 30), pose(0, 0.2, 40)

tool = dispkin.MetricSet()
tool.add_relative(dispkin.shapes.icosahedron(0.02, [0, 0, 0]))  # around the flange
tool.add_relative(dispkin.shapes.icosahedron(0.02, [0, 0, 0.2]))  # around the tool tip
limits = dispkin.Limits(velocity=0.25, acceleration=1.0, jerk=10.0)


def build(blend):
    path = dispkin.Path.lin(start, p1)
    path.then(dispkin.Path.circ(p1, via, p2), blend=blend)
    path.then(dispkin.Path.lin(p2, end), blend=blend)
    return path


def peak_point_speed(traj, step=1e-3):
    t = np.linspace(0.0, traj.duration, int(traj.duration / step) + 2)
    poses, twists = traj.sample(t), traj.body_twist(t)
    return max(dispkin.max_point_speed(tool, dispkin.Pose.from_matrix(m), xi) for m, xi in zip(poses, twists))


sharp, smooth = build(None), build(0.03)
for name, path in (("sharp corners", sharp), ("blended 30 mm", smooth)):
    traj = dispkin.plan(path, tool, limits)
    print(
        f"{name}: {len(path)} sections, {traj.piece_count} rest-to-rest piece(s), {traj.duration:.3f} s, "
        f"fastest tool point {peak_point_speed(traj):.4f} m/s (limit {limits.velocity} m/s)"
    )

blended = dispkin.plan(smooth, tool, limits)
assert blended.piece_count == 1
assert blended.duration < dispkin.plan(sharp, tool, limits).duration

try:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ImportError:
    print("matplotlib is not installed: no plot")
else:
    from dispkin import plots

    figure, (left, right) = plt.subplots(1, 2, figsize=(10, 4), constrained_layout=True)
    plots.path_xy(sharp, ax=left, label="LIN–CIRC–LIN", linestyle="--", color="grey")
    plots.path_xy(smooth, ax=left, label="blended, 30 mm", color="C0")
    left.plot([p.translation[0] for p in (p1, p2)], [p.translation[1] for p in (p1, p2)], "ko", label="via points")
    left.legend()
    left.set_title("flange track")
    plots.point_speed(blended, tool, system_velocity=limits.velocity, ax=right)
    right.set_title("blended: one move, no stop at the via points")
    plots.save([left], "03_blended_path.png")
    print("plot: 03_blended_path.png")
