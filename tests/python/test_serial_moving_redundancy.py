"""A seven-joint arm's redundancy parameter moved along a planned path (doc/inverse-kinematics.md
§14, eqs. 47–51): FollowedTrajectory, check_joint_limits and re-timing (both methods) with a
RedundancyRule see the joints of θ(s) — starting exactly at q_start, without jumps, with q̇ and q̈
that include the parameter's own rates — and keep the joint limits densely."""

import numpy as np
import pytest

import dispkin
from test_serial_seven_joints import panda_lin

pytestmark = pytest.mark.skipif(not hasattr(dispkin, "SerialArm"), reason="built without the serial-arm plugin")


@pytest.fixture(scope="module")
def lin():
    a, q, path, tool = panda_lin()
    return a, q, path, tool, dispkin.plan(path, tool, dispkin.Limits(1.0, 20.0, 400.0))


def test_the_followed_lin_moves_the_parameter_from_q_start_without_a_jump(lin):
    a, q, _, _, traj = lin
    moved = dispkin.FollowedTrajectory.from_start(traj, a, q, redundancy_rule=dispkin.RedundancyRule())
    assert np.array_equal(moved.start, q) and moved.midpoint_error <= 1e-10
    t = np.linspace(0.0, traj.duration, 2001)
    positions, velocities = moved.joint_positions(t), moved.joint_velocities(t)
    assert np.abs(positions[:, 6] - q[6]).max() > 1e-2  # the parameter does move
    assert np.abs(velocities[:, 6]).max() > 0.0
    # Never a jump: every step between samples within what the largest joint speed covers.
    dt = t[1] - t[0]
    assert np.all(np.abs(np.diff(positions, axis=0)) <= np.abs(velocities).max(axis=0) * dt * 1.001 + 1e-15)
    # q̇ is the derivative of q(t) (doc/inverse-kinematics.md eq. 47, θ′ included): central
    # differences agree (to 1e-4 rad/s of speeds up to 10 rad/s: h q̈'s step where the time law's s̈
    # steps; without θ′'s self-motion term q̇₇ alone would be off by up to 0.4 rad/s).
    h = 1e-7
    inner = t[1:-1]
    difference = (moved.joint_positions(inner + h) - moved.joint_positions(inner - h)) / (2 * h)
    assert np.abs(difference - velocities[1:-1]).max() <= 1e-4
    # The tip on the planned path.
    for k in range(0, len(t), 100):
        assert np.abs(a.forward(positions[k]).matrix() - traj.sample(t[k])).max() <= 1e-9
    # Held unless asked: the default and RedundancyRule.held() keep q₇ at q_start's value.
    for held in (
        dispkin.FollowedTrajectory.from_start(traj, a, q),
        dispkin.FollowedTrajectory.from_start(traj, a, q, redundancy_rule=dispkin.RedundancyRule.held()),
    ):
        assert np.abs(held.joint_positions(t)[:, 6] - q[6]).max() <= 1e-12


def test_the_check_sees_the_joints_the_followed_trajectory_gives(lin):
    a, q, _, _, traj = lin
    rule = dispkin.RedundancyRule()
    report = dispkin.check_joint_limits(traj, a, q, samples_between=20, redundancy_rule=rule)
    samples = report.samples
    assert np.abs(samples["q"][0] - q).max() <= 1e-14  # the IK at t = 0: q_start to rounding
    for x, time in zip(samples["q"], samples["time"]):
        assert np.abs(a.forward(x).matrix() - traj.sample(time)).max() <= 1e-10
    moved = dispkin.FollowedTrajectory.from_start(traj, a, q, redundancy_rule=rule)
    assert np.abs(samples["q"] - moved.joint_positions(samples["time"])).max() <= 1e-9
    assert np.abs(samples["qd"] - moved.joint_velocities(samples["time"])).max() <= 1e-6
    assert np.abs(samples["qd"][:, 6]).max() > 0.0
    held = dispkin.check_joint_limits(traj, a, q, samples_between=20)
    assert np.all(held.samples["qd"][:, 6] == 0.0)


