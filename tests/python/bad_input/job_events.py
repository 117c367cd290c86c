"""The rows of the bad-input table (tests/python/test_bad_input_table.py) of one area: Job
events: stops, resumptions, speed overrides."""

import pathlib

from dispkin import jobs

from .rows import V, row, section
from .serial_arm import URDF
from .job_files import ExitStatus, GOOD_JOB, job_file, run_cli
from .hostile_inputs import UR_JOB, ur_job

section("Job events (stops, resumptions, speed overrides)")


def events_job(name, *lines):
    """GOOD_JOB with an `events` list of `lines` (the list on line 9, its first entry on line 10)."""
    return job_file(name, GOOD_JOB + "events:\n" + "".join(line + "\n" for line in lines))


def ptp_events_job():
    """The UR5e job with a PTP move before its LIN move, and a stop."""
    text = UR_JOB.format(urdf=URDF / "arm_ur5e_dh.urdf").replace(
        "moves:\n", "moves:\n  - ptp: {joints: [0.1, -1.9, 1.9, -1.57, -1.57, 0.0]}\n"
    )
    return pathlib.Path(job_file("events_ptp.yaml", text + "events:\n  - {at: 0.5, stop: true}\n")).name


row(
    "jobs.load_job",
    "events out of time order",
    lambda: jobs.load_job(events_job("events_order.yaml", "  - {at: 2, stop: true}", "  - {at: 1, resume: true}")),
    V,
    "events_order.yaml:11:6: events[1].at: 1: before the event before it (events[0].at = 2): give the events in time order",
)
row(
    "jobs.load_job",
    "a resume without a stop before it",
    lambda: jobs.load_job(events_job("events_resume.yaml", "  - {at: 1, resume: true}")),
    V,
    "events_resume.yaml:10:13: events[0].resume: true: no stop before it",
)
row(
    "jobs.load_job",
    "two stops in a row",
    lambda: jobs.load_job(events_job("events_stops.yaml", "  - {at: 0.5, stop: true}", "  - {at: 1, stop: true}")),
    V,
    "events_stops.yaml:11:13: events[1].stop: true: the motion is already stopped, by events[0] at t = 0.5 s",
)
row(
    "jobs.load_job",
    "override factor 0",
    lambda: jobs.load_job(events_job("events_zero.yaml", "  - {at: 0.5, override: 0}")),
    V,
    "events_zero.yaml:10:15: events[0].override: 0: must be in [0.001, 10]",
)
row(
    "jobs.load_job",
    "override factor 20",
    lambda: jobs.load_job(events_job("events_twenty.yaml", "  - {at: 0.5, override: 20}")),
    V,
    "events_twenty.yaml:10:15: events[0].override: 20: must be in [0.001, 10]",
)
row(
    "jobs.load_job",
    "an unknown key in an event",
    lambda: jobs.load_job(events_job("events_key.yaml", "  - {at: 0.5, stop: true, speed: 2}")),
    V,
    "events_key.yaml:10:27: events[0].speed: unknown key (allowed here: at, override, resume, stop)",
)
row(
    "jobs.load_job",
    "an event time that is a word",
    lambda: jobs.load_job(events_job("events_word.yaml", "  - {at: soon, stop: true}")),
    V,
    "events_word.yaml:10:6: events[0].at: 'soon' is not of type 'number'",
)
row(
    "jobs.load_job",
    "stop: false",
    lambda: jobs.load_job(events_job("events_false.yaml", "  - {at: 1, stop: false}")),
    V,
    "events_false.yaml:10:13: events[0].stop: false: a `stop` event is written `stop: true`",
)
row(
    "jobs.load_job",
    "a negative event time",
    lambda: jobs.load_job(events_job("events_negative.yaml", "  - {at: -1, stop: true}")),
    V,
    "events_negative.yaml:10:6: events[0].at: -1 is less than the minimum of 0",
)
row(
    "jobs.load_job",
    "a NaN event time",
    lambda: jobs.load_job(events_job("events_nan.yaml", "  - {at: .nan, stop: true}")),
    V,
    "events_nan.yaml:10:6: events[0].at: nan: must be finite",
)
row(
    "jobs.load_job",
    "a stop and an override in one event",
    lambda: jobs.load_job(events_job("events_two.yaml", "  - {at: 1, stop: true, override: 0.5}")),
    V,
    "events_two.yaml:10:5: events[0]: expected exactly one of `stop` | `resume` | `override`; found `at`, `stop`, `override`",
)
row(
    "jobs.load_job",
    "1001 events",
    lambda: jobs.load_job(events_job("events_many.yaml", *(f"  - {{at: {k}, override: 0.5}}" for k in range(1001)))),
    V,
    "events_many.yaml:9:1: events: 1001 events, more than 1000, the most a job may have",
)
row(
    "cli.main",
    "check: events in a job with a PTP move (planned part by part)",
    lambda: run_cli("check", ptp_events_job()),
    ExitStatus,
    "exit status 1: dispkin check: events_ptp.yaml:12:1: events: events apply to a job planned as one Cartesian trajectory; moves[0] is a PTP move",
)
row(
    "cli.main",
    "check: events in a re-timed job",
    lambda: run_cli(
        "check", ur_job("events_retime.yaml", "retime: {method: optimal}", "events:", "  - {at: 0.5, override: 0.5}")
    ),
    ExitStatus,
    "exit status 1: dispkin check: events_retime.yaml:12:1: events: a re-timed trajectory (`retime`) keeps to the joint limits",
)
row(
    "cli.main",
    "plan: a stop after the motion has ended",
    lambda: run_cli("plan", pathlib.Path(events_job("events_late.yaml", "  - {at: 50, stop: true}")).name, "-o", "out"),
    ExitStatus,
    "exit status 1: dispkin plan: events_late.yaml:10:6: events[0].at: 50: the motion ends at t = 1.38066 s; a stop at or after its end changes nothing",
)
row(
    "cli.main",
    "plan: a resume of a stop that came to rest at the end of the path",
    lambda: run_cli(
        "plan",
        pathlib.Path(events_job("events_end.yaml", "  - {at: 1.1, stop: true}", "  - {at: 2, resume: true}")).name,
        "-o",
        "out",
    ),
    ExitStatus,
    "exit status 1: dispkin plan: events_end.yaml:11:13: events[1].resume: true: nothing to resume",
)
row(
    "jobs.plan_job",
    "a stop at 0 never resumed (no motion)",
    lambda: jobs.plan_job(jobs.load_job(events_job("events_never.yaml", "  - {at: 0, stop: true}"))),
    V,
    "events_never.yaml:10:6: events[0].at: 0: the stop comes before the motion starts and no resumption follows",
)
