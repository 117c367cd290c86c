"""`dispkin plan` fails loudly when the trajectory it writes breaks a machine limit, and job files
re-time to joint limits and read MoveIt / Pilz limits files."""

import io
import json
import os
import pathlib
import re
import subprocess
import sys

import numpy as np
import pytest

import dispkin
from dispkin import cli, jobs
from dispkin.commands import EXIT_LIMITS_BROKEN
from dispkin.progress import Progress

ROOT = pathlib.Path(__file__).resolve().parents[2]
DATA = ROOT / "tests" / "data"
HEXAPOD = DATA / "jobs" / "violating_hexapod_too_high.yaml"
UR5E = DATA / "jobs" / "violating_ur5e_too_fast.yaml"


def plan(job_file, outdir, *extra):
    return cli.main(["plan", str(job_file), "-o", str(outdir), *extra])


def with_lines(job_file, directory, *lines, drop=(), name=None):
    """The job file with `lines` appended (paths made absolute) and the lines starting with one of
    `drop` removed, written into `directory` (as `name`, default the job file's name)."""
    text = job_file.read_text().replace("urdf: ../urdf/", f"urdf: {DATA / 'urdf'}/")
    kept = [line for line in text.splitlines() if not any(line.startswith(d) for d in drop)]
    out = directory / (name or job_file.name)
    out.write_text("\n".join(kept + list(lines)) + "\n")
    return out


def test_hexapod_job_too_high_fails_naming_legs_times_and_excess(tmp_path, capsys):
    assert plan(HEXAPOD, tmp_path) == EXIT_LIMITS_BROKEN
    captured = capsys.readouterr()
    job = jobs.load_job(HEXAPOD)
    summary = json.loads((tmp_path / job.outputs["json"]).read_text())["dispkin"]["summary"]
    lengths = np.array([p["positions"] for p in json.loads((tmp_path / job.outputs["json"]).read_text())["points"]])
    leg_max = np.asarray(job.hexapod.leg_max)
    # The written legs are too long; every such leg is reported, with its worst sample.
    too_long = [name for k, name in enumerate(job.joint_names) if np.max(lengths[:, k]) > leg_max[k]]
    assert too_long
    positions = {v["joint"]: v for v in summary["violations"] if v["kind"] == "position"}
    assert sorted(positions) == sorted(too_long)
    for name, v in positions.items():
        k = job.joint_names.index(name)
        assert v["value"] == pytest.approx(np.max(lengths[:, k]), rel=1e-12)
        assert v["limit"] == leg_max[k] and v["excess"] == pytest.approx(v["value"] - leg_max[k], rel=1e-12)
        assert v["sample"] == int(np.argmax(lengths[:, k]))
        assert f"position of {name}: {v['value']:.6g} m" in captured.err
    assert "breaks" in captured.err and "--allow-violations" in captured.err
    assert not summary["within_machine_limits"]
    assert summary["binding"].startswith("none: the trajectory breaks limits")
    assert "LIMIT BROKEN: position of" in captured.out


def test_ur5e_job_too_fast_fails_naming_the_wrist(tmp_path, capsys):
    assert plan(UR5E, tmp_path) == EXIT_LIMITS_BROKEN
    err = capsys.readouterr().err
    job = jobs.load_job(UR5E)
    document = json.loads((tmp_path / job.outputs["json"]).read_text())
    qd = np.array([p["velocities"] for p in document["points"]])
    limit = np.asarray(job.arm.joint_limits.velocity)
    k = job.joint_names.index("wrist_3_joint")
    assert np.max(np.abs(qd[:, k])) > 1.5 * limit[k]  # the tool turns at up to 0.25 m/s / 0.04 m against 3.14 rad/s
    broken = [v for v in document["dispkin"]["summary"]["violations"] if v["kind"] == "velocity"]
    assert [v["joint"] for v in broken] == ["wrist_3_joint"]
    v = broken[0]
    assert abs(v["value"]) == pytest.approx(np.max(np.abs(qd[:, k])), rel=1e-12) and v["limit"] == limit[k]
    assert document["points"][v["sample"]]["velocities"][k] == v["value"]
    assert (
        f"velocity of wrist_3_joint: {v['value']:.6g} rad/s at t = {v['time']:.4f} s (sample {v['sample']}), limit 3.14 rad/s"
        in err
    )
    assert document["dispkin"]["summary"]["binding"].startswith("none: the trajectory breaks limits")