def test_to_end_moves_the_parameter_backwards_from_q_end(lin):
    a, q, path, tool, traj = lin
    q_end = dispkin.FollowedTrajectory.from_start(traj, a, q).end
    moved = dispkin.FollowedTrajectory.to_end(traj, a, q_end, redundancy_rule=dispkin.RedundancyRule())
    assert np.array_equal(moved.end, q_end)
    assert abs(moved.start[6] - q_end[6]) > 1e-2
    assert np.abs(a.forward(moved.start).matrix() - traj.sample(0.0)).max() <= 1e-9


def test_retiming_by_scaling_keeps_the_limits_densely_with_the_parameter_moving(lin):
    a, q, path, tool, _ = lin
    rule = dispkin.RedundancyRule()
    scaled = dispkin.retime(
        path, tool, dispkin.Limits(1.5, 400.0, 1e5), a, q, method="scaling", samples_between=50, redundancy_rule=rule
    )
    assert scaled.iterations > 1 and scaled.report.within_limits
    assert np.abs(scaled.report.samples["qd"][:, 6]).max() > 0.0
    # The loop's guarantee holds at the instants it checks; FollowedTrajectory, sampled there through
    # its own grid, agrees with the check's q̇.
    limits = a.joint_limits
    followed = dispkin.FollowedTrajectory.from_start(scaled.trajectory, a, q, redundancy_rule=rule)
    at = scaled.report.samples["time"]
    assert np.abs(followed.joint_velocities(at) - scaled.report.samples["qd"]).max() <= 1e-6
    assert np.all(np.abs(scaled.report.samples["qd"]) <= limits.velocity)
    # Densely: the check at 200 instants between characteristic points sees the joints and rates
    # FollowedTrajectory gives there from its own grid (doc/inverse-kinematics.md eq. 50). (Between
    # the loop's instants the speeds may pass the limits: 1.2 % here at 50 instants, 0.25 % at 400.)
    dense = dispkin.check_joint_limits(scaled.trajectory, a, q, samples_between=200, redundancy_rule=rule)
    assert np.abs(followed.joint_velocities(dense.samples["time"]) - dense.samples["qd"]).max() <= 1e-6
    assert np.abs(followed.joint_positions(dense.samples["time"]) - dense.samples["q"]).max() <= 1e-9
    # q̈ as reported is the derivative of q̇ along the re-timed motion (at instants off the middle,
    # where this law's s̈ steps and so does q̈).
    t = np.linspace(0.0, scaled.trajectory.duration, 302)[1:-1]
    h = 1e-8  # s⃛ steps at the time law's phases: q̈ has kinks there, the difference's error ∝ h
    rate = (followed.joint_velocities(t + h) - followed.joint_velocities(t - h)) / (2 * h)
    accelerations = followed.joint_accelerations(t)
    assert np.abs(rate - accelerations).max() <= 1e-3 * np.abs(accelerations).max()


