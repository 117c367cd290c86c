"""atheris (libFuzzer for Python) target: limits files (MoveIt's joint_limits.yaml, the Pilz
planner's cartesian_limits.yaml). The fuzzer's bytes are the text of a limits file, written to a
scratch directory, then read by ``dispkin.limits_files`` (``load_limits_file``,
``read_moveit_joint_limits`` and ``read_pilz_cartesian_limits``; a MoveIt file that reads is
applied to the UR5e of tests/data/urdf) and through a job that names it in ``limits_file:``
(``dispkin.jobs.load_job``).

A finding is anything but the documented outcomes: limits, a ``LimitsFileError`` (a ValueError
naming the file, line and key) from the readers, a ``JobError`` from the job. Any other
exception, a message longer than MAX_MESSAGE characters (a file must not be echoed into its
error), a crash or a hang (libFuzzer's ``-timeout``) aborts the run and saves the input. Run by
``scripts/run-fuzzers.sh fuzz_limits_files``; seeds: ``tests/fuzz/corpus/fuzz_limits_files``.

Usage (libFuzzer flags): ``python tests/fuzz/fuzz_limits_files.py [-runs=N] [-max_total_time=S] CORPUS...``
"""

import os
import pathlib
import sys

import atheris

with atheris.instrument_imports():
    import yaml  # noqa: F401  (instrumented: its parser is most of what the bytes reach)
    from dispkin import jobs, limits_files
    from dispkin.job import input_budget, reader  # noqa: F401

import dispkin

REPO = pathlib.Path(__file__).resolve().parents[2]
#: Longest message accepted: a file, a line and column, a key and a value shown to 200 characters.
MAX_MESSAGE = 2000
SCRATCH = pathlib.Path(os.environ.get("FUZZ_LIMITS_SCRATCH", REPO / "build" / "fuzz" / "limits_scratch")).resolve()
SCRATCH.mkdir(parents=True, exist_ok=True)
LIMITS_FILE = SCRATCH / "limits.yaml"
JOB_FILE = SCRATCH / "job.yaml"
JOB_FILE.write_text(
    (REPO / "examples" / "jobs" / "ur5e_lin_move.yaml")
    .read_text()
    .replace("urdf: ../../tests/data/urdf/", f"urdf: {REPO / 'tests' / 'data' / 'urdf'}/")
    + "limits_file: limits.yaml\n"
)
ARM = dispkin.SerialArm.from_urdf(str(REPO / "tests" / "data" / "urdf" / "arm_ur5e_dh.urdf"), "base_link", "tool0")


def refused(error: Exception) -> None:
    """A documented refusal: its message is short and text."""
    message = str(error)
    if len(message) > MAX_MESSAGE:
        raise AssertionError(f"a message of {len(message)} characters: {message[:300]!r}")
    message.encode("utf-8")


def read(reader_function) -> object:
    try:
        return reader_function(LIMITS_FILE)
    except limits_files.LimitsFileError as error:
        refused(error)
        return None


def test_one_input(data: bytes) -> None:
    LIMITS_FILE.write_bytes(data)
    moveit = read(limits_files.read_moveit_joint_limits)
    read(limits_files.read_pilz_cartesian_limits)
    if moveit is not None:
        try:
            limits_files.apply_moveit_joint_limits(ARM, moveit)
        except limits_files.LimitsFileError as error:
            refused(error)
    try:
        jobs.load_job(JOB_FILE)
    except jobs.JobError as error:
        refused(error)


def main() -> None:
    atheris.Setup(sys.argv, test_one_input)
    atheris.Fuzz()


if __name__ == "__main__":
    main()