def test_allow_violations_exits_zero_and_still_reports(tmp_path, capsys):
    assert plan(UR5E, tmp_path, "--allow-violations") == 0
    err = capsys.readouterr().err
    assert "velocity of wrist_3_joint" in err and "allowed by --allow-violations" in err


@pytest.mark.parametrize("method", ["scaling", "optimal"])
def test_retimed_ur5e_job_keeps_the_limits(tmp_path, capsys, method):
    job_file = with_lines(UR5E, tmp_path, f"retime: {{method: {method}}}")
    assert plan(job_file, tmp_path / "out") == 0
    captured = capsys.readouterr()
    assert "LIMIT BROKEN" not in captured.out and captured.err == ""
    job = jobs.load_job(job_file)
    assert job.retime.method == method
    document = json.loads((tmp_path / "out" / job.outputs["json"]).read_text())
    qd = np.array([p["velocities"] for p in document["points"]])
    k = job.joint_names.index("wrist_3_joint")
    limit = job.arm.joint_limits.velocity[k]
    assert np.max(np.abs(qd[:, k])) <= limit * (1 + 1e-6)
    assert np.max(np.abs(qd[:, k])) >= 0.9 * limit  # re-timed up to the limit, not below it
    assert document["dispkin"]["summary"]["within_machine_limits"]


def test_moveit_limits_file_lowers_the_arm_limits_and_optimal_retiming_keeps_them(tmp_path, capsys):
    moveit = DATA / "limits" / "ur5e_joint_limits.yaml"
    job_file = with_lines(UR5E, tmp_path, f"limits_file: {moveit}", "retime: {method: optimal}")
    job = jobs.load_job(job_file)
    assert job.limits_files == [moveit]
    assert job.joint_limits_from == "MoveIt ur5e_joint_limits.yaml"
    names = job.joint_names
    assert job.arm.joint_limits.velocity[names.index("shoulder_pan_joint")] == 2.0
    assert job.joint_acceleration[names.index("elbow_joint")] == 8.0
    assert np.isinf(job.joint_acceleration[names.index("wrist_1_joint")])
    np.testing.assert_array_equal(job.retime.joint_acceleration, job.joint_acceleration)
    assert plan(job_file, tmp_path / "out") == 0
    out = capsys.readouterr().out
    assert "(<= 1 is within the MoveIt ur5e_joint_limits.yaml limits)" in out
    document = json.loads((tmp_path / "out" / job.outputs["json"]).read_text())
    qdd = np.array([p["accelerations"] for p in document["points"]])
    bounded = np.isfinite(job.joint_acceleration)
    assert np.all(np.max(np.abs(qdd[:, bounded]), axis=0) <= job.joint_acceleration[bounded] * (1 + 1e-6))