def test_optimal_retiming_solves_the_joints_the_check_sees_with_the_parameter_moving(lin):
    """retime(method="optimal") with a moving rule: its grid solves the joints at θ(s) of the
    planned path with θ′ and θ″ in q′ and q″ (doc/inverse-kinematics.md eq. 51), so the result's
    report is check_joint_limits with the same rule and keeps the joint velocity and acceleration
    limits also at 100 instants between characteristic points; a limit binds (not needlessly
    slow), the joints start at q_start exactly, the parameter moves, and the result is not slower
    than the scaling loop under the same rule."""
    a, q, path, tool, _ = lin
    rule = dispkin.RedundancyRule()
    limits = dispkin.Limits(1.5, 400.0)
    acceleration = np.full(7, 20.0)
    optimal = dispkin.retime(
        path,
        tool,
        limits,
        a,
        q,
        profile="trapezoid",
        method="optimal",
        joint_acceleration=acceleration,
        samples_between=3,
        redundancy_rule=rule,
    )
    same = dispkin.check_joint_limits(optimal.trajectory, a, q, samples_between=3, redundancy_rule=rule)
    for key in ("time", "q", "qd", "qdd"):
        np.testing.assert_array_equal(optimal.report.samples[key], same.samples[key])
    dense = dispkin.check_joint_limits(optimal.trajectory, a, q, samples_between=100, redundancy_rule=rule)
    samples = dense.samples
    velocity = np.abs(samples["qd"]) / a.joint_limits.velocity
    accelerating = np.abs(samples["qdd"]) / acceleration
    torque = np.abs(samples["static_torque"] + samples["dynamic_torque"]) / a.joint_limits.effort
    assert dense.position_excess == 0.0 and velocity.max() <= 1.0 and accelerating.max() <= 1.0
    assert torque.max() <= 1.0
    assert max(velocity.max(), accelerating.max()) > 0.97
    assert np.abs(samples["q"][:, 6] - q[6]).max() > 0.01 and np.abs(samples["qd"][:, 6]).max() > 0.0
    followed = dispkin.FollowedTrajectory.from_start(optimal.trajectory, a, q, redundancy_rule=rule)
    assert np.array_equal(followed.start, q)
    assert np.abs(followed.joint_positions(samples["time"]) - samples["q"]).max() <= 1e-9
    # Against the scaling loop (joint velocities and efforts only; its FACC keeps the dynamic torque
    # within what the static one leaves, stricter than the optimal method's whole torque): not slower.
    fastest = dispkin.retime(path, tool, limits, a, q, profile="trapezoid", method="optimal", redundancy_rule=rule)
    scaled = dispkin.retime(path, tool, limits, a, q, profile="trapezoid", method="scaling", redundancy_rule=rule)
    assert max(fastest.velocity_ratio, fastest.torque_ratio) <= 1.0 and scaled.report.within_limits
    assert fastest.trajectory.duration <= scaled.trajectory.duration


def test_optimal_retiming_with_the_held_rule_is_the_default_bit_for_bit(lin):
    a, q, path, tool, _ = lin
    limits = dispkin.Limits(1.5, 400.0)
    default = dispkin.retime(path, tool, limits, a, q, profile="trapezoid", method="optimal")
    held = dispkin.retime(
        path, tool, limits, a, q, profile="trapezoid", method="optimal", redundancy_rule=dispkin.RedundancyRule.held()
    )
    assert held.trajectory.duration == default.trajectory.duration
    np.testing.assert_array_equal(held.grid_s, default.grid_s)
    np.testing.assert_array_equal(held.grid_speed, default.grid_speed)
    np.testing.assert_array_equal(held.report.samples["qd"], default.report.samples["qd"])
    assert np.all(held.report.samples["qd"][:, 6] == 0.0)


def test_bad_redundancy_rules_are_named(lin):
    a, q, path, tool, traj = lin
    for name, value in [("gain", -1.0), ("max_rate", float("nan")), ("singularity_weight", float("inf"))]:
        rule = dispkin.RedundancyRule()
        setattr(rule, name, value)
        with pytest.raises(ValueError, match=f"redundancy_rule.{name}"):
            dispkin.FollowedTrajectory.from_start(traj, a, q, redundancy_rule=rule)
        with pytest.raises(ValueError, match=f"redundancy_rule.{name}"):
            dispkin.check_joint_limits(traj, a, q, redundancy_rule=rule)
        with pytest.raises(ValueError, match=f"redundancy_rule.{name}"):
            dispkin.retime(
                path,
                tool,
                dispkin.Limits(1.5, 400.0),
                a,
                q,
                profile="trapezoid",
                method="optimal",
                redundancy_rule=rule,
            )


