"""Joint-limit prediction and the re-timing loop of the KUKA re-timing patent ("The robot drives
through a preset working track") from Python (doc/retiming.md §1–3)."""

import pathlib

import numpy as np
import pytest

import dispkin

pytestmark = pytest.mark.skipif(not hasattr(dispkin, "SerialArm"), reason="built without the serial-arm plugin")

URDF = pathlib.Path(__file__).resolve().parents[1] / "data" / "urdf" / "arm_ur5e_dh.urdf"


def move():
    arm = dispkin.SerialArm.from_urdf(str(URDF), "base_link", "tool0")
    q = np.array([0.3, -1.2, 1.5, -1.9, -1.57, 0.2])
    a = arm.forward(q)
    b = dispkin.Pose.from_xyzuvw([0.25, -0.1, -0.1, 0, 0, 0.5]) * a
    b = dispkin.Pose(b.quaternion, a.translation + np.array([0.25, -0.1, -0.1]))
    tool = dispkin.MetricSet()
    tool.add_relative(dispkin.shapes.icosahedron(0.05, [0, 0, 0.1]))
    return arm, q, dispkin.Path.lin(a, b), tool


def test_check_reports_factors_and_samples():
    arm, q, path, tool = move()
    traj = dispkin.plan(path, tool, dispkin.Limits(6.0, 100.0, 4000.0))
    report = dispkin.check_joint_limits(traj, arm, q)
    assert report.velocity_factor > 1.5 and not report.within_limits
    samples = report.samples
    assert samples["q"].shape == (len(samples["time"]), 6)
    np.testing.assert_allclose(samples["q"][0], q, atol=1e-9)
    assert 0 <= report.velocity_joint < 6 and 0 <= report.velocity_time <= traj.duration


def test_retime_by_scaling_converges_within_the_limits():
    arm, q, path, tool = move()
    result = dispkin.retime(path, tool, dispkin.Limits(1.5, 400.0, 1e5), arm, q)
    assert result.report.within_limits and result.iterations >= 2
    dense = dispkin.check_joint_limits(result.trajectory, arm, q, samples_between=200)
    assert dense.acceleration_factor <= 1.01 and dense.velocity_factor <= 1.001
    with pytest.raises(ValueError, match='method = "fastest"'):
        dispkin.retime(path, tool, dispkin.Limits(1.5, 400.0, 1e5), arm, q, method="fastest")