def test_joint_accelerations_of_a_limits_file_are_checked_without_retiming(tmp_path, capsys):
    # Joint accelerations far below what the move needs: planned under the DISP limits only, the
    # written trajectory breaks them and plan says which; re-timed with them, it keeps them.
    names = jobs.load_job(UR5E).joint_names
    moveit = tmp_path / "slow_joint_limits.yaml"
    moveit.write_text(
        "joint_limits:\n"
        + "".join(f"  {n}:\n    has_acceleration_limits: true\n    max_acceleration: 0.5\n" for n in names)
    )
    job_file = with_lines(UR5E, tmp_path, f"limits_file: {moveit}")
    assert plan(job_file, tmp_path / "plain") == EXIT_LIMITS_BROKEN
    err = capsys.readouterr().err
    job = jobs.load_job(job_file)
    document = json.loads((tmp_path / "plain" / job.outputs["json"]).read_text())
    qdd = np.array([p["accelerations"] for p in document["points"]])
    too_fast = {n for n, a in zip(names, np.max(np.abs(qdd), axis=0)) if a > 0.5 * (1 + 1e-6)}
    assert "wrist_3_joint" in too_fast
    reported = {v["joint"] for v in document["dispkin"]["summary"]["violations"] if v["kind"] == "acceleration"}
    assert reported == too_fast
    assert "acceleration of wrist_3_joint" in err and "rad/s²" in err
    retimed = with_lines(job_file, tmp_path, "retime: {method: optimal}", name="retimed.yaml")
    assert plan(retimed, tmp_path / "out") == 0
    capsys.readouterr()


def test_pilz_limits_file_gives_the_path_limits_and_the_rotational_limit(tmp_path):
    pilz = DATA / "limits" / "pilz_cartesian_limits.yaml"
    job_file = with_lines(UR5E, tmp_path, f"limits_file: [{pilz}]", "limits: {jerk: 10.0}", drop=("limits:",))
    job = jobs.load_job(job_file)
    limits = dispkin.limits_files.read_pilz_cartesian_limits(pilz)
    assert job.limits == limits.limits(10.0)
    assert job.limits.angular_velocity == limits.max_rot_vel
    # The angular limit is the rotational limit itself, not a sphere added to the set.
    assert all(radius != limits.rotation_sphere_radius for _, radius, _ in job.metric_set.spheres(0))


@pytest.mark.parametrize(
    "text, where, reason",
    [
        ("retime: {method: fastest}", "retime.method", "'fastest' is not one of 'scaling', 'optimal'"),
        ("retime: {joint_acceleration: 2}", "retime", "missing required key `method`"),
        (
            "retime: {method: optimal, joint_acceleration: [1, 2]}",
            "retime.joint_acceleration",
            "expected one value or 6",
        ),
        (
            "retime: {method: optimal, joint_acceleration: -1}",
            "retime.joint_acceleration",
            "-1: expected a positive number or a list of positive numbers",
        ),
        (
            "retime: {method: scaling, joint_acceleration: 2}",
            "retime.joint_acceleration",
            "joint accelerations need method: optimal",
        ),
        ("limits_file: 3", "limits_file", "3: expected a file name or a list of file names"),
        ("limits_file: nowhere.yaml", "limits_file", "does not exist"),
    ],
)
def test_bad_retime_and_limits_file_are_pointed_errors(tmp_path, text, where, reason):
    job_file = with_lines(UR5E, tmp_path, text)
    line = len(job_file.read_text().splitlines())
    with pytest.raises(jobs.JobError) as info:
        jobs.load_job(job_file)
    message = str(info.value)
    assert re.match(rf"^{re.escape(str(job_file))}:{line}:\d+: {re.escape(where)}: ", message), message
    assert reason in message


def test_limits_file_that_is_neither_moveit_nor_pilz(tmp_path):
    other = tmp_path / "other.yaml"
    other.write_text("max_speed: 3\n")
    job_file = with_lines(UR5E, tmp_path, f"limits_file: {other}")
    with pytest.raises(jobs.JobError, match=r"limits_file: .*is neither a MoveIt joint_limits.yaml"):
        jobs.load_job(job_file)


def test_retime_needs_a_machine_and_a_hexapod_needs_the_optimal_method(tmp_path):
    with pytest.raises(jobs.JobError, match=r"retime.method: 'scaling': .*re-time a hexapod with method: optimal"):
        jobs.load_job(with_lines(HEXAPOD, tmp_path, "retime: {method: scaling}"))
    blended = ROOT / "examples" / "jobs" / "blended_tool_move.yaml"
    with pytest.raises(jobs.JobError, match=r"retime: re-timing keeps a machine's joint limits"):
        jobs.load_job(with_lines(blended, tmp_path, "retime: {method: optimal}"))


