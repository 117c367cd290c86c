"""`dispkin batch` and dispkin.batch: many jobs on local processes or a Dask cluster, each planned
exactly as `dispkin plan` plans it alone, one summary table, a failed job reported and the
others planned."""

import contextlib
import csv
import io
import json
import os
import pathlib
import shutil

import pytest

import dispkin
from dispkin import batches, cli, jobs
from dispkin.commands import EXIT_LIMITS_BROKEN

ROOT = pathlib.Path(__file__).resolve().parents[2]
DATA = ROOT / "tests" / "data" / "jobs"

# Two variants of one move (limits), a hexapod job whose trajectory breaks its leg limits, and a
# job that cannot be planned (a negative velocity limit).
VARIANT = """name: {name}
metric_set:
  points:
    - relative: [[0, 0, 0.3]]
    - {{shape: sphere, radius: 0.1, center: [0, 0, 0]}}
start: {{xyzuvw: [0, 0, 0, 0, 0, 0]}}
moves:
  - lin: {{to: {{xyzuvw: [0.05, 0.02, 0, 10, 0, 30]}}}}
limits: {{velocity: {velocity}, acceleration: 0.5, jerk: 5.0}}
"""


@pytest.fixture
def job_files(tmp_path, monkeypatch):
    """Four job files in tmp_path/jobs, named relative to tmp_path (the current directory):
    slow.yaml, fast.yaml, the violating hexapod job, and a bad one."""
    monkeypatch.chdir(tmp_path)
    directory = pathlib.Path("jobs")
    directory.mkdir()
    for name, velocity in (("slow", 0.05), ("fast", 0.2)):
        (directory / f"{name}.yaml").write_text(VARIANT.format(name=name, velocity=velocity))
    for source in ("violating_hexapod_too_high.yaml", "bad_negative_velocity.yaml"):
        shutil.copy(DATA / source, directory / source)
    return [
        str(directory / name)
        for name in ("slow.yaml", "fast.yaml", "violating_hexapod_too_high.yaml", "bad_negative_velocity.yaml")
    ]


def plan_alone(job_file, outdir):
    """`dispkin plan JOB -o OUTDIR`: (exit status, stderr)."""
    errors = io.StringIO()
    with contextlib.redirect_stderr(errors), contextlib.redirect_stdout(io.StringIO()):
        status = cli.main(["plan", job_file, "-o", str(outdir), "-q"])
    return status, errors.getvalue()


def read_table(directory):
    with open(directory / batches.SUMMARY_FILE, newline="", encoding="utf-8") as f:
        return list(csv.DictReader(f))


def assert_same_as_planned_alone(job_files, outdir, alone):
    """Each job's folder holds byte for byte what `dispkin plan` writes for it alone, and the
    summary table has its duration, binding limit and broken limits; the bad job failed with
    the error `dispkin plan` gives."""
    rows = read_table(outdir)
    assert [r["job"] for r in rows] == job_files
    assert [r["folder"] for r in rows] == ["slow", "fast", "violating_hexapod_too_high", "bad_negative_velocity"]
    for job_file, row in zip(job_files[:3], rows):
        status, _ = plan_alone(job_file, alone / row["folder"])
        expected = sorted(p.name for p in (alone / row["folder"]).iterdir())
        assert sorted(p.name for p in (outdir / row["folder"]).iterdir()) == expected and len(expected) == 3
        for name in expected:
            assert (outdir / row["folder"] / name).read_bytes() == (alone / row["folder"] / name).read_bytes(), name
        job = jobs.load_job(job_file)
        summary = json.loads((alone / row["folder"] / job.outputs["json"]).read_text())["dispkin"]["summary"]
        assert float(row["duration"]) == summary["duration"] and row["binding"] == summary["binding"]
        assert int(row["violations"]) == len(summary["violations"]) and row["error"] == ""
        assert row["status"] == ("limits broken" if status == EXIT_LIMITS_BROKEN else "planned")
    assert [r["status"] for r in rows] == ["planned", "planned", "limits broken", "failed"]
    assert float(rows[0]["duration"]) > float(rows[1]["duration"])  # the slower variant takes longer
    assert rows[2]["broken_limits"].startswith("position of leg")
    status, err = plan_alone(job_files[3], alone / "bad")
    assert status == 1 and err == f"dispkin plan: {rows[3]['error']}\n"  # the very error of planning it alone
    assert "limits.velocity" in rows[3]["error"] and rows[3]["duration"] == "" and rows[3]["violations"] == ""
    assert not (outdir / "bad_negative_velocity").exists()
    return rows


