"""atheris (libFuzzer for Python) target: job files. The fuzzer's bytes are the text of a job
file, written to a scratch directory laid out like the repository (so the relative URDF and
hexapod paths of the seed jobs resolve), then read by ``dispkin.jobs.load_job``; a job of at
most ``MAX_PLANNED_SECTIONS`` Cartesian path sections (PTP moves aside) is also planned with
``plan_job``.

A finding is anything but the loader's documented outcome: a job, or a ``JobError`` (a
ValueError naming the key and line). Any other exception, a crash, a hang (libFuzzer's
``-timeout``) or a planned trajectory with a non-finite duration aborts the run and saves the
input. Run by ``scripts/run-fuzzers.sh fuzz_jobs`` (``make fuzz``), which installs atheris into
the venv from ``requirements-fuzz.txt``; seeds: ``examples/jobs`` and ``tests/data/jobs``.

Usage (libFuzzer flags): ``python tests/fuzz/fuzz_jobs.py [-runs=N] [-max_total_time=S] CORPUS...``
"""

import math
import os
import pathlib
import sys

import atheris

with atheris.instrument_imports():
    import yaml  # noqa: F401  (instrumented: its parser is most of what the bytes reach)
    import jsonschema  # noqa: F401
    from dispkin import jobs

REPO = pathlib.Path(__file__).resolve().parents[2]
# Paths of planned jobs are bounded: planning thousands of sections takes too long per input.
MAX_PLANNED_SECTIONS = 200


def scratch_directory() -> pathlib.Path:
    """<scratch>/data/jobs, with <scratch>/tests → the repository's tests (examples/jobs write
    ../../tests/data/urdf/…), <scratch>/data/urdf → tests/data/urdf and data/jobs/hexapod.json →
    tests/data/jobs/hexapod.json (tests/data/jobs write ../urdf/… and hexapod.json)."""
    root = pathlib.Path(os.environ.get("FUZZ_JOBS_SCRATCH", REPO / "build" / "fuzz" / "jobs_scratch")).resolve()
    job_dir = root / "data" / "jobs"
    job_dir.mkdir(parents=True, exist_ok=True)
    links = {
        root / "tests": REPO / "tests",
        root / "data" / "urdf": REPO / "tests" / "data" / "urdf",
    }
    for extra in (REPO / "tests" / "data" / "jobs").iterdir():
        if extra.suffix != ".yaml":
            links[job_dir / extra.name] = extra
    for link, target in links.items():
        if not link.is_symlink():
            link.symlink_to(target)
    return job_dir


JOB_FILE = scratch_directory() / "job.yaml"


def test_one_input(data: bytes) -> None:
    JOB_FILE.write_bytes(data)
    try:
        job = jobs.load_job(JOB_FILE)
    except jobs.JobError:
        return
    # The Cartesian runs are bounded; a PTP move cuts itself into sections by its own
    # tolerance (about 10³ per move, a few milliseconds).
    cartesian = [part.path for part in job.parts if part.kind == "path"] if job.has_ptp else [job.path]
    if sum(len(path) for path in cartesian) > MAX_PLANNED_SECTIONS:
        return
    try:
        trajectory = jobs.plan_job(job)
    except jobs.JobError:
        return
    if not math.isfinite(trajectory.duration):
        raise AssertionError(f"plan_job: non-finite duration {trajectory.duration}")


def main() -> None:
    atheris.Setup(sys.argv, test_one_input)
    atheris.Fuzz()


if __name__ == "__main__":
    main()
