"""Hostile job and limits files (doc/input-budget.md): malformed jobs refused at FILE:LINE:COLUMN,
alias bombs, deep nesting, huge numbers, many moves, files that are no regular files. Each case
gives dispkin's own error within a small memory (children with a capped address space:
_hostile.py) or plans.
"""

import os
import pathlib
import re
import subprocess
import sys

import pytest

from dispkin import jobs

from _hostile import DATA, cli_in_child, run_isolated


# --- 8. job files: nesting, aliases, huge numbers, tiny sample periods, many moves ----------

BAD_JOBS = sorted((DATA / "jobs").glob("bad_*.yaml"))
# FILE:LINE:COLUMN: key: reason, or FILE:LINE:COLUMN: not valid YAML: reason where the text is
# no YAML (no key yet).
WHERE = r"^dispkin (check|plan): \S+\.yaml:\d+:\d+: (\S+|not valid YAML): "


@pytest.mark.parametrize("job", BAD_JOBS, ids=[p.name for p in BAD_JOBS])
def test_cli_refuses_every_malformed_job_with_file_line_column(job, tmp_path):
    # In a child process, as a user runs it: the exit status, and stderr without a traceback.
    for command in (["check", str(job)], ["plan", str(job), "-o", str(tmp_path)]):
        done = subprocess.run([sys.executable, "-m", "dispkin", *command], capture_output=True, text=True, timeout=300)
        assert done.returncode == 1, (command, done.returncode, done.stderr[-3000:])
        assert "Traceback" not in done.stderr, done.stderr[-3000:]
        assert re.match(WHERE, done.stderr), done.stderr[:500]
        assert len(done.stderr) < 20_000  # a message, not an echo of the file


def test_the_alias_bomb_is_refused_within_a_small_memory():
    bomb = DATA / "jobs" / "bad_alias_bomb.yaml"
    status, out, err = run_isolated(
        f"from dispkin import cli; sys.exit(cli.main(['check', {str(bomb)!r}]))", address_space=1 << 30
    )
    assert status == 1 and "Traceback" not in err, err[-2000:]
    assert "the job expands to more than 500000 values" in err


def test_yaml_nesting_up_to_the_limit_is_read(tmp_path):
    # 32 levels pass the reader (the schema then refuses the odd shape with its own message).
    job = tmp_path / "nested.yaml"
    job.write_text("name: " + "[" * 31 + "x" + "]" * 31 + "\n")
    with pytest.raises(jobs.JobError) as info:
        jobs.load_job(job)
    assert (
        "nest deeper" not in str(info.value)
        and "name: [[[" in str(info.value)
        and "is not of type 'string'" in str(info.value)
    )


def test_integers_up_to_2_to_the_53_are_numbers(tmp_path):
    job = tmp_path / "big.yaml"
    job.write_text((DATA.parent.parent / "examples" / "jobs" / "blended_tool_move.yaml").read_text())
    text = job.read_text()
    assert "velocity:" in text
    job.write_text(re.sub(r"velocity: [0-9.e-]+", f"velocity: {2**53}", text, count=1))
    with pytest.raises(jobs.JobError) as info:
        jobs.load_job(job)
    assert "bits" not in str(info.value)  # a value the schema or the library then judges


