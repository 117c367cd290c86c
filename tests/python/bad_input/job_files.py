"""The rows of the bad-input table (tests/python/test_bad_input_table.py) of one area: Job
files (dispkin.jobs.load_job) and the command line (dispkin.cli.main)."""

import contextlib
import io
import os
import pathlib

from dispkin import cli
from dispkin import jobs

from .rows import V, _TMP, row

# --- job files (dispkin.jobs.load_job) and the command line (dispkin.cli.main) --------------


JOB_DIR = pathlib.Path(_TMP) / "jobs"
JOB_DIR.mkdir()
GOOD_JOB = """metric_set:
  points:
    - relative: [[0, 0, 0.3]]
    - {shape: sphere, radius: 0.1, center: [0, 0, 0]}
start: {xyzuvw: [0, 0, 0, 0, 0, 0]}
moves:
  - lin: {to: {xyzuvw: [0.05, 0.02, 0, 10, 0, 30]}}
limits: {velocity: 0.1, acceleration: 0.5, jerk: 5.0}
"""


def job_file(name, text=None, data=None):
    """A job file `name` in the table's temporary directory: `text`, or GOOD_JOB with the
    (old, new) replacements in `data` (bytes are written as they are)."""
    path = JOB_DIR / name
    if isinstance(text, bytes):
        path.write_bytes(text)
    else:
        if text is None:
            text = GOOD_JOB
            for old, new in data or ():
                assert old in text, old
                text = text.replace(old, new)
        path.write_text(text)
    return str(path)


class ExitStatus(Exception):
    """A non-zero exit of dispkin.cli.main, as the table's exception: the message is the exit
    status and what the command wrote to stderr (without argparse's usage lines)."""


def run_cli(*argv):
    """dispkin.cli.main(argv) run in the table's job directory (file names in the messages are
    then as given) with stdout and stderr captured; raises ExitStatus if it fails."""
    err = io.StringIO()
    here = os.getcwd()
    os.chdir(JOB_DIR)
    try:
        with contextlib.redirect_stderr(err), contextlib.redirect_stdout(io.StringIO()):
            status = cli.main(list(argv))
    except SystemExit as exit:  # argparse
        status = exit.code
    finally:
        os.chdir(here)
    if status != 0:
        lines = err.getvalue().splitlines()
        while lines and (lines[0].startswith("usage:") or lines[0].startswith(" ")):
            lines.pop(0)
        raise ExitStatus(f"exit status {status}: " + "\n".join(lines))
    return status


def missing_job():
    return str(JOB_DIR / "missing.yaml")


