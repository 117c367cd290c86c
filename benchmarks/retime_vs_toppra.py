"""Joint-limit check and re-timing on a 6-axis arm move, against TOPP-RA (`toppra`) in the same run.

The move is example 05's UR5e LIN (350 mm, 30° turn, requested at 3 m/s and 400 m/s² for a tool
ball). dispkin's optimal re-timing includes everything it does per call: planning the DISP
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
arm = dispkin.SerialArm.from_urdf(str(ROOT / "tests/data/urdf/arm_ur5e_dh.urdf"), "base_link", "tool0")
q_start = np.array([0.3, -1.2, 1.5, -1.9, -1.57, 0.2])
start = arm.forward(q_start)
turned = dispkin.Pose.from_xyzuvw([0, 0, 0, 0, 0, np.radians(30)]) * start
path = dispkin.Path.lin(start, dispkin.Pose(turned.quaternion, start.translation + np.array([0.25, -0.2, -0.15])))
tool = dispkin.MetricSet()
tool.add_relative(dispkin.shapes.icosahedron(0.05, [0, 0, 0.1]))
fast = dispkin.Limits(3.0, 400.0)
ACCELERATION = np.array([8.0, 8.0, 8.0, 12.0, 12.0, 12.0])
GRID = 100

# The joint path for toppra: dispkin's q(s), sampled.
samples = dispkin.check_joint_limits(
    dispkin.plan(path, tool, fast, profile="trapezoid"), arm, q_start, samples_between=20
).samples
s, keep = np.unique(samples["s"], return_index=True)
pick = np.linspace(0, len(s) - 1, 101).round().astype(int)
s_knots, q_knots = s[pick], samples["q"][keep][pick]
limits = arm.joint_limits


def toppra_run(with_torque):
    spline = toppra.SplineInterpolator(s_knots, q_knots)
    constraints = [toppra.constraint.JointVelocityConstraint(np.column_stack([-limits.velocity, limits.velocity]))]
    if with_torque:
        constraints.append(
            toppra.constraint.JointTorqueConstraint(
                lambda q, qd, qdd: arm.torques(q, qd, qdd),
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
        gridpoints=np.linspace(s_knots[0], s_knots[-1], GRID + 1),
        parametrizer="ParametrizeConstAccel",
    )
    return instance.compute_trajectory(0, 0).duration


def ours(with_torque, check):
    r = dispkin.retime(
        path,
        tool,
        fast,
        arm,
        q_start,
        profile="trapezoid",
        method="optimal",
        grid_intervals=GRID,
        joint_acceleration=None if with_torque else ACCELERATION,
        torque_limits=with_torque,
        samples_between=check,
    )
    return r.trajectory.duration


def scaling():
    return dispkin.retime(path, tool, fast, arm, q_start, profile="trapezoid", method="scaling").trajectory.duration


def check():
    return dispkin.check_joint_limits(dispkin.plan(path, tool, fast, profile="trapezoid"), arm, q_start).velocity_factor


def timed(f, values, name):
    """A block: one call of f on this thread, its value kept in values[name]; its CPU time (s)."""

    def block():
        start = time.thread_time()
        values[name] = f()
        return time.thread_time() - start

    return block


def main():
    repeats = int(sys.argv[1]) if len(sys.argv) > 1 else 20
    rows = [
        ("check_joint_limits (samples_between=10)", check),
        ("retime scaling (velocity + torque)", scaling),
    ]
    groups = []
    for with_torque, label in ((False, "velocity + acceleration"), (True, "velocity + torque")):
        groups.append(
            [
                (f"dispkin optimal, {label}, dense check 3", lambda w=with_torque: ours(w, 3)),
                (f"dispkin optimal, {label}, check 0 (ends and middles only)", lambda w=with_torque: ours(w, 0)),
                (f"toppra, {label}", lambda w=with_torque: toppra_run(w)),
            ]
        )
    rows += [row for group in groups for row in group]
    # Alternating rounds (cpu_rounds.py): every row once per round, starting from another row
    # each round, so that a slow spell of the machine falls on all of them alike; the median over
    # the rounds per row.
    values = {}
    times = alternating_rounds({name: timed(f, values, name) for name, f in rows}, repeats)
    median = {name: statistics.median(times[name]) for name, _ in rows}
    print(f"CPU time (time.thread_time), median of {repeats} alternating rounds")
    print(f"{'what':70s} {'median':>10s} {'duration':>10s} {'toppra/this':>12s}")
    for group in groups:
        toppra_name = group[-1][0]
        for name, _ in group:
            ratio = median[toppra_name] / median[name]
            print(f"{name:70s} {median[name] * 1e3:7.2f} ms {values[name]:10.5f} {ratio:11.2f}x")
        ours_duration, toppra_duration = values[group[0][0]], values[toppra_name]
        print(f"{'  duration vs toppra':70s} {100.0 * (ours_duration / toppra_duration - 1.0):+9.3f} %")
    for name, _ in rows[:2]:
        print(f"{name:70s} {median[name] * 1e3:7.2f} ms {values[name]:10.5f}")


if __name__ == "__main__":
    main()
