"""`dispkin plan` fails loudly when the trajectory it writes breaks a machine limit, and job files
re-time to joint limits and read MoveIt / Pilz limits files."""

import io
import json
import re
import subprocess
import sys

import numpy as np
import pytest

import dispkin
from dispkin import jobs
from dispkin.commands import EXIT_LIMITS_BROKEN
from dispkin.progress import Progress

from _cli_jobs import DATA, HEXAPOD, ROOT, UR5E, plan, with_lines


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