def test_a_panda_job_with_the_parameter_moved_checks_and_plans(tmp_path, capsys):
    """`redundancy: moved`: `dispkin check` and `dispkin plan` agree — on a LIN job both pass, the
    written joints start at q_start and move q₇ without a jump, with the scaling and with the
    optimal re-timing."""
    import csv

    from dispkin import cli
    from test_serial_arm import panda_urdf_without_fingers
    from test_serial_seven_joints import panda_job

    job = panda_job(tmp_path, panda_urdf_without_fingers(), redundancy="redundancy: moved", ptp=False)
    assert cli.main(["check", str(job)]) == 0
    assert "moved from its value in q_start" in capsys.readouterr().out
    assert cli.main(["plan", str(job), "-o", str(tmp_path / "out")]) == 0
    rows = list(csv.reader((tmp_path / "out" / "panda_lin_and_ptp.csv").open()))
    table = np.array(rows[1:], dtype=float)
    q = table[:, [rows[0].index(f"panda_joint{k}.position") for k in range(1, 8)]]
    np.testing.assert_array_equal(q[0], [0.1, -0.4, 0.2, -2.0, 0.1, 1.8, 0.7])
    assert np.abs(q[:, 6] - 0.7).max() > 1e-2 and np.abs(np.diff(q, axis=0)).max() <= 0.05
    job.write_text(job.read_text().replace("method: scaling", "method: optimal"))
    assert cli.main(["check", str(job)]) == 0
    assert cli.main(["plan", str(job), "-o", str(tmp_path / "out2")]) == 0
    table = np.array(list(csv.reader((tmp_path / "out2" / "panda_lin_and_ptp.csv").open()))[1:], dtype=float)
    q = table[:, [rows[0].index(f"panda_joint{k}.position") for k in range(1, 8)]]
    np.testing.assert_array_equal(q[0], [0.1, -0.4, 0.2, -2.0, 0.1, 1.8, 0.7])
    assert np.abs(q[:, 6] - 0.7).max() > 1e-2 and np.abs(np.diff(q, axis=0)).max() <= 0.05


def test_a_moved_parameter_job_runs_into_its_ptp_move_without_a_jump(tmp_path, capsys):
    """With `redundancy: moved` the PTP move after the LIN starts at the joints where θ(s) of the
    planned LIN ends — those FollowedTrajectory.from_start gives on the very plan the job keeps —
    so the written joints are continuous at the join; `dispkin check` and `dispkin plan` both pass."""
    import csv

    from dispkin import cli, jobs
    from test_serial_arm import panda_urdf_without_fingers
    from test_serial_seven_joints import panda, panda_job

    job_file = panda_job(tmp_path, panda_urdf_without_fingers(), redundancy="redundancy: moved")
    assert cli.main(["check", str(job_file)]) == 0
    assert cli.main(["plan", str(job_file), "-o", str(tmp_path / "out")]) == 0
    capsys.readouterr()
    job = jobs.load_job(job_file)
    planned = jobs.plan_job(job)
    (run, lin), (ptp, joint_line) = planned.parts
    assert run.kind == "path" and ptp.kind == "ptp" and lin is run.trajectory
    followed = dispkin.FollowedTrajectory.from_start(lin, job.arm, job.q_start, redundancy_rule=job.redundancy_rule)
    end = followed.joint_positions([lin.duration])[0]
    np.testing.assert_array_equal(ptp.q_start, end)
    np.testing.assert_array_equal(joint_line.joint_positions([0.0])[0], end)
    assert abs(end[6] - 0.7) > 1e-2  # q₇ moved along the LIN: the held value would jump
    rows = list(csv.reader((tmp_path / "out" / "panda_lin_and_ptp.csv").open()))
    table = np.array(rows[1:], dtype=float)
    q = table[:, [rows[0].index(f"panda_joint{k}.position") for k in range(1, 8)]]
    dt = np.diff(table[:, rows[0].index("time_s")])
    assert np.all(np.abs(np.diff(q, axis=0)) <= panda().joint_limits.velocity * dt[:, None])


def test_a_held_parameter_job_runs_into_its_ptp_move_without_a_jump(tmp_path):
    """With `redundancy: q_start` the LIN ends at q_start's q₇, and the PTP move after it starts
    from those very joints (its start is the run's end as the followers give it, not as a moving
    rule would): no step between 10 ms samples larger than the joints' speed limits allow."""
    import csv

    from dispkin import cli
    from test_serial_arm import panda_urdf_without_fingers
    from test_serial_seven_joints import panda, panda_job

    job = panda_job(tmp_path, panda_urdf_without_fingers())
    assert cli.main(["plan", str(job), "-o", str(tmp_path / "out")]) == 0
    rows = list(csv.reader((tmp_path / "out" / "panda_lin_and_ptp.csv").open()))
    table = np.array(rows[1:], dtype=float)
    q = table[:, [rows[0].index(f"panda_joint{k}.position") for k in range(1, 8)]]
    dt = np.diff(table[:, rows[0].index("time_s")])
    assert np.all(np.abs(np.diff(q, axis=0)) <= panda().joint_limits.velocity * dt[:, None])
