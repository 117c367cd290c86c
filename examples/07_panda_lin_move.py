"""07 — a LIN move of a seven-joint arm: the Franka Panda, its redundancy, re-timing and a plot.

The Panda of example-robot-data (pip install example-robot-data) is a 7R arm; dispkin solves it
along a redundancy parameter, the locked joint q7 (family `locked_joint`, doc/inverse-kinematics.md
§11): every IK solution at one value of q7 in closed form. The move: 150 mm along x, 100 mm along
y, 100 mm down while the tool turns 20° about its own axis, with no point of the tool (its tip and
a 50 mm ball around the flange) faster than 0.25 m/s.

- `follow` walks the sampled poses from q_start; by default it moves q7 away from the joint limits
  and singular poses at a bounded rate (§12), with move_redundancy=False it keeps q7 at q_start's.
- `retime` slows the Cartesian plan where the joints (q7 kept at q_start's value) would exceed
  their speed or torque limits, and `check_joint_limits` confirms it densely.
The plot (07_panda_lin_move.png) shows the re-timed joints against their limits.
"""

import importlib.metadata
import math
import pathlib
import sys

import numpy as np

import dispkin

try:
    robots = importlib.metadata.distribution("example-robot-data").locate_file(
        "cmeel.prefix/share/example-robot-data/robots"
    )
except importlib.metadata.PackageNotFoundError:
    sys.exit("07_panda_lin_move needs the Panda of example-robot-data: pip install example-robot-data")
urdf = (pathlib.Path(robots) / "panda_description" / "urdf" / "panda.urdf").read_text()

arm = dispkin.SerialArm.from_urdf(urdf, "panda_link0", "panda_hand")
q_start = np.array([0.1, -0.4, 0.2, -2.0, 0.1, 1.8, 0.7])
start = arm.forward(q_start)
goal = (
    dispkin.Pose((1, 0, 0, 0), (0.15, 0.1, -0.1)) * start * dispkin.Pose.from_xyzuvw([0, 0, 0, 0, 0, math.radians(20)])
)
path = dispkin.Path.lin(start, goal)

tool = dispkin.MetricSet()
tool.add_relative((0.0, 0.0, 0.1))  # the tool tip, panda_hand coordinates
tool.add_sphere((0.0, 0.0, 0.0), 0.05)
limits = dispkin.Limits(velocity=0.25, acceleration=1.0, jerk=10.0)
traj = dispkin.plan(path, tool, limits)
print(
    f"{arm.robot_name}: family {arm.family}, redundancy {arm.redundancy.kind} "
    f"({arm.redundancy.joint_name} in [{arm.redundancy.lower:.3f}, {arm.redundancy.upper:.3f}])"
)

poses = [dispkin.Pose.from_matrix(m) for m in traj.sample(np.linspace(0.0, traj.duration, 41))]
moved = arm.follow(poses, q_start)
kept = arm.follow(poses, q_start, move_redundancy=False)
for name, joints in (("q7 moved by the rule", moved), ("q7 kept", kept)):
    worst = max(np.abs(arm.forward(q).matrix() - p.matrix()).max() for q, p in zip(joints, poses))
    steps = np.abs(np.diff(joints, axis=0)).max()
    print(
        f"follow, {name}: q7 from {joints[0, 6]:.4f} to {joints[-1, 6]:.4f} rad, largest joint step "
        f"{steps:.4f} rad, largest pose error {worst:.1e}"
    )
    assert np.abs(joints[0] - q_start).max() <= 1e-9 and steps <= 0.3 and worst <= 1e-10

fast = dispkin.Limits(velocity=1.5, acceleration=20.0, jerk=400.0)
retimed = dispkin.retime(path, tool, fast, arm, q_start, profile="scurve", method="optimal")
report = dispkin.check_joint_limits(retimed.trajectory, arm, q_start, samples_between=20)
samples = report.samples
joint_limits = arm.joint_limits
print(
    f"re-timed for the joints: {retimed.trajectory.duration:.3f} s (planned for the tool alone at "
    f"{fast.velocity} m/s: {dispkin.plan(path, tool, fast).duration:.3f} s); joint speed / limit "
    f"{np.max(np.abs(samples['qd']) / joint_limits.velocity):.3f}"
)
assert np.all(np.abs(samples["qd"]) <= joint_limits.velocity)
assert np.all(np.abs(samples["static_torque"] + samples["dynamic_torque"]) <= joint_limits.effort)

if __name__ == "__main__":
    import matplotlib

    matplotlib.use("Agg")
    from dispkin import plots

    axes = plots.joint_limits(
        samples["time"],
        arm.joint_names,
        samples["q"],
        samples["qd"],
        joint_limits.lower,
        joint_limits.upper,
        joint_limits.velocity,
    )
    plots.save(axes, "07_panda_lin_move.png")
    print("wrote 07_panda_lin_move.png")