row(
    "jobs.load_job",
    "missing file",
    lambda: jobs.load_job(missing_job()),
    V,
    "missing.yaml: cannot read the job file: No such file or directory",
)
row(
    "jobs.load_job",
    "not UTF-8",
    lambda: jobs.load_job(job_file("latin1.yaml", b"name: d\xe9mo\n")),
    V,
    "latin1.yaml:1:8: the job file is not UTF-8 text: byte 0xe9",
)
row(
    "jobs.load_job",
    "empty file",
    lambda: jobs.load_job(job_file("empty.yaml", "")),
    V,
    "empty.yaml: the job file is empty",
)
row(
    "jobs.load_job",
    "malformed YAML (unclosed bracket)",
    lambda: jobs.load_job(job_file("malformed.yaml", data=[("jerk: 5.0}", "jerk: 5.0")])),
    V,
    "malformed.yaml:9:1: not valid YAML: expected ',' or '}', but got '<stream end>'",
)
row(
    "jobs.load_job",
    "not a mapping",
    lambda: jobs.load_job(job_file("list.yaml", "- lin\n- circ\n")),
    V,
    "list.yaml:1:1: (job): a job is a mapping of keys",
)
row(
    "jobs.load_job",
    "NaN velocity limit",
    lambda: jobs.load_job(job_file("nan_limit.yaml", data=[("velocity: 0.1", "velocity: .nan")])),
    V,
    "nan_limit.yaml:8:10: limits.velocity: nan: must be finite",
)
row(
    "jobs.load_job",
    "+inf acceleration limit",
    lambda: jobs.load_job(job_file("inf_limit.yaml", data=[("acceleration: 0.5", "acceleration: .inf")])),
    V,
    "inf_limit.yaml:8:25: limits.acceleration: inf: must be finite",
)
row(
    "jobs.load_job",
    "zero velocity limit",
    lambda: jobs.load_job(job_file("zero_limit.yaml", data=[("velocity: 0.1", "velocity: 0")])),
    V,
    "zero_limit.yaml:8:10: limits.velocity: 0 is less than or equal to the minimum of 0",
)
row(
    "jobs.load_job",
    "negative sphere radius",
    lambda: jobs.load_job(job_file("radius.yaml", data=[("radius: 0.1", "radius: -0.1")])),
    V,
    "radius.yaml:4:23: metric_set.points[1].radius: -0.1 is less than or equal to the minimum of 0",
)
row(
    "jobs.load_job",
    "both center and centre",
    lambda: jobs.load_job(job_file("both.yaml", data=[("center: [0, 0, 0]", "center: [0, 0, 0], centre: [0, 0, 0]")])),
    V,
    "both.yaml:4:55: metric_set.points[1].centre: `centre` is an alias of `center`: give one of them, not both",
)
row(
    "jobs.load_job",
    "NaN center",
    lambda: jobs.load_job(job_file("nan_center.yaml", data=[("center: [0, 0, 0]", "center: [0, .nan, 0]")])),
    V,
    "nan_center.yaml:4:48: metric_set.points[1].center[1]: nan: must be finite",
)
row(
    "cli.main",
    "unknown option",
    lambda: run_cli("plan", pathlib.Path(job_file("good.yaml")).name, "--bogus"),
    ExitStatus,
    "exit status 2: dispkin: error: unrecognized arguments: --bogus",
)
row(
    "cli.main",
    "no command",
    lambda: run_cli(),
    ExitStatus,
    "exit status 2: dispkin: error: the following arguments are required: COMMAND",
)
row(
    "cli.main",
    "unknown command",
    lambda: run_cli("run", "good.yaml"),
    ExitStatus,
    "exit status 2: dispkin: error: argument COMMAND: invalid choice: 'run'",
)
row(
    "cli.main",
    "demo --moves 0",
    lambda: run_cli("demo", "--moves", "0", "--no-job", "-q"),
    ExitStatus,
    "exit status 2: dispkin demo: error: argument --moves: must be a positive integer, got 0",
)
row(
    "cli.main",
    "demo --moves not a number",
    lambda: run_cli("demo", "--moves", "many", "--no-job", "-q"),
    ExitStatus,
    "exit status 2: dispkin demo: error: argument --moves: must be a positive integer, got 'many'",
)
row(
    "cli.main",
    "check of a missing file",
    lambda: run_cli("check", "missing.yaml"),
    ExitStatus,
    "exit status 1: dispkin check: missing.yaml: cannot read the job file: No such file or directory",
)
row(
    "cli.main",
    "check of malformed YAML",
    lambda: run_cli("check", pathlib.Path(job_file("malformed_cli.yaml", data=[("jerk: 5.0}", "jerk: 5.0")])).name),
    ExitStatus,
    "exit status 1: dispkin check: malformed_cli.yaml:9:1: not valid YAML: expected ',' or '}', but got '<stream end>'",
)
row(
    "cli.main",
    "plan of a job with a NaN limit",
    lambda: run_cli(
        "plan", pathlib.Path(job_file("nan_plan.yaml", data=[("jerk: 5.0", "jerk: .nan")])).name, "-o", "out"
    ),
    ExitStatus,
    "exit status 1: dispkin plan: nan_plan.yaml:8:44: limits.jerk: nan: must be finite",
)