def test_plot_without_matplotlib_says_what_to_install(tmp_path, capsys, monkeypatch):
    monkeypatch.setitem(sys.modules, "matplotlib", None)  # import matplotlib now raises ImportError
    assert plan(UR5E, tmp_path, "--plot") == 1
    err = capsys.readouterr().err
    assert "--plot needs matplotlib" in err and "pip install 'dispkin[plot]'" in err
    assert not list(tmp_path.iterdir())  # it says so before any work


class _Stream(io.StringIO):
    def __init__(self, terminal):
        super().__init__()
        self.terminal = terminal

    def isatty(self):
        return self.terminal


def test_progress_only_on_a_terminal_unless_forced():
    assert not Progress.for_stderr(_Stream(False), "x").enabled
    assert Progress.for_stderr(_Stream(True), "x").enabled
    assert Progress.for_stderr(_Stream(False), "x", force=True).enabled
    assert not Progress.for_stderr(_Stream(True), "x", force=True, quiet=True).enabled


def test_progress_lines_while_sampling(tmp_path, capsys):
    pipe = _Stream(False)
    progress = Progress(pipe, "dispkin plan", interval=0.0)
    ok = dispkin.commands.run_plan(
        str(UR5E), str(tmp_path), False, io.StringIO(), allow_violations=True, progress=progress, errors=io.StringIO()
    )
    assert ok == 0
    lines = pipe.getvalue().splitlines()
    assert lines[0] == "dispkin plan: planning"
    samples = len(jobs.sample_times(jobs.plan_job(jobs.load_job(UR5E)).duration, 0.01))
    assert f"dispkin plan: sampling (point speeds) {samples}/{samples} (100 %)" in lines
    assert lines[-1] == f"dispkin plan: {samples} samples"
    assert "\r" not in pipe.getvalue()  # whole lines on a pipe
    terminal = _Stream(True)
    progress = Progress(terminal, "p", interval=0.0)
    progress.stage("a long stage")
    progress.step("b", 1, 2)
    progress.finish()
    # One line rewritten in place, a shorter text padded over the longer one before it.
    assert terminal.getvalue() == "\rp: a long stage\rp: b 1/2 (50 %)\rp: done" + " " * 8 + "\n"


def test_plan_is_silent_on_stderr_in_a_pipe_by_default(tmp_path):
    import subprocess

    result = subprocess.run(
        [sys.executable, "-m", "dispkin", "plan", str(UR5E), "-o", str(tmp_path), "--allow-violations"],
        capture_output=True,
        text=True,
        timeout=600,
    )
    assert result.returncode == 0
    assert "sampling" not in result.stderr and "planning" not in result.stderr
    result = subprocess.run(
        [sys.executable, "-m", "dispkin", "plan", str(UR5E), "-o", str(tmp_path)],
        capture_output=True,
        text=True,
        timeout=600,
    )
    assert result.returncode == EXIT_LIMITS_BROKEN and "velocity of wrist_3_joint" in result.stderr


# --- every machine limit, between the written samples too ---------------------------------

LIN = ROOT / "examples" / "jobs" / "ur5e_lin_move.yaml"
PTP = ROOT / "examples" / "jobs" / "ur5e_ptp_and_lin.yaml"


def example_job(example, directory, *lines, name="job.yaml"):
    """The example job with its URDF path made absolute and `lines` appended (replacing its
    top-level keys of the same name)."""
    text = example.read_text().replace("urdf: ../../tests/data/urdf/", f"urdf: {DATA / 'urdf'}/")
    replaced = {line.split(":")[0] for line in lines}
    kept = [line for line in text.splitlines() if line.split(":")[0] not in replaced]
    out = directory / name
    out.write_text("\n".join(kept + list(lines)) + "\n")
    return out


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


# --- output files: checked before any work, never an input ---------------------------------


