"""`dispkin plan` checks every machine limit between the written samples too: a limit broken
only between them fails the plan, and the exit status agrees with the summary."""

import json
import re

import numpy as np
import pytest

import dispkin
from dispkin import jobs
from dispkin.commands import EXIT_LIMITS_BROKEN

from _cli_jobs import LIN, PTP, example_job, plan


# --- every machine limit, between the written samples too ---------------------------------


def moveit_file(directory, joint, flag, key, value):
    file = directory / f"{joint}_{key}.yaml"
    file.write_text(f"joint_limits:\n  {joint}:\n    {flag}: true\n    {key}: {float(value)!r}\n")
    return file


def dense_states(job, trajectory):
    """|q-dot-dot| and |tau| per joint at the dense check points (check_joint_limits, or part by
    part with 1 ms samples of a PTP move), computed here independently of the summary."""
    arm = job.arm.with_joint_limits(effort=np.full(job.arm.dof, np.inf))
    parts = trajectory.parts if isinstance(trajectory, jobs.JobTrajectory) else [(job.parts[0], trajectory)]
    qdd, tau = [], []
    for part, traj in parts:
        if part.kind == "path":
            samples = dispkin.check_joint_limits(traj, arm, part.q_start).samples
        else:
            samples = arm.check_joint_limits(
                traj, np.linspace(0.0, traj.duration, int(np.ceil(traj.duration / 1e-3)) + 1)
            ).samples
        qdd.append(np.abs(samples["qdd"]))
        tau.append(np.abs(samples["static_torque"] + samples["dynamic_torque"]))
    return np.max(np.vstack(qdd), axis=0), np.max(np.vstack(tau), axis=0)


def limit_between_samples(example, tmp_path, period):
    """(joint, kind index, a limit above every written sample's value but below the dense
    check's peak) for accelerations (0) and efforts (1) of the example sampled every `period`."""
    job = jobs.load_job(example_job(example, tmp_path, f"output: {{sample_period: {period}}}", name="probe.yaml"))
    trajectory = jobs.plan_job(job)
    samples = jobs.sample_job(job, trajectory)
    sampled = (np.max(np.abs(samples.accelerations), axis=0), np.max(np.abs(samples.effort), axis=0))
    dense = dense_states(job, trajectory)
    found = {}
    for kind in (0, 1):
        gap = dense[kind] / np.maximum(sampled[kind], 1e-300)
        k = int(np.argmax(gap))
        assert gap[k] > 1.02, "the samples must miss the peak for this test to mean anything"
        found[kind] = (job.joint_names[k], float(np.sqrt(sampled[kind][k] * dense[kind][k])), float(sampled[kind][k]))
    return found


def summary_of(directory, job_file):
    job = jobs.load_job(job_file)
    return json.loads((directory / job.outputs["json"]).read_text())["dispkin"]["summary"]


@pytest.mark.parametrize("example, period", [(LIN, 0.2), (PTP, 0.25)], ids=["lin", "ptp"])
@pytest.mark.parametrize("kind", ["acceleration", "effort"])
def test_a_limit_broken_only_between_samples_fails_the_plan(tmp_path, capsys, example, period, kind):
    joint, limit, sampled = limit_between_samples(example, tmp_path, period)[0 if kind == "acceleration" else 1]
    assert sampled < limit
    flag, key = (
        ("has_acceleration_limits", "max_acceleration")
        if kind == "acceleration"
        else ("has_effort_limits", "max_effort")
    )
    job_file = example_job(
        example,
        tmp_path,
        f"output: {{sample_period: {period}}}",
        f"limits_file: {moveit_file(tmp_path, joint, flag, key, limit)}",
    )
    assert plan(job_file, tmp_path / "out") == EXIT_LIMITS_BROKEN
    captured = capsys.readouterr()
    summary = summary_of(tmp_path / "out", job_file)
    broken = [v for v in summary["violations"] if v["kind"] == kind and v["joint"] == joint]
    assert len(broken) == 1 and broken[0]["sample"] is None and abs(broken[0]["value"]) > limit
    assert f"{kind} of {joint}: " in captured.err and "(between samples)" in captured.err
    # One verdict: the summary's lines say what the exit status says.
    assert not summary["within_machine_limits"] and not summary["joints"]["within_limits"]
    assert "within limits: False" in captured.out


