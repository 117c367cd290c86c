"""Durations of the jerk-limited optimal re-timing (doc/retiming.md §6) against the jerk-free
optimum, TOPP-RA (`toppra`, no jerk limit) and the scaling loop of the KUKA re-timing patent
("The robot drives through a preset working track") with S-curves.

Cases: example 05's UR5e LIN (350 mm, 30° turn; the velocity + torque limits of the URDF), the
test suite's UR5e LIN and CIRC (290 mm, 0.5 rad turn), each requested at DISP limits the joints
cannot follow, with a range of jerk limits; and a slow move where only the DISP limits bind
(there the jerk-limited optimum should be the S-curve). Prints a Markdown table.

Usage:  .venv/bin/python benchmarks/retime_jerk_durations.py
"""

import pathlib

import numpy as np
import toppra
import toppra.algorithm
import toppra.constraint

import dispkin

ROOT = pathlib.Path(__file__).resolve().parents[1]
arm = dispkin.SerialArm.from_urdf(str(ROOT / "tests/data/urdf/arm_ur5e_dh.urdf"), "base_link", "tool0")
Q0 = np.array([0.3, -1.2, 1.5, -1.9, -1.57, 0.2])
tool = dispkin.MetricSet()
tool.add_relative(dispkin.shapes.icosahedron(0.05, [0, 0, 0.1]))
start = arm.forward(Q0)


def example05():
    turned = dispkin.Pose.from_xyzuvw([0, 0, 0, 0, 0, np.radians(30)]) * start
    return dispkin.Path.lin(start, dispkin.Pose(turned.quaternion, start.translation + np.array([0.25, -0.2, -0.15])))


def test_move(kind):
    turned = dispkin.Pose.from_xyzuvw([0, 0, 0, 0, 0, 0.5]) * start
    b = dispkin.Pose(turned.quaternion, start.translation + np.array([0.25, -0.1, -0.1]))
    if kind == "lin":
        return dispkin.Path.lin(start, b)
    via = dispkin.Pose(start.quaternion, start.translation + np.array([0.15, 0.05, -0.02]))
    return dispkin.Path.circ(start, via, b)


def toppra_duration(path, grid=100):
    samples = dispkin.check_joint_limits(
        dispkin.plan(path, tool, dispkin.Limits(0.1, 1.0), profile="trapezoid"), arm, Q0, samples_between=20
    ).samples
    s, keep = np.unique(samples["s"], return_index=True)
    limits = arm.joint_limits
    constraints = [
        toppra.constraint.JointVelocityConstraint(np.column_stack([-limits.velocity, limits.velocity])),
        toppra.constraint.JointTorqueConstraint(
            lambda q, qd, qdd: arm.torques(q, qd, qdd), np.column_stack([-limits.effort, limits.effort]), np.zeros(6)
        ),
    ]
    instance = toppra.algorithm.TOPPRA(
        constraints,
        toppra.SplineInterpolator(s, samples["q"][keep]),
        gridpoints=np.linspace(s[0], s[-1], grid + 1),
        parametrizer="ParametrizeConstAccel",
    )
    return instance.compute_trajectory(0, 0).duration


CASES = [
    ("example 05 LIN", example05(), 3.0, 400.0, [100.0, 1000.0, 10000.0]),
    ("test LIN", test_move("lin"), 1.5, 400.0, [150.0, 1500.0]),
    ("test CIRC", test_move("circ"), 1.5, 400.0, [150.0, 1500.0]),
    ("test LIN, DISP-bound", test_move("lin"), 0.3, 2.0, [20.0]),
]

print(
    "| move | v, a (DISP) | jerk | jerk-free optimal | toppra (no jerk) | jerk-limited optimal | window T | "
    "cost vs jerk-free | S-curve plan (no joint limits) | scaling, S-curve |"
)
print("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|")
for name, path, v, a, jerks in CASES:
    plain = dispkin.retime(path, tool, dispkin.Limits(v, a), arm, Q0, profile="trapezoid", method="optimal")
    theirs = toppra_duration(path)
    for j in jerks:
        limits = dispkin.Limits(v, a, j)
        jerked = dispkin.retime(path, tool, limits, arm, Q0, profile="scurve", method="optimal")
        try:
            scaled = f"{dispkin.retime(path, tool, limits, arm, Q0, profile='scurve', method='scaling').trajectory.duration:.4f} s"
        except RuntimeError:
            scaled = "does not converge"
        scurve = dispkin.plan(path, tool, limits, profile="scurve").duration
        d0, d1 = plain.trajectory.duration, jerked.trajectory.duration
        print(
            f"| {name} | {v:g} m/s, {a:g} m/s² | {j:g} | {d0:.4f} s | {theirs:.4f} s | {d1:.4f} s | "
            f"{jerked.jerk_window * 1e3:.1f} ms | +{(d1 / d0 - 1) * 100:.1f} % | {scurve:.4f} s | "
            f"{scaled} |"
        )
