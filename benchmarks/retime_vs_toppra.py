"""Joint-limit check and re-timing on 6-axis arm moves, against TOPP-RA (`toppra`) in the same run.

Two moves. The project's benchmark is example 05's UR5e LIN (350 mm, 30° turn, requested at 3 m/s
and 400 m/s² for a tool ball). The large joint motion is a LIN of example-robot-data's UR5
(`ur5_robot.urdf`) between the poses of two configurations 0.1–1.2 rad apart joint by joint, under
DISP limits so slack (10 m/s, 1000 m/s²) that only the joint velocity and acceleration limits bind.
dispkin's optimal re-timing includes everything it does per call: planning the DISP
trajectory, the IK of the joint path at the grid points (one per point: q, with q′ and q″ in
closed form), the torque coefficients (two recursive Newton–Euler passes per point), the
reachability passes, and its dense check of the result (check_samples_between). toppra gets the
joint path ready made (a cubic spline through 100 samples of the same q(s)) and computes its
parameterisation on the same 100-interval grid; its time includes building the spline, the
constraints and the solver.

Times are CPU time of the calling thread (time.thread_time: dispkin releases the interpreter lock
but computes on this thread), in alternating rounds (dispkin and toppra one after the other, round
by round), medians per row; the last column is toppra's median over the row's.

Usage:  .venv/bin/python benchmarks/retime_vs_toppra.py [repeats]
"""

import importlib.metadata
import pathlib
import statistics
import sys
import time

import numpy as np
import toppra
import toppra.algorithm
import toppra.constraint

import dispkin
from cpu_rounds import alternating_rounds

ROOT = pathlib.Path(__file__).resolve().parents[1]
tool = dispkin.MetricSet()
tool.add_relative(dispkin.shapes.icosahedron(0.05, [0, 0, 0.1]))
ACCELERATION = np.array([8.0, 8.0, 8.0, 12.0, 12.0, 12.0])
GRID = 100


class Move:
    """A LIN of `arm` from q_start under the DISP limits `limits`, and its joint path for toppra:
    dispkin's q(s) at 101 samples of the plan's dense check."""

    def __init__(self, arm, q_start, path, limits):
        self.arm, self.q_start, self.path, self.limits = arm, q_start, path, limits
        samples = dispkin.check_joint_limits(
            dispkin.plan(path, tool, limits, profile="trapezoid"), arm, q_start, samples_between=20
        ).samples
        s, keep = np.unique(samples["s"], return_index=True)
        pick = np.linspace(0, len(s) - 1, 101).round().astype(int)
        self.s_knots, self.q_knots = s[pick], samples["q"][keep][pick]
        self.joint_motion = np.ptp(samples["q"], axis=0)


def project_move():
    """Example 05's UR5e LIN, requested at 3 m/s and 400 m/s²."""
    arm = dispkin.SerialArm.from_urdf(str(ROOT / "tests/data/urdf/arm_ur5e_dh.urdf"), "base_link", "tool0")
    q_start = np.array([0.3, -1.2, 1.5, -1.9, -1.57, 0.2])
    start = arm.forward(q_start)
    turned = dispkin.Pose.from_xyzuvw([0, 0, 0, 0, 0, np.radians(30)]) * start
    end = dispkin.Pose(turned.quaternion, start.translation + np.array([0.25, -0.2, -0.15]))
    return Move(arm, q_start, dispkin.Path.lin(start, end), dispkin.Limits(3.0, 400.0))


def large_move():
    """example-robot-data's UR5: a LIN between the poses of two configurations whose joints differ
    by 1.2, 0.5, 0.6, 0.3, 0.4 and 0.1 rad, the DISP limits slack (10 m/s, 1000 m/s²)."""
    robots = importlib.metadata.distribution("example-robot-data").locate_file(
        "cmeel.prefix/share/example-robot-data/robots"
    )
    urdf = pathlib.Path(robots) / "ur_description" / "urdf" / "ur5_robot.urdf"
    arm = dispkin.SerialArm.from_urdf(str(urdf), "base_link", "tool0")
    q_start = np.array([0.0, -1.6, 1.7, -1.7, -1.57, 0.0])
    q_end = q_start + np.array([1.2, 0.5, -0.6, 0.3, 0.4, 0.1])
    path = dispkin.Path.lin(arm.forward(q_start), arm.forward(q_end))
    return Move(arm, q_start, path, dispkin.Limits(10.0, 1000.0))


