"""02 — a hexapod scan: rotate a fibre end about a pivot, legs kept in range and below their speed.

A symmetric 6-6 hexapod carries a fibre whose end sits 50 mm above the platform centre. The
fibre end is both the tool frame (platform coordinates) and the work frame (world coordinates):
the scan commands XYZUVW of the tool frame in the work frame, which tilts the platform ±5° about
the fibre end (the pivot) in three LIN moves. The metric set is a spherical shell of 10 mm around
the fibre end (the angular scan of the DISP patent JP7742490B2). The leg speed is held either by
rule (a), the six upper leg joints as a group held to the leg speed, or by rule (b), the joint-space
metric (plan(..., joint_metric=hexapod)); both are checked densely and their durations compared.
(The C++ twin is 02_hexapod_scan.cpp.)
"""

import math

import numpy as np

import dispkin

hexapod = dispkin.Hexapod.symmetric(
    base_radius=0.12,
    base_gap=math.radians(20),
    platform_radius=0.08,
    platform_gap=math.radians(20),
    height=0.15,
    leg_min=0.13,
    leg_max=0.20,
    leg_speed=0.01,
)
home = hexapod.forward(hexapod.inverse(dispkin.Pose.from_xyzuvw([0, 0, 0.15, 0, 0, 0])))
fibre_end = np.array([0.0, 0.0, 0.05])  # platform coordinates
frames = dispkin.WorkToolFrames(
    work=dispkin.Pose.from_xyzuvw([0, 0, 0.20, 0, 0, 0]), tool=dispkin.Pose.from_xyzuvw([*fibre_end, 0, 0, 0])
)
pivot = frames.pivot

shell = dispkin.MetricSet()
shell.add_relative(dispkin.shapes.spherical_shell(0.01, 40, pivot))
shell.set_group_speed(0, 0.002)  # the fibre end region: 2 mm/s
scan = dispkin.MetricSet()
scan.add_relative(dispkin.shapes.spherical_shell(0.01, 40, pivot))
scan.set_group_speed(0, 0.002)
hexapod.add_leg_speed_group(scan, 1)  # rule (a): the six upper joints held to the leg speed

tilts = [(0, 0), (5, 0), (-5, 0), (0, 5)]
poses = [frames.platform_pose_xyzuvw([0, 0, 0, math.radians(u), math.radians(v), 0]) for u, v in tilts]
path = dispkin.Path.lin(poses[0], poses[1], pivot=pivot)
for a, b in zip(poses[1:], poses[2:]):
    path.then(dispkin.Path.lin(a, b, pivot=pivot))

limits = dispkin.Limits(velocity=0.01, acceleration=0.05, jerk=0.5)
traj = dispkin.plan(path, scan, limits)
check = hexapod.check_trajectory(traj, 1e-3)
print(f"scan: {len(tilts) - 1} tilts about the fibre end, {traj.duration:.2f} s, {traj.piece_count} stops")
print(
    f"leg lengths {check.min_length.min() * 1000:.2f} .. {check.max_length.max() * 1000:.2f} mm "
    f"(range {0.13 * 1000:.0f} .. {0.20 * 1000:.0f} mm)"
)
print(f"fastest leg {check.max_speed.max() * 1000:.3f} mm/s (limit {0.01 * 1000:.0f} mm/s); within limits: {check.ok}")
assert check.ok

# Rule (b): no leg group in the set; each section is made long enough for the fastest leg.
traj_b = dispkin.plan(path, shell, limits, joint_metric=hexapod)
check_b = hexapod.check_trajectory(traj_b, 1e-3)
print(
    f"rule (b), joint-space metric: {traj_b.duration:.2f} s (rule (a): {traj.duration:.2f} s), "
    f"fastest leg {check_b.max_speed.max() * 1000:.3f} mm/s; within limits: {check_b.ok}"
)
assert check_b.ok

# Leg lengths and the fastest point's speed over time (needs matplotlib: pip install dispkin[plot]).
try:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ImportError:
    print("matplotlib is not installed: no plot")
else:
    from dispkin import plots

    figure, (top, bottom) = plt.subplots(2, 1, figsize=(7, 6), sharex=True, constrained_layout=True)
    plots.leg_lengths(hexapod, traj, ax=top)
    plots.point_speed(traj, scan, system_velocity=limits.velocity, ax=bottom)
    top.set_title("hexapod scan about the fibre end")
    plots.save([top], "02_hexapod_scan.png")
    print("plot: 02_hexapod_scan.png")