def many_blended_moves(count):
    lines = [
        "metric_set:",
        "  points:",
        "    - {shape: sphere, radius: 0.1}",
        "start: {xyzuvw: [0, 0, 0, 0, 0, 0]}",
        "moves:",
    ]
    for k in range(1, count + 1):
        x, y = 0.05 * ((k + 1) // 2), 0.05 * (k // 2)
        blend = ", blend: 0.01" if k > 1 else ""
        lines.append(f"  - {{lin: {{to: {{xyzuvw: [{x:.2f}, {y:.2f}, 0, 0, 0, 0]}}}}{blend}}}")
    lines.append("limits: {velocity: 0.1, acceleration: 1.0, jerk: 10}")
    lines.append("output: {sample_period: 0.5}")
    return "\n".join(lines) + "\n"


def test_ten_thousand_blended_moves_plan(tmp_path):
    job = tmp_path / "many.yaml"
    job.write_text(many_blended_moves(10_000))
    done = subprocess.run(
        [sys.executable, "-m", "dispkin", "plan", str(job), "-o", str(tmp_path)],
        capture_output=True,
        text=True,
        timeout=600,
    )
    assert done.returncode == 0 and "Traceback" not in done.stderr, done.stderr[-3000:]
    assert (tmp_path / "many.csv").exists()
    first = done.stdout.splitlines()[0]
    assert (
        first.startswith("job many: 10000 move(s) (lin, lin (blend 0.01 m),") and "… 9980 more), machine: none" in first
    )


# --- 10. limits files (MoveIt, Pilz) under the job files' limits; the plan's own failures -----

LIN_JOB = DATA.parent.parent / "examples" / "jobs" / "ur5e_lin_move.yaml"


def lin_job_with(tmp_path, *lines):
    """The UR5e LIN example in tmp_path with `lines` appended (its URDF path made absolute)."""
    job = tmp_path / "job.yaml"
    text = LIN_JOB.read_text().replace("urdf: ../../tests/data/urdf/", f"urdf: {DATA / 'urdf'}/")
    job.write_text(text + "\n".join(lines) + "\n")
    return job


LIMITS_BOMB = """# 9^9 = 3.9e8 values from nine lines
a: &a [x, x, x, x, x, x, x, x, x]
b: &b [*a, *a, *a, *a, *a, *a, *a, *a, *a]
c: &c [*b, *b, *b, *b, *b, *b, *b, *b, *b]
d: &d [*c, *c, *c, *c, *c, *c, *c, *c, *c]
e: &e [*d, *d, *d, *d, *d, *d, *d, *d, *d]
f: &f [*e, *e, *e, *e, *e, *e, *e, *e, *e]
g: &g [*f, *f, *f, *f, *f, *f, *f, *f, *f]
h: &h [*g, *g, *g, *g, *g, *g, *g, *g, *g]
joint_limits: {elbow_joint: *h}
"""


def test_a_limits_file_alias_bomb_is_refused_within_a_small_memory(tmp_path):
    bomb = tmp_path / "bomb.yaml"
    bomb.write_text(LIMITS_BOMB)
    status, err = cli_in_child(["check", str(lin_job_with(tmp_path, f"limits_file: {bomb}"))], address_space=1 << 30)
    assert status == 1 and len(err) < 2000, err[-2000:]
    assert re.search(rf"limits_file: {re.escape(str(bomb))}:\d+:\d+: \(limits file\): ", err), err
    assert "(limits file): the limits file expands to more than 500000 values" in err


def test_a_deep_limits_file_is_refused_by_its_nesting(tmp_path):
    deep = tmp_path / "deep.yaml"
    deep.write_text("joint_limits: " + "{a: " * 50_000 + "1" + "}" * 50_000 + "\n")
    status, err = cli_in_child(["check", str(lin_job_with(tmp_path, f"limits_file: {deep}"))])
    assert status == 1 and "mappings and lists nest deeper than 32 levels" in err and f"{deep}:1:" in err


def test_a_huge_limits_file_is_refused_unread_within_a_small_memory(tmp_path):
    huge = tmp_path / "huge.yaml"
    with open(huge, "wb") as f:
        f.truncate(2 * 2**30)
    status, err = cli_in_child(["check", str(lin_job_with(tmp_path, f"limits_file: {huge}"))], address_space=1 << 30)
    assert status == 1 and "the limits file is larger than 33554432 bytes" in err


@pytest.mark.parametrize("kind", ["fifo", "directory", "device"])
def test_a_limits_file_that_is_no_regular_file_is_named_for_what_it_is(tmp_path, kind):
    target = {"fifo": tmp_path / "fifo.yaml", "directory": tmp_path / "dir.yaml", "device": pathlib.Path("/dev/zero")}[
        kind
    ]
    if kind == "fifo":
        os.mkfifo(target)
    elif kind == "directory":
        target.mkdir()
    status, err = cli_in_child(["check", str(lin_job_with(tmp_path, f"limits_file: {target}"))], timeout=60)
    assert status == 1
    assert ("is a directory" if kind == "directory" else "is not a regular file (a FIFO, a device or a socket)") in err
    assert "does not exist" not in err


@pytest.mark.parametrize("kind", ["fifo", "directory"])
def test_a_job_file_that_is_no_regular_file_is_named_for_what_it_is(tmp_path, kind):
    target = tmp_path / "job.yaml"
    os.mkfifo(target) if kind == "fifo" else target.mkdir()
    for command in ("check", "plan"):
        status, err = cli_in_child(
            [command, str(target)] + (["-o", str(tmp_path / "out")] if command == "plan" else []), timeout=60
        )
        assert status == 1
        assert (": is a directory, not a job file" if kind == "directory" else ": is not a regular file") in err


def test_huge_integers_and_latin1_in_a_limits_file_are_dispkins_own_errors(tmp_path):
    big = tmp_path / "big.yaml"
    big.write_text(
        "joint_limits:\n  elbow_joint:\n    has_velocity_limits: true\n    max_velocity: " + "9" * 4000 + "\n"
    )
    status, err = cli_in_child(["check", str(lin_job_with(tmp_path, f"limits_file: {big}"))])
    assert status == 1 and f"{big}:4:5: joint_limits.elbow_joint.max_velocity = an integer of 13288 bits" in err
    latin = tmp_path / "latin.yaml"
    latin.write_bytes(b"cartesian_limits:\n  max_trans_vel: 1 # \xb5m\n")
    status, err = cli_in_child(["check", str(lin_job_with(tmp_path, f"limits_file: {latin}"))])
    assert status == 1 and f"{latin}:2:22: the limits file is not UTF-8 text: byte 0xb5" in err


def test_an_effort_limit_the_static_torque_breaks_is_reported_not_raised(tmp_path):
    moveit = tmp_path / "weak.yaml"
    moveit.write_text("joint_limits:\n  shoulder_lift_joint:\n    has_effort_limits: true\n    max_effort: 5.0\n")
    status, err = cli_in_child(
        ["plan", str(lin_job_with(tmp_path, f"limits_file: {moveit}")), "-o", str(tmp_path / "out")]
    )
    assert status == 3 and "effort of shoulder_lift_joint: " in err


def test_a_job_value_its_tag_cannot_make_is_refused_at_its_place(tmp_path):
    job = tmp_path / "tagged.yaml"
    job.write_text(
        (DATA.parent.parent / "examples" / "jobs" / "blended_tool_move.yaml")
        .read_text()
        .replace("velocity: 0.25", "velocity: !!float quick", 1)
    )
    status, err = cli_in_child(["check", str(job)])
    assert status == 1 and re.search(rf"{re.escape(str(job))}:\d+:\d+: not valid YAML: 'quick' is no float", err), err