def test_plan_exits_zero_only_when_the_summary_says_within_limits(tmp_path, capsys):
    # The same job with the limit just above the dense peak: now it holds everywhere.
    joint, _, _ = limit_between_samples(LIN, tmp_path, 0.2)[1]
    job = jobs.load_job(example_job(LIN, tmp_path, "output: {sample_period: 0.2}", name="probe2.yaml"))
    peak = dense_states(job, jobs.plan_job(job))[1][job.joint_names.index(joint)]
    job_file = example_job(
        LIN,
        tmp_path,
        "output: {sample_period: 0.2}",
        f"limits_file: {moveit_file(tmp_path, joint, 'has_effort_limits', 'max_effort', peak * 1.01)}",
    )
    assert plan(job_file, tmp_path / "out") == 0
    captured = capsys.readouterr()
    assert "within limits: True" in captured.out and "LIMIT BROKEN" not in captured.out and captured.err == ""
    assert summary_of(tmp_path / "out", job_file)["within_machine_limits"]


def test_a_static_torque_beyond_its_effort_limit_is_a_broken_limit_not_a_traceback(tmp_path, capsys):
    job = jobs.load_job(LIN)
    samples = jobs.sample_job(job, jobs.plan_job(job))
    holding = np.max(np.abs([job.arm.static_torques(q) for q in samples.positions]), axis=0)
    k = int(np.argmax(holding))
    limit = 0.9 * holding[k]  # the arm cannot even hold itself there, at any speed
    joint = job.joint_names[k]
    job_file = example_job(
        LIN, tmp_path, f"limits_file: {moveit_file(tmp_path, joint, 'has_effort_limits', 'max_effort', limit)}"
    )
    assert plan(job_file, tmp_path / "out") == EXIT_LIMITS_BROKEN
    captured = capsys.readouterr()
    assert f"effort of {joint}: " in captured.err
    assert "effort factor undefined (a static torque alone reaches its effort limit)" in captured.out
    summary = summary_of(tmp_path / "out", job_file)
    assert summary["joints"]["acceleration_factor"] is None and not summary["within_machine_limits"]
    # Re-timing cannot help: a clear error at the key, not a traceback.
    retimed = example_job(
        LIN,
        tmp_path,
        f"limits_file: {tmp_path / f'{joint}_max_effort.yaml'}",
        "retime: {method: scaling}",
        name="retimed.yaml",
    )
    assert plan(retimed, tmp_path / "out2") == 1
    err = capsys.readouterr().err
    assert re.search(rf"retimed\.yaml:\d+:1: retime: planning failed: joint {joint}: the static torque", err), err


def test_hexapod_leg_speed_broken_only_between_samples(tmp_path, capsys):
    # A symmetric hexapod whose leg speed limit lies between the fastest written sample and
    # the fastest leg of the 1 ms check (the planner does not know it: no leg group, no joint metric).
    def job_with(speed, name):
        file = tmp_path / name
        file.write_text(f"""machine:
  hexapod:
    symmetric: {{base_radius: 0.15, base_gap: 20, platform_radius: 0.1, platform_gap: 20, height: 0.2,
                leg_min: 0.15, leg_max: 0.32, leg_speed: {speed!r}}}
metric_set:
  points:
    - relative: [[0, 0, 0.3], [0.1, 0, 0.3], [0, 0.1, 0.3]]
moves:
  - lin: {{to: {{xyzuvw: [0.02, 0.01, 0.2, 0, 0, 5]}}}}
limits: {{velocity: 0.05, acceleration: 0.5, jerk: 5.0}}
output: {{sample_period: 0.3}}
""")
        return file

    probe = jobs.load_job(job_with(1.0, "probe.yaml"))
    trajectory = jobs.plan_job(probe)
    sampled = np.max(np.abs(jobs.sample_job(probe, trajectory).velocities), axis=0)
    dense = probe.hexapod.check_trajectory(trajectory, 1e-3).max_speed
    # One leg speed for all six legs: the fastest written sample against the fastest leg.
    assert np.max(dense) > 1.02 * np.max(sampled), "the samples must miss the peak for this test to mean anything"
    limit = float(np.sqrt(np.max(dense) * np.max(sampled)))
    job_file = job_with(limit, "job.yaml")
    assert plan(job_file, tmp_path / "out") == EXIT_LIMITS_BROKEN
    captured = capsys.readouterr()
    summary = summary_of(tmp_path / "out", job_file)
    speeds = [v for v in summary["violations"] if v["kind"] == "velocity"]
    assert speeds and all(v["sample"] is None for v in speeds)
    assert not summary["legs"]["within_limits"] and "within limits: False" in captured.out
    assert "(between samples)" in captured.err
