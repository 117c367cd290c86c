"""01 — the first DISP distance: how fast does a tool really move?

A 300 mm tool turns while its centre point (TCP) moves 50 mm. A controller that limits the TCP
speed and, separately, the angular speed lets the tool tip run faster than commanded. dispkin
measures the move with the metric set {tool tip, sphere around the TCP} instead, and plans it.
(The C++ twin is 01_disp_distance.cpp.)
"""

import math

import numpy as np

import dispkin

tool = dispkin.MetricSet()
tool.add_relative([0.0, 0.0, 0.3])  # the tool tip, 300 mm along z
tool.add_sphere([0.0, 0.0, 0.0], 0.1)  # 100 mm sphere around the TCP

start = dispkin.Pose()
end = dispkin.Pose.from_xyzuvw([0.05, 0.02, 0.0, math.radians(10), 0.0, math.radians(30)])

chord = dispkin.disp_distance(tool, start, end)
lin = dispkin.section_length(tool, start, end, interpolation="decoupled")
screw = dispkin.section_length(tool, start, end, interpolation="screw")

# The usual controller: TCP at v, rotation at v / eqradius (eqradius = the sphere radius).
v, eqradius = 0.1, 0.1
angle = np.linalg.norm(end.log()[3:])
tcp_only_duration = max(np.linalg.norm(end.translation - start.translation) / v, angle * eqradius / v)

print(f"chord distance            {chord:.6f} m")
print(f"LIN section length        {lin:.6f} m  -> {lin / v:.3f} s at {v:.2f} m/s")
print(f"screw section length      {screw:.6f} m  -> {screw / v:.3f} s")
print(
    f"TCP + angular limit       {tcp_only_duration:.3f} s: fastest point at {lin / tcp_only_duration:.3f} m/s "
    f"= {lin / tcp_only_duration / v:.2f} x the limit"
)

traj = dispkin.plan(dispkin.Path.lin(start, end), tool, dispkin.Limits(v, 0.5, jerk=5.0))
print(
    f"dispkin S-curve plan      {traj.duration:.3f} s, path speed never above {traj.path_velocity(np.linspace(0, traj.duration, 1001)).max():.4f} m/s"
)
assert chord <= lin * (1 + 1e-12)
