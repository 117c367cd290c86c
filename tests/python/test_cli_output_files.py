"""`dispkin plan`'s output files: checked before any work (names, directories, FIFOs), and never
an input of the job (the job file, its limits file, its URDF)."""

import json
import os
import re
import subprocess
import sys

import pytest

from dispkin import jobs

from _cli_jobs import DATA, LIN, example_job, plan


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
