"""The rows of the bad-input table (tests/python/test_bad_input_table.py) of one area: Batches
(dispkin.batch, dispkin batch)."""

import pathlib

import dispkin

from .rows import V, row, section
from .job_files import ExitStatus, JOB_DIR, job_file, run_cli

section("Batches")

BATCH_OUT = str(JOB_DIR / "batch_out")
row("dispkin.batch", "no job file", lambda: dispkin.batch([], BATCH_OUT), V, "jobs: no job file given")
row(
    "dispkin.batch",
    "workers = 0",
    lambda: dispkin.batch([job_file("good.yaml")], BATCH_OUT, workers=0),
    V,
    "workers = 0: must be an integer from 1 to ",
)
row(
    "dispkin.batch",
    "workers = 2.5",
    lambda: dispkin.batch([job_file("good.yaml")], BATCH_OUT, workers=2.5),
    V,
    "workers = 2.5: must be an integer from 1 to ",
)
row(
    "dispkin.batch",
    "workers and a scheduler",
    lambda: dispkin.batch([job_file("good.yaml")], BATCH_OUT, workers=2, scheduler="tcp://127.0.0.1:8786"),
    V,
    "workers = 2: give either workers (local processes) or scheduler (a Dask cluster), not both",
)
row(
    "dispkin.batch",
    "scheduler = 42",
    lambda: dispkin.batch([job_file("good.yaml")], BATCH_OUT, scheduler=42),
    V,
    "scheduler = 42: must be the address of a Dask scheduler (e.g. 'tcp://host:8786') or a distributed.Client",
)
row(
    "cli.main",
    "batch -o naming an existing file",
    lambda: run_cli("batch", "good.yaml", "-o", pathlib.Path(job_file("batch_file.txt", "not a directory\n")).name),
    ExitStatus,
    "exit status 1: dispkin batch: -o DIR = 'batch_file.txt': is not a directory",
)
row(
    "cli.main",
    "batch --scheduler without a port",
    lambda: run_cli("batch", "good.yaml", "-o", "out", "--scheduler", "nowhere"),
    ExitStatus,
    "exit status 1: dispkin batch: --scheduler = 'nowhere': cannot connect to a Dask scheduler there: missing port number in address 'nowhere'",
)
row(
    "cli.main",
    "batch --workers 0",
    lambda: run_cli("batch", "good.yaml", "-o", "out", "--workers", "0"),
    ExitStatus,
    "exit status 2: dispkin batch: error: argument --workers: must be a positive integer, got 0",
)
row(
    "cli.main",
    "batch with --workers and --scheduler",
    lambda: run_cli("batch", "good.yaml", "-o", "out", "--workers", "2", "--scheduler", "tcp://h:1"),
    ExitStatus,
    "exit status 2: dispkin batch: error: argument --scheduler: not allowed with argument --workers",
)
row(
    "cli.main",
    "batch without -o",
    lambda: run_cli("batch", "good.yaml"),
    ExitStatus,
    "exit status 2: dispkin batch: error: the following arguments are required: -o/--outdir",
)