def test_batch_on_local_processes_is_planning_each_job_alone(job_files, tmp_path, capsys):
    status = cli.main(["batch", *job_files, "-o", str(tmp_path / "out"), "--workers", "2", "--progress"])
    captured = capsys.readouterr()
    assert status == 1  # a job failed: that outranks the broken limits of another
    rows = assert_same_as_planned_alone(job_files, tmp_path / "out", tmp_path / "alone")
    assert rows[3]["error"].startswith(f"{job_files[3]}:8:3: limits.velocity: -0.1")  # named as given
    assert f"dispkin batch: {rows[3]['error']}\n" in captured.err
    assert "dispkin batch: 1 of 4 job(s) failed" in captured.err
    assert f"dispkin batch: {job_files[2]}: the trajectory breaks" in captured.err
    # Progress: a line per finished job, then the last one.
    assert sum(f"/4 jobs: {job}: " in captured.err for job in job_files) == 4
    assert "dispkin batch: 4 job(s) done" in captured.err
    assert "3 of 4 job(s) planned" in captured.out


def test_batch_exit_status_without_a_failed_job(job_files, tmp_path, capsys):
    """A trajectory that breaks a machine limit gives dispkin plan's exit status 3, unless allowed."""
    out = tmp_path / "out"
    assert cli.main(["batch", *job_files[1:3], "-o", str(out), "--workers", "1", "-q"]) == EXIT_LIMITS_BROKEN
    assert "use --allow-violations" in capsys.readouterr().err
    assert cli.main(["batch", job_files[1], job_files[1], "-o", str(out), "--allow-violations", "-q"]) == 0
    assert [r["folder"] for r in read_table(out)] == ["fast", "fast-2"]  # one folder per job, never shared
    assert (out / "fast-2" / "fast.csv").read_bytes() == (out / "fast" / "fast.csv").read_bytes()


def test_batch_on_a_dask_cluster_is_planning_each_job_alone(job_files, tmp_path):
    distributed = pytest.importorskip("distributed")
    with distributed.LocalCluster(
        n_workers=1, threads_per_worker=2, processes=False, dashboard_address=None
    ) as cluster:
        results = dispkin.batch(job_files, tmp_path / "out", scheduler=cluster.scheduler_address)
    assert [r.status for r in results] == ["planned", "planned", "limits broken", "failed"]
    assert [r.outdir for r in results] == [tmp_path / "out" / r["folder"] for r in read_table(tmp_path / "out")]
    rows = assert_same_as_planned_alone(job_files, tmp_path / "out", tmp_path / "alone")
    assert [r.duration for r in results[:3]] == [float(r["duration"]) for r in rows[:3]]
    assert results[3].error == rows[3]["error"] and results[2].violations == rows[2]["broken_limits"].split("; ")


def plan_or_die(job_file, outdir, plot):
    """The planning of a batch's worker, except that the process planning fast.yaml dies (as one
    killed for its memory does)."""
    if pathlib.Path(job_file).name == "fast.yaml":
        os._exit(9)
    return batches.plan_job_file(job_file, outdir, plot)


def test_a_worker_process_that_dies_fails_its_job_alone(job_files, tmp_path):
    tasks = [
        (str(pathlib.Path(job).absolute()), str(tmp_path / "out" / str(k)), False)
        for k, job in enumerate(job_files[:3])
    ]
    outcomes = dict(batches._run_on_processes(2, plan_or_die)(tasks))
    assert sorted(outcomes) == [0, 1, 2]
    assert outcomes[1]["error"] == "the worker process planning it died: killed (out of memory?) or crashed"
    for k in (0, 2):  # the jobs the dying process took down with its pool are planned again
        assert outcomes[k]["duration"] > 0 and (tmp_path / "out" / str(k)).is_dir()