@pytest.fixture
def no_planning(monkeypatch):
    """Fails the test if the job is planned: output errors come before any work."""

    def refuse(job):
        raise AssertionError("planned although an output is wrong")

    monkeypatch.setattr(jobs, "plan_job", refuse)


def output_error(capsys, job_file, outdir, *extra):
    assert plan(job_file, outdir, *extra) == 1
    err = capsys.readouterr().err
    assert "Traceback" not in err
    return err


@pytest.mark.parametrize(
    "key, value, reason",
    [
        ("csv", "..", "'..': a file name, not a path"),
        ("json", ".", "'.': a file name, not a path"),
        ("summary", "sub/x.txt", "'sub/x.txt': a file name, not a path"),
        ("csv", "x" * 300 + ".csv", "longer than 255 bytes, the longest file name"),
    ],
)
def test_bad_output_names_are_refused_at_their_key(tmp_path, capsys, no_planning, key, value, reason):
    job_file = example_job(LIN, tmp_path, f"output: {{sample_period: 0.01, {key}: {json.dumps(value)}}}")
    err = output_error(capsys, job_file, tmp_path / "out")
    assert re.match(rf"dispkin plan: {re.escape(str(job_file))}:\d+:\d+: output\.{key}: ", err), err
    assert reason in err and not (tmp_path / "out").exists()


def test_a_long_job_name_is_refused_at_name(tmp_path, capsys, no_planning):
    job_file = example_job(LIN, tmp_path, "name: " + "n" * 300)
    err = output_error(capsys, job_file, tmp_path / "out")
    assert re.match(rf"dispkin plan: {re.escape(str(job_file))}:\d+:1: name: 'nnn", err), err
    assert "longer than 255 bytes, the longest file name: give a shorter name, or output.csv" in err
    # With its own output names the long name is fine.
    named = example_job(
        LIN, tmp_path, "name: " + "n" * 300, "output: {csv: a.csv, json: a.json, summary: a.txt}", name="named.yaml"
    )
    assert jobs.load_job(named).outputs == {"csv": "a.csv", "json": "a.json", "summary": "a.txt"}


def test_two_outputs_of_one_name_are_refused(tmp_path, capsys, no_planning):
    job_file = example_job(LIN, tmp_path, "output: {csv: same.txt, summary: same.txt}")
    err = output_error(capsys, job_file, tmp_path / "out")
    assert "output.summary: 'same.txt': the same file as output.csv" in err
    plotted = example_job(LIN, tmp_path, "output: {csv: a.csv, summary: a.png}", name="plotted.yaml")
    pytest.importorskip("matplotlib")
    err = output_error(capsys, plotted, tmp_path / "out", "--plot")
    assert f"--plot: {str(tmp_path / 'out' / 'a.png')!r} is also output.summary" in err


def test_outdir_that_is_a_file_is_refused(tmp_path, capsys, no_planning):
    taken = tmp_path / "taken"
    taken.write_text("keep me\n")
    err = output_error(capsys, LIN, taken)
    assert f"dispkin plan: -o OUTDIR = {str(taken)!r}: is not a directory" in err
    err = output_error(capsys, LIN, taken / "sub")
    assert f"-o OUTDIR = {str(taken / 'sub')!r}: cannot be made: {str(taken)!r} is not a directory" in err
    assert taken.read_text() == "keep me\n"


@pytest.mark.parametrize("how", ["same name", "symlink", "hard link"])
def test_the_job_file_is_never_an_output(tmp_path, capsys, no_planning, how):
    job_file = example_job(LIN, tmp_path, "output: {csv: alias.yaml}")
    outdir = tmp_path if how == "same name" else tmp_path / "out"
    if how == "same name":
        job_file = example_job(LIN, tmp_path, "output: {csv: job.yaml}")
    else:
        outdir.mkdir()
        (outdir / "alias.yaml").symlink_to(job_file) if how == "symlink" else os.link(job_file, outdir / "alias.yaml")
    before = job_file.read_text()
    err = output_error(capsys, job_file, outdir)
    assert re.search(
        r":\d+:\d+: output\.csv: '(job|alias)\.yaml': .* is the job file \(.*job\.yaml\): an input is never overwritten",
        err,
    ), err
    assert job_file.read_text() == before


