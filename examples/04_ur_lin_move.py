"""04 — a LIN move of a UR5e in Cartesian space, and the joint path that drives it.

The UR5e shipped with the package (dispkin.data.path("ur5e.urdf"), written from its DH table) carries a 150 mm tool
along its flange axis. The move: 200 mm along base x, 100 mm along y and 100 mm down while the tool turns 30°
about its own axis, planned so that no point of the tool (its tip and a 40 mm ball around the
flange) exceeds 0.25 m/s. Each sampled pose is solved by the analytic IK (`three_parallel`
family, all solutions) and the solution nearest to the previous one is kept (`follow`).
(The C++ twin is 04_ur_lin_move.cpp.)
"""

import math

import numpy as np

import dispkin

arm = dispkin.SerialArm.from_urdf(dispkin.data.path("ur5e.urdf"), "base_link", "tool0")
q_start = np.array([0.0, -1.9, 1.9, -1.57, -1.57, 0.0])
start = arm.forward(q_start)
goal = (
    dispkin.Pose((1, 0, 0, 0), (0.2, 0.1, -0.1)) * start * dispkin.Pose.from_xyzuvw([0, 0, 0, 0, 0, math.radians(30)])
)

tool = dispkin.MetricSet()
tool.add_relative((0.0, 0.0, 0.15))  # the tool tip, tool0 coordinates
tool.add_sphere((0.0, 0.0, 0.0), 0.04)
traj = dispkin.plan(dispkin.Path.lin(start, goal), tool, dispkin.Limits(velocity=0.25, acceleration=1.0, jerk=10.0))

times = np.linspace(0.0, traj.duration, 11)
poses = [dispkin.Pose.from_matrix(m) for m in traj.sample(times)]
joints = arm.follow(poses, q_start)
print(f"{arm.robot_name}: family {arm.family}, LIN move of {traj.duration:.3f} s")
print("   t/s   " + "  ".join(f"{name[:11]:>11}" for name in arm.joint_names))
for t, q in zip(times, joints):
    print(f"{t:7.3f}  " + "  ".join(f"{v:11.5f}" for v in q))
worst = max(np.abs(arm.forward(q).matrix() - p.matrix()).max() for q, p in zip(joints, poses))
steps = np.abs(np.diff(joints, axis=0)).max()
print(f"largest pose error {worst:.1e}, largest joint step between samples {steps:.3f} rad")
assert worst <= 1e-10 and steps < 0.5
