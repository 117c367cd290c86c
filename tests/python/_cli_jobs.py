"""What the tests of `dispkin plan` on job files share (test_cli_limits.py,
test_cli_limits_between_samples.py, test_cli_output_files.py, test_cli_values_as_written.py):
the test jobs and the examples, made into job files with lines added or dropped.
"""

import pathlib


from dispkin import cli


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
