"""05 — a UR5e move that is too fast for its joints, re-timed two ways.

The move (a LIN of 350 mm with a 30° turn of the tool) is planned at 3 m/s and 400 m/s² for
the tool points: the UR5e's joints cannot follow (joint speeds of 3.14 rad/s and torques of
150 / 28 N·m, from dispkin.data.path("ur5e.urdf")). Two re-timings keep every joint limit:
- "scaling", the loop of the KUKA re-timing patent ("The robot drives through a preset working
  track"): lower the whole move's speed and acceleration until the largest joint velocity and
  dynamic torque fit (FVEL, FACC ≤ 1);
- "optimal": the fastest timing that keeps the tool-point limits and the joint velocities and
  torques at once, slowing down only where a limit binds (reachability analysis over s) — and
  the same with a jerk limit on the tool points (profile="scurve").
The plot (05_joint_limit_retiming.png) shows joint speeds and torques against their limits.
(The C++ twin is 05_joint_limit_retiming.cpp.)
"""

import numpy as np

import dispkin

arm = dispkin.SerialArm.from_urdf(dispkin.data.path("ur5e.urdf"), "base_link", "tool0")
q_start = np.array([0.3, -1.2, 1.5, -1.9, -1.57, 0.2])
start = arm.forward(q_start)
turned = dispkin.Pose.from_xyzuvw([0, 0, 0, 0, 0, np.radians(30)]) * start
goal = dispkin.Pose(turned.quaternion, start.translation + np.array([0.25, -0.2, -0.15]))
path = dispkin.Path.lin(start, goal)
tool = dispkin.MetricSet()
tool.add_relative(dispkin.shapes.icosahedron(0.05, [0, 0, 0.1]))  # a 50 mm ball 100 mm out
fast = dispkin.Limits(velocity=3.0, acceleration=400.0)

requested = dispkin.plan(path, tool, fast, profile="trapezoid")
before = dispkin.check_joint_limits(requested, arm, q_start)
print(
    f"requested: {requested.duration:.3f} s, FVEL {before.velocity_factor:.2f}, FACC {before.acceleration_factor:.2f}"
)

scaled = dispkin.retime(path, tool, fast, arm, q_start, profile="trapezoid", method="scaling")
optimal = dispkin.retime(path, tool, fast, arm, q_start, profile="trapezoid", method="optimal")
print(
    f"scaling:   {scaled.trajectory.duration:.3f} s after {scaled.iterations} plans "
    f"(velocity {scaled.limits.velocity:.3f} m/s, acceleration {scaled.limits.acceleration:.1f} m/s²)"
)
print(
    f"optimal:   {optimal.trajectory.duration:.3f} s; largest joint speed / limit {optimal.velocity_ratio:.3f}, "
    f"torque / limit {optimal.torque_ratio:.3f}"
)
assert requested.duration < optimal.trajectory.duration <= scaled.trajectory.duration

# The same with a jerk limit on the tool points: each rest-to-rest run is averaged over a window T
# so that |s'''| <= jerk; the DISP and joint limits still hold, at a cost of about T.
smooth = dispkin.Limits(velocity=3.0, acceleration=400.0, jerk=2000.0)
jerked = dispkin.retime(path, tool, smooth, arm, q_start, profile="scurve", method="optimal")
print(
    f"optimal, jerk <= {smooth.jerk:g} m/s³: {jerked.trajectory.duration:.3f} s (window "
    f"{jerked.jerk_window * 1e3:.1f} ms); joint speed / limit {jerked.velocity_ratio:.3f}, "
    f"torque / limit {jerked.torque_ratio:.3f}"
)
assert optimal.trajectory.duration <= jerked.trajectory.duration

limits = arm.joint_limits
runs = {}
for name, result in (("scaling", scaled), ("optimal", optimal), ("optimal, jerk-limited", jerked)):
    samples = dispkin.check_joint_limits(result.trajectory, arm, q_start, samples_between=20).samples
    torque = samples["static_torque"] + samples["dynamic_torque"]
    assert np.all(np.abs(samples["qd"]) <= limits.velocity) and np.all(np.abs(torque) <= limits.effort)
    runs[name] = (samples["time"], np.abs(samples["qd"]) / limits.velocity, np.abs(torque) / limits.effort)

if __name__ == "__main__":
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(2, 3, figsize=(15, 6), sharey="row", constrained_layout=True)
    for column, (name, (t, speed, torque)) in enumerate(runs.items()):
        for row, (values, label) in enumerate(((speed, "|q̇| / q̇max"), (torque, "|τ| / τmax"))):
            ax = axes[row, column]
            for j, joint in enumerate(arm.joint_names):
                ax.plot(t, values[:, j], label=joint)
            ax.axhline(1.0, color="k", linestyle="--", linewidth=1)
            ax.set_ylabel(label)
            ax.set_xlabel("t / s")
        axes[0, column].set_title(f"{name}: {t[-1]:.3f} s")
    axes[0, 1].legend(fontsize=7, loc="lower center")
    fig.savefig("05_joint_limit_retiming.png", dpi=90)
    print("wrote 05_joint_limit_retiming.png")