@pytest.mark.parametrize("which", ["limits file", "URDF"])
def test_a_file_the_job_reads_is_never_an_output(tmp_path, capsys, no_planning, which):
    moveit = tmp_path / "limits.yaml"
    moveit.write_text((DATA / "limits" / "ur5e_joint_limits.yaml").read_text())
    if which == "URDF":
        urdf = tmp_path / "arm.urdf"
        urdf.write_text((DATA / "urdf" / "arm_ur5e_dh.urdf").read_text())
        job_file = example_job(LIN, tmp_path, "output: {summary: arm.urdf}")
        job_file.write_text(job_file.read_text().replace(f"urdf: {DATA / 'urdf'}/arm_ur5e_dh.urdf", "urdf: arm.urdf"))
        guarded = urdf
    else:
        job_file = example_job(LIN, tmp_path, "limits_file: limits.yaml", "output: {summary: limits.yaml}")
        guarded = moveit
    before = guarded.read_text()
    err = output_error(capsys, job_file, tmp_path)
    assert f"output.summary: {guarded.name!r}: " in err and "is a file the job reads" in err
    assert guarded.read_text() == before


def test_an_output_that_is_a_fifo_or_a_directory_is_refused_without_hanging(tmp_path, no_planning):
    out = tmp_path / "out"
    out.mkdir()
    os.mkfifo(out / "job.csv")
    (out / "job.json").mkdir()
    job_file = example_job(LIN, tmp_path, "output: {csv: job.csv}")
    done = subprocess.run(
        [sys.executable, "-m", "dispkin", "plan", str(job_file), "-o", str(out)],
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert done.returncode == 1 and "Traceback" not in done.stderr
    assert (
        "output.csv: 'job.csv': " in done.stderr
        and "is not a regular file (a FIFO, a device or a socket)" in done.stderr
    )
    json_file = example_job(LIN, tmp_path, "output: {json: job.json}", name="other.yaml")
    done = subprocess.run(
        [sys.executable, "-m", "dispkin", "plan", str(json_file), "-o", str(out)],
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert done.returncode == 1 and "output.json: 'job.json': " in done.stderr and "is a directory" in done.stderr


# --- values as written, at their keys ----------------------------------------------------------

BLENDED = """name: blended
metric_set:
  points:
    - {shape: icosahedron, radius: 0.02, center: [0, 0, 0]}
start: {xyzuvw: [0, 0, 0, 0, 0, 0]}
moves:
  - lin: {to: {xyzuvw: [0.3, 0, 0, 0, 0, 10]}}
  - lin: {to: {xyzuvw: [0.3, 0.2, 0, 0, 0, 40]}}
    BLEND
    orientation_blend: ORIENTATION
limits: {velocity: 0.25, acceleration: 1.0, jerk: 10.0}
"""


@pytest.mark.parametrize("orientation", ["nested_slerp", "rotation_vector"])
@pytest.mark.parametrize(
    "blend, reason",
    [
        (
            "blend_weight: 1e-300",
            "moves[1].blend_weight: 1e-300: must be at least 1e-05: a smaller share puts the blend's ends",
        ),
        ("blend_weight: 9e-6", "moves[1].blend_weight: 9e-06: must be at least 1e-05"),
        ("blend: 1e-300", "moves[1].blend: 1e-300: must be at least 1e-09 m, the smallest blend dispkin builds"),
    ],
)
def test_blends_too_small_to_build_are_refused_at_their_key(tmp_path, capsys, blend, reason, orientation):
    job_file = tmp_path / "blended.yaml"
    job_file.write_text(BLENDED.replace("BLEND", blend).replace("ORIENTATION", orientation))
    assert plan(job_file, tmp_path / "out") == 1
    assert capsys.readouterr().err.startswith(f"dispkin plan: {job_file}:9:5: {reason}")
    with pytest.raises(jobs.JobError) as info:
        jobs.load_job(job_file)
    assert str(info.value).startswith(f"{job_file}:9:5: {reason}")


@pytest.mark.parametrize("orientation", ["nested_slerp", "rotation_vector"])
def test_the_smallest_blend_weight_plans(tmp_path, capsys, orientation):
    job_file = tmp_path / "blended.yaml"
    job_file.write_text(BLENDED.replace("BLEND", "blend_weight: 1e-5").replace("ORIENTATION", orientation))
    assert plan(job_file, tmp_path / "out") == 0
    capsys.readouterr()


def test_a_planning_failure_names_the_blend_that_has_no_length(tmp_path):
    # A blend below the sizes the builder refuses cannot be written in a job any more; the
    # mapping from a section without length to its key is checked on the parts directly.
    job = jobs.load_job(ROOT / "examples" / "jobs" / "blended_tool_move.yaml")
    from dispkin.job import planning

    assert planning._failed_at(job, job.parts[0]) == (("moves", 0), None)  # every section has a length
    with pytest.raises(jobs.JobError) as info:
        planning._planned(
            job, job.parts[0], lambda: (_ for _ in ()).throw(ValueError("segments[0].length = 0: must be finite"))
        )
    assert re.match(
        rf"{re.escape(str(job.file))}:\d+:\d+: moves\[0\]: planning failed: segments\[0\]\.length = 0", str(info.value)
    )


@pytest.mark.parametrize(
    "limit, unit",
    [
        ("angular_velocity: 1e300", "deg/s"),
        ("angular_velocity: 1e-300", "deg/s"),
        ("angular_acceleration: 1e300", "deg/s²"),
    ],
)
def test_angular_limits_are_refused_in_degrees_at_their_key(tmp_path, limit, unit):
    key, value = limit.split(": ")
    job_file = example_job(LIN, tmp_path, f"limits: {{velocity: 0.25, acceleration: 1.0, jerk: 10.0, {limit}}}")
    with pytest.raises(jobs.JobError) as info:
        jobs.load_job(job_file)
    assert re.match(
        rf"{re.escape(str(job_file))}:\d+:\d+: limits\.{key}: {re.escape(repr(float(value)))}: "
        rf"must be in \[5\.72958e-11, 5\.72958e\+13\] {unit}$",
        str(info.value),
    ), str(info.value)


@pytest.mark.parametrize(
    "key, value, reason",
    [
        ("base_gap", "200", "200: must be in [0, 120) deg"),
        ("platform_gap", "-5", "-5: must be in [0, 120) deg"),
        ("leg_speed", "1e300", "1e+300: must be in [1e-12, 1e12]"),
    ],
)
def test_a_symmetric_hexapod_is_refused_at_the_key_as_written(tmp_path, key, value, reason):
    symmetric = {
        "base_radius": "0.15",
        "base_gap": "20",
        "platform_radius": "0.1",
        "platform_gap": "20",
        "height": "0.2",
        "leg_min": "0.15",
        "leg_max": "0.32",
        "leg_speed": "0.01",
        key: value,
    }
    job_file = tmp_path / "hexapod.yaml"
    job_file.write_text(
        "machine:\n  hexapod:\n    symmetric: {" + ", ".join(f"{k}: {v}" for k, v in symmetric.items()) + "}\n"
        "metric_set:\n  points:\n    - relative: [[0, 0, 0.3]]\n"
        "moves:\n  - lin: {to: {xyzuvw: [0.01, 0, 0.2, 0, 0, 0]}}\n"
        "limits: {velocity: 0.1, acceleration: 0.5, jerk: 5.0}\n"
    )
    with pytest.raises(jobs.JobError) as info:
        jobs.load_job(job_file)
    assert re.match(
        rf"{re.escape(str(job_file))}:3:\d+: machine\.hexapod\.symmetric\.{key}: {re.escape(reason)}", str(info.value)
    ), str(info.value)