def toppra_run(move, with_torque):
    spline = toppra.SplineInterpolator(move.s_knots, move.q_knots)
    limits = move.arm.joint_limits
    constraints = [toppra.constraint.JointVelocityConstraint(np.column_stack([-limits.velocity, limits.velocity]))]
    if with_torque:
        constraints.append(
            toppra.constraint.JointTorqueConstraint(
                lambda q, qd, qdd: move.arm.torques(q, qd, qdd),
                np.column_stack([-limits.effort, limits.effort]),
                np.zeros(6),
            )
        )
    else:
        constraints.append(
            toppra.constraint.JointAccelerationConstraint(np.column_stack([-ACCELERATION, ACCELERATION]))
        )
    instance = toppra.algorithm.TOPPRA(
        constraints,
        spline,
        gridpoints=np.linspace(move.s_knots[0], move.s_knots[-1], GRID + 1),
        parametrizer="ParametrizeConstAccel",
    )
    return instance.compute_trajectory(0, 0).duration


def ours(move, with_torque, check):
    r = dispkin.retime(
        move.path,
        tool,
        move.limits,
        move.arm,
        move.q_start,
        profile="trapezoid",
        method="optimal",
        grid_intervals=GRID,
        joint_acceleration=None if with_torque else ACCELERATION,
        torque_limits=with_torque,
        samples_between=check,
    )
    return r.trajectory.duration


def scaling(move):
    return dispkin.retime(
        move.path, tool, move.limits, move.arm, move.q_start, profile="trapezoid", method="scaling"
    ).trajectory.duration


def check(move):
    trajectory = dispkin.plan(move.path, tool, move.limits, profile="trapezoid")
    return dispkin.check_joint_limits(trajectory, move.arm, move.q_start).velocity_factor


def timed(f, values, name):
    """A block: one call of f on this thread, its value kept in values[name]; its CPU time (s)."""

    def block():
        start = time.thread_time()
        values[name] = f()
        return time.thread_time() - start

    return block


def groups_of(move, label, with_torque):
    """dispkin's optimal re-timing with its dense check and with the characteristic points only,
    then toppra, on one move and one set of joint limits."""
    return [
        (f"{label}: dispkin optimal, dense check 3", lambda: ours(move, with_torque, 3)),
        (f"{label}: dispkin optimal, check 0 (ends and middles only)", lambda: ours(move, with_torque, 0)),
        (f"{label}: toppra", lambda: toppra_run(move, with_torque)),
    ]


def main():
    repeats = int(sys.argv[1]) if len(sys.argv) > 1 else 20
    project, large = project_move(), large_move()
    print("large joint motion: each joint moves", np.array2string(large.joint_motion, precision=2), "rad")
    rows = [
        ("UR5e LIN: check_joint_limits (samples_between=10)", lambda: check(project)),
        ("UR5e LIN: retime scaling (velocity + torque)", lambda: scaling(project)),
    ]
    groups = [
        groups_of(project, "UR5e LIN, velocity + acceleration", False),
        groups_of(project, "UR5e LIN, velocity + torque", True),
        groups_of(large, "UR5 large joint motion, velocity + acceleration", False),
    ]
    rows += [row for group in groups for row in group]
    # Alternating rounds (cpu_rounds.py): every row once per round, starting from another row
    # each round, so that a slow spell of the machine falls on all of them alike; the median over
    # the rounds per row.
    values = {}
    times = alternating_rounds({name: timed(f, values, name) for name, f in rows}, repeats)
    median = {name: statistics.median(times[name]) for name, _ in rows}
    print(f"CPU time (time.thread_time), median of {repeats} alternating rounds")
    print(f"{'what':75s} {'median':>10s} {'duration':>10s} {'toppra/this':>12s}")
    for group in groups:
        toppra_name = group[-1][0]
        for name, _ in group:
            ratio = median[toppra_name] / median[name]
            print(f"{name:75s} {median[name] * 1e3:7.2f} ms {values[name]:10.5f} {ratio:11.2f}x")
        ours_duration, toppra_duration = values[group[0][0]], values[toppra_name]
        print(f"{'  duration vs toppra':75s} {100.0 * (ours_duration / toppra_duration - 1.0):+9.3f} %")
    for name, _ in rows[:2]:
        print(f"{name:75s} {median[name] * 1e3:7.2f} ms {values[name]:10.5f}")


if __name__ == "__main__":
    main()
