"""Job files with `events`: stops, resumptions and speed overrides applied to the planned
Cartesian trajectory (doc/events.md). `dispkin plan` samples, writes and summarises the trajectory
after them; `dispkin check` validates them; every bad event is refused at its key and line."""

import csv
import json
import pathlib
import re
import subprocess
import sys

import numpy as np
import pytest

import dispkin
from dispkin import cli, jobs
from dispkin.commands import EXIT_LIMITS_BROKEN
from dispkin.job import input_budget

ROOT = pathlib.Path(__file__).resolve().parents[2]
EXAMPLE = ROOT / "examples" / "jobs" / "ur5e_lin_move_events.yaml"
VIOLATING = ROOT / "tests" / "data" / "jobs" / "violating_ur5e_too_fast.yaml"

# Eight lines, then `events:` on line 9 and its entries from line 10 on.
BASE = """metric_set:
  points:
    - relative: [[0, 0, 0.3]]
    - {shape: sphere, radius: 0.1, center: [0, 0, 0]}
start: {xyzuvw: [0, 0, 0, 0, 0, 0]}
moves:
  - lin: {to: {xyzuvw: [0.05, 0.02, 0, 10, 0, 30]}}
limits: {velocity: 0.1, acceleration: 0.5, jerk: 5.0}
"""


def job_with(directory, *lines, base=BASE, name="job.yaml"):
    """`base` with `lines` appended, written as `name` in `directory`."""
    path = directory / name
    path.write_text(base + "".join(line + "\n" for line in lines))
    return path


def arm_job(example, directory, *lines, name="job.yaml"):
    """A job file of examples/jobs or tests/data/jobs with its URDF path made absolute and `lines` appended."""
    text = example.read_text()
    for relative in ("../../tests/data/urdf/", "../urdf/"):
        text = text.replace(f"urdf: {relative}", f"urdf: {ROOT / 'tests' / 'data' / 'urdf'}/")
    return job_with(directory, *lines, base=text, name=name)


def read_csv(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    return rows[0], np.array(rows[1:], dtype=float)


def planned(job_file, outdir, capsys, *extra):
    """(exit status, printed summary, CSV header, CSV table, JSON summary) of `dispkin plan`."""
    status = cli.main(["plan", str(job_file), "-o", str(outdir), *extra])
    out = capsys.readouterr().out
    job = jobs.load_job(job_file)
    header, table = read_csv(outdir / job.outputs["csv"])
    summary = json.loads((outdir / job.outputs["json"]).read_text())["dispkin"]["summary"]
    return status, out, header, table, summary


# --- what `dispkin plan` writes ------------------------------------------------------------


def test_stop_resume_and_override_in_the_written_samples(tmp_path, capsys):
    """The example job (a UR5e LIN move followed by the arm): the sampled path velocity is the
    plan's up to the stop, falls to 0 within the stop's duration and stays there until the
    resumption, runs again to the end of the path, and after the override's easing stays within
    the factor times the velocity limit."""
    status, out, header, table, summary = planned(EXAMPLE, tmp_path, capsys, "--plot")
    assert status == 0
    job = jobs.load_job(EXAMPLE)
    stop, resume, override = job.events
    assert [e.kind for e in job.events] == ["stop", "resume", "override"] and override.factor == 0.5
    t, v = table[:, 0], table[:, header.index("path_velocity_mps")]
    fastest = table[:, header.index("fastest_point_speed_mps")]
    plan = dispkin.plan(job.path, job.metric_set, job.limits, job.profile)
    # Before the stop: the motion as planned, bit for bit.
    before = t < stop.at
    np.testing.assert_array_equal(v[before], plan.path_velocity(t[before]))
    # The stop: braking (never faster than when it began) to rest within its duration, at rest
    # until the resumption.
    record = summary["events"][0]
    assert record["kind"] == "stop" and record["at"] == stop.at and record["came_to_rest"]
    a, j, v_max = job.limits.acceleration, job.limits.jerk, job.limits.velocity
    assert 0.0 < record["stop_duration"] <= record["path_velocity"] / a + a / j + 1e-12
    braking = (t >= stop.at) & (t < stop.at + record["stop_duration"])
    assert np.all(np.diff(v[braking]) <= 1e-15) and np.all(v[braking] <= record["path_velocity"])
    resting = (t >= stop.at + record["stop_duration"]) & (t <= resume.at)
    assert resting.sum() >= 10 and np.all(np.abs(v[resting]) <= 1e-12)
    assert record["stop_position"] > record["path_position"]
    # The resumption: moving again, to the end of the path.
    assert np.max(v[(t > resume.at) & (t < override.at)]) > 0.5 * v_max
    assert summary["completed"] and summary["end_position"] == summary["length"]
    final = jobs.plan_job(job)
    assert float(final.path_position(final.duration)) == pytest.approx(final.length, rel=1e-12)
    # The override: from the end of its easing (full jerk and deceleration), at most 0.5 times
    # the velocity limit, and it gets there; the fastest point of the tool too.
    eased = override.at + 2 * a / j + (1.0 - override.factor) * v_max / a
    after = t >= eased
    assert after.sum() >= 10
    assert np.all(v[after] <= override.factor * v_max * (1 + 1e-9))
    assert np.max(v[after]) >= 0.99 * override.factor * v_max
    assert np.all(fastest[after] <= override.factor * v_max * (1 + 1e-6))
    assert np.all(v <= v_max * (1 + 1e-9)) and np.all(fastest <= v_max * (1 + 1e-6))
    # The summary lists the events, in the JSON and in the text.
    assert [r["kind"] for r in summary["events"]] == ["stop", "resume", "override"]
    assert summary["events"][1]["factor"] == 1.0 and summary["events"][2] == {
        "at": override.at,
        "kind": "override",
        "path_position": pytest.approx(float(final.path_position(override.at)), abs=1e-15),
        "path_velocity": pytest.approx(float(final.path_velocity(override.at)), abs=1e-15),
        "factor": 0.5,
        "while_stopped": False,
    }
    assert (
        f"event 0 at t = 0.4000 s: stop from s = {record['path_position']:.6f} m at {record['path_velocity']:.6f} m/s, "
        f"at rest at s = {record['stop_position']:.6f} m after {record['stop_duration']:.4f} s"
    ) in out
    assert "event 1 at t = 0.9000 s: resume from s = " in out
    assert "event 2 at t = 1.3000 s: speed override 0.5 × the velocity-limit curve as planned" in out
    assert "STOPPED" not in out
    text = (tmp_path / job.outputs["summary"]).read_text()
    assert "event 0 at t = 0.4000 s: stop" in text
    # The arm follows the trajectory after the events, from q_start, within its limits.
    assert summary["within_machine_limits"] and summary["duration"] == final.duration
    assert (tmp_path / "ur5e_lin_move_events.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_a_job_whose_events_end_stopped_says_where(tmp_path, capsys):
    """A stop without a resumption: exit status 0, and the summary says the motion ends stopped
    at s of the path's length L (completed: false); corners after it are not among its stops."""
    job_file = job_with(tmp_path, "events:", "  - {at: 0.5, stop: true}")
    status, out, header, table, summary = planned(job_file, tmp_path / "out", capsys)
    assert status == 0
    final = jobs.plan_job(jobs.load_job(job_file))
    assert final.stopped and summary["completed"] is False
    assert summary["end_position"] == final.end_position < summary["length"]
    share = 100 * final.end_position / final.length
    assert (
        f"ends STOPPED at s = {final.end_position:.6f} m of the path's {final.length:.6f} m ({share:.1f} %): "
        "the motion does not reach the end of its path"
    ) in out
    assert summary["stops"] == [{"s": final.end_position, "reason": "stopped at t = 0.5 s"}]
    v = table[:, header.index("path_velocity_mps")]
    assert table[-1, 0] == final.duration and v[-1] == 0.0


def test_a_stopped_blended_path_lists_only_the_stops_it_reaches(tmp_path, capsys):
    """On a path with corners, a stop before the second corner: the first corner is among the
    stops, the second is not (the motion never gets there)."""
    text = (ROOT / "examples" / "jobs" / "hexapod_scan.yaml").read_text()
    job_file = job_with(tmp_path, "events:", "  - {at: 1.5, stop: true}", base=text)
    status, out, _, _, summary = planned(job_file, tmp_path / "out", capsys)
    assert status == 0 and not summary["completed"]
    plan = jobs.plan_job(jobs.load_job(ROOT / "examples" / "jobs" / "hexapod_scan.yaml"))
    corners = [s for s, _ in plan.stops]
    assert len(corners) == 2 and corners[0] < summary["end_position"] < corners[1]
    assert [s["s"] for s in summary["stops"]] == [corners[0], summary["end_position"]]
    assert summary["legs"]["within_limits"]


def test_override_above_one_speeds_up_a_slowed_move_up_to_the_system_velocity(tmp_path):
    """A move's own velocity (half the system velocity) slows it; an override of 3 runs it at the
    system velocity, its ceiling, never faster."""
    base = BASE.replace(
        "  - lin: {to: {xyzuvw: [0.05, 0.02, 0, 10, 0, 30]}}\n",
        "  - lin: {to: {xyzuvw: [0.3, 0, 0, 0, 0, 0]}}\n    velocity: 0.05\n",
    )
    slow = jobs.plan_job(jobs.load_job(job_with(tmp_path, base=base, name="slow.yaml")))
    job = jobs.load_job(job_with(tmp_path, "events:", "  - {at: 0.5, override: 3}", base=base, name="fast.yaml"))
    fast = jobs.plan_job(job)
    t = np.linspace(0.0, fast.duration, 4001)
    v = fast.path_velocity(t)
    assert np.max(slow.path_velocity(t)) <= 0.05 * (1 + 1e-9)
    assert np.max(v) <= 0.1 * (1 + 1e-9) and np.max(v) >= 0.1 * (1 - 1e-9)
    assert fast.duration < 0.6 * slow.duration and fast.override_factor == 3.0


def test_an_override_while_stopped_holds_from_the_resumption(tmp_path):
    job = jobs.load_job(
        job_with(
            tmp_path,
            "events:",
            "  - {at: 0.5, stop: true}",
            "  - {at: 1.0, override: 0.2}",
            "  - {at: 1.5, resume: true}",
        )
    )
    final = jobs.plan_job(job)
    records = jobs.describe_events(job, final)
    assert records[1]["while_stopped"] and records[2]["factor"] == 0.2
    t = np.linspace(1.5, final.duration, 2001)
    assert np.max(final.path_velocity(t)) <= 0.2 * job.limits.velocity * (1 + 1e-9)
    assert final.override_factor == 0.2 and not final.stopped


@pytest.mark.parametrize(
    "events",
    [
        [(0.5, "stop", None), (0.9, "resume", None), (1.1, "override", 0.3)],
        [(0.5, "stop", None), (0.6, "resume", None)],  # resumed while braking
        [(0.3, "override", 0.5), (0.3, "stop", None), (0.3, "resume", None)],  # three at one instant
        [
            (0.0, "override", 0.5),
            (1.0, "stop", None),
            (1.5, "override", 2.0),
            (2.0, "resume", None),
            (2.2, "stop", None),
        ],
    ],
)
def test_described_events_are_those_applied_one_by_one(tmp_path, events):
    """The summary measures each stop on the trajectory after all events: the same numbers as
    the stop applied in its turn (the motion before an event is kept bit for bit)."""
    lines = ["events:"] + [
        f"  - {{at: {at}, {kind}: {'true' if factor is None else factor}}}" for at, kind, factor in events
    ]
    job = jobs.load_job(job_with(tmp_path, *lines))
    trajectory = dispkin.plan(job.path, job.metric_set, job.limits, job.profile)
    expected = []
    for k, (at, kind, factor) in enumerate(events):
        if kind == "stop":
            trajectory = trajectory.stopped_at(at)
            braking = max(trajectory.duration - at, 0.0)
            resume = (
                next(e[0] for e in events[k:] if e[1] == "resume")
                if any(e[1] == "resume" for e in events[k:])
                else None
            )
            expected.append((trajectory.end_position, braking, resume is None or resume >= at + braking))
        elif kind == "resume":
            trajectory = trajectory.resumed_at(at)
        else:
            trajectory = trajectory.with_override(at, factor)
    final = jobs.plan_job(job)
    assert final.duration == trajectory.duration and final.end_position == trajectory.end_position
    records = jobs.describe_events(job, final)
    assert [
        (r["stop_position"], r["stop_duration"], r["came_to_rest"]) for r in records if r["kind"] == "stop"
    ] == expected


def test_the_exit_status_keeps_its_rules(tmp_path, capsys):
    """A job whose trajectory breaks a joint limit still does with a stop and a resumption
    (status 3), and keeps it at a low enough override from the start (status 0)."""
    broken = arm_job(
        VIOLATING, tmp_path, "events:", "  - {at: 0.3, stop: true}", "  - {at: 1.0, resume: true}", name="broken.yaml"
    )
    assert cli.main(["plan", str(broken), "-o", str(tmp_path / "a")]) == EXIT_LIMITS_BROKEN
    assert "velocity of wrist_3_joint" in capsys.readouterr().err
    slowed = arm_job(VIOLATING, tmp_path, "events:", "  - {at: 0, override: 0.3}", name="slowed.yaml")
    assert cli.main(["plan", str(slowed), "-o", str(tmp_path / "b")]) == 0
    summary = json.loads((tmp_path / "b" / "violating_ur5e_too_fast.json").read_text())["dispkin"]["summary"]
    assert summary["within_machine_limits"] and summary["joints"]["velocity_factor"] < 1.0


def test_check_validates_and_lists_the_events(tmp_path, capsys):
    assert cli.main(["check", str(EXAMPLE)]) == 0
    out = capsys.readouterr().out
    assert (
        "  events: stop at t = 0.4 s, resume at t = 0.9 s, override 0.5 at t = 1.3 s "
        "(applied in this order to the planned trajectory)"
    ) in out


def test_the_override_range_is_the_library_s():
    low, high = jobs.OVERRIDE_RANGE
    metric_set = dispkin.MetricSet()
    metric_set.add_sphere([0, 0, 0], 0.1)
    trajectory = dispkin.plan(
        dispkin.Path.lin(dispkin.Pose(), dispkin.Pose.from_xyzuvw([0.1, 0, 0, 0, 0, 0])),
        metric_set,
        dispkin.Limits(0.1, 1.0, 10.0),
    )
    for factor in (low, high):
        assert trajectory.with_override(0.2, factor).override_factor == factor
    for factor in (low * 0.999, high * 1.001):
        with pytest.raises(ValueError, match="must be in"):
            trajectory.with_override(0.2, factor)


# --- bad events ------------------------------------------------------------------------------

# (events lines, key path, line, fragment of the reason): refused by `dispkin check` and `dispkin plan`.
BAD_EVENTS = {
    "out of order": (
        ["  - {at: 2, stop: true}", "  - {at: 1, resume: true}"],
        "events[1].at",
        11,
        "1: before the event before it (events[0].at = 2): give the events in time order",
    ),
    "resume without a stop": (["  - {at: 1, resume: true}"], "events[0].resume", 10, "true: no stop before it"),
    "two stops in a row": (
        ["  - {at: 0.5, stop: true}", "  - {at: 1, stop: true}"],
        "events[1].stop",
        11,
        "true: the motion is already stopped, by events[0] at t = 0.5 s",
    ),
    "a stop, a resume, two stops": (
        [
            "  - {at: 0.2, stop: true}",
            "  - {at: 0.4, resume: true}",
            "  - {at: 0.5, stop: true}",
            "  - {at: 0.6, override: 0.5}",
            "  - {at: 0.7, stop: true}",
        ],
        "events[4].stop",
        14,
        "already stopped, by events[2]",
    ),
    "override 0": (["  - {at: 0.5, override: 0}"], "events[0].override", 10, "0: must be in [0.001, 10]"),
    "override 20": (["  - {at: 0.5, override: 20}"], "events[0].override", 10, "20: must be in [0.001, 10]"),
    "override negative": (["  - {at: 0.5, override: -0.5}"], "events[0].override", 10, "-0.5: must be in [0.001, 10]"),
    "unknown key": (
        ["  - {at: 0.5, stop: true, speed: 2}"],
        "events[0].speed",
        10,
        "unknown key (allowed here: at, override, resume, stop)",
    ),
    "at not a number": (["  - {at: soon, stop: true}"], "events[0].at", 10, "'soon' is not of type 'number'"),
    "override not a number": (
        ["  - {at: 1, override: half}"],
        "events[0].override",
        10,
        "'half' is not of type 'number'",
    ),
    "stop: false": (
        ["  - {at: 1, stop: false}"],
        "events[0].stop",
        10,
        "false: a `stop` event is written `stop: true`",
    ),
    "resume: false": (
        ["  - {at: 0.5, stop: true}", "  - {at: 1, resume: false}"],
        "events[1].resume",
        11,
        "false: a `resume` event is written `resume: true`",
    ),
    "stop: 1": (["  - {at: 1, stop: 1}"], "events[0].stop", 10, "1 is not of type 'boolean'"),
    "negative at": (["  - {at: -1, stop: true}"], "events[0].at", 10, "-1 is less than the minimum of 0"),
    "NaN at": (["  - {at: .nan, stop: true}"], "events[0].at", 10, "nan: must be finite"),
    "infinite at": (["  - {at: .inf, override: 0.5}"], "events[0].at", 10, "inf: must be finite"),
    "two kinds in one event": (
        ["  - {at: 1, stop: true, override: 0.5}"],
        "events[0]",
        10,
        "expected exactly one of `stop` | `resume` | `override`; found `at`, `stop`, `override`",
    ),
    "no kind": (["  - {at: 1}"], "events[0]", 10, "expected exactly one of `stop` | `resume` | `override`; found `at`"),
    "no time": (["  - {stop: true}"], "events[0]", 10, "missing required key `at`"),
    "not a list": ([" {at: 1, stop: true}"], "events", 9, "is not of type 'array'"),
    "an empty list": ([" []"], "events", 9, "expected at least 1 item(s), got 0"),
    "more events than the limit": (
        [f"  - {{at: {k}, override: 0.5}}" for k in range(input_budget.MAX_EVENTS + 1)],
        "events",
        9,
        f"{input_budget.MAX_EVENTS + 1} events, more than {input_budget.MAX_EVENTS}",
    ),
}


def bad_job(directory, lines):
    if lines[0].startswith(" ") and not lines[0].startswith("  -"):  # the value on the line of `events:`
        return job_with(directory, "events:" + lines[0])
    return job_with(directory, "events:", *lines)


@pytest.mark.parametrize("case", sorted(BAD_EVENTS))
def test_bad_events_are_refused_at_their_key_and_line(tmp_path, capsys, case):
    lines, key, line, reason = BAD_EVENTS[case]
    job_file = bad_job(tmp_path, lines)
    with pytest.raises(jobs.JobError) as info:
        jobs.load_job(job_file)
    message = str(info.value)
    assert message.startswith(f"{job_file}:{line}:") and f": {key}: " in message and reason in message, message
    assert info.value.line == line
    for command in (["check", str(job_file)], ["plan", str(job_file), "-o", str(tmp_path / "out")]):
        assert cli.main(command) == 1
        captured = capsys.readouterr()
        assert captured.err.startswith(f"dispkin {command[0]}: {job_file}:{line}:") and reason in captured.err
        assert not captured.out
    assert not (tmp_path / "out").exists()


# (events lines, key path, line, fragment): valid for `dispkin check`, refused by `dispkin plan`
# once the motion is planned.
BAD_WHEN_PLANNED = {
    "a stop after the motion has ended": (
        ["  - {at: 50, stop: true}"],
        "events[0].at",
        10,
        "50: the motion ends at t = 1.38066 s; a stop at or after its end changes nothing",
    ),
    "an override after the motion has ended": (
        ["  - {at: 0.5, override: 0.5}", "  - {at: 20, override: 1}"],
        "events[1].at",
        11,
        "20: the motion ends at t = 1.96132 s with the events before it; a speed override at or after its end",
    ),
    "a resume of a stop at the end of the path": (
        ["  - {at: 1.1, stop: true}", "  - {at: 2, resume: true}"],
        "events[1].resume",
        11,
        "true: nothing to resume: the stop of events[0] (t = 1.1 s) comes to rest at the end of the path",
    ),
    "a stop before the motion starts, never resumed": (
        ["  - {at: 0, stop: true}"],
        "events[0].at",
        10,
        "0: the stop comes before the motion starts and no resumption follows",
    ),
    "a resume a million seconds later": (
        ["  - {at: 0.5, stop: true}", "  - {at: 1.0e6, resume: true}"],
        "events[1].at",
        11,
        "with this event the motion lasts 1e+06 s, 1e+08 samples of 0.01 s (output.sample_period), more than 10000000",
    ),
}


@pytest.mark.parametrize("case", sorted(BAD_WHEN_PLANNED))
def test_events_that_find_nothing_to_act_on_are_refused_when_planned(tmp_path, capsys, case):
    lines, key, line, reason = BAD_WHEN_PLANNED[case]
    job_file = bad_job(tmp_path, lines)
    assert cli.main(["check", str(job_file)]) == 0
    capsys.readouterr()
    assert cli.main(["plan", str(job_file), "-o", str(tmp_path / "out")]) == 1
    captured = capsys.readouterr()
    assert captured.err.startswith(f"dispkin plan: {job_file}:{line}:") and f": {key}: " in captured.err, captured.err
    assert reason in captured.err, captured.err
    assert not captured.out and not (tmp_path / "out").exists()


def test_events_are_refused_where_the_trajectory_takes_none(tmp_path, capsys):
    """A job with PTP moves (planned part by part) and a re-timed job (its law keeps to joint
    limits): refused at `events`, by `dispkin check` too, saying why."""
    ptp = arm_job(
        ROOT / "examples" / "jobs" / "ur5e_ptp_and_lin.yaml",
        tmp_path,
        "events:",
        "  - {at: 0.5, stop: true}",
        name="ptp.yaml",
    )
    retimed = arm_job(
        ROOT / "examples" / "jobs" / "ur5e_lin_move.yaml",
        tmp_path,
        "retime: {method: optimal}",
        "events:",
        "  - {at: 0.5, override: 0.5}",
        name="retimed.yaml",
    )
    for job_file, reason in (
        (ptp, "moves[0] is a PTP move, so this job is planned part by part"),
        (retimed, "a re-timed trajectory (`retime`) keeps to the joint limits"),
    ):
        line = job_file.read_text().splitlines().index("events:") + 1
        assert cli.main(["check", str(job_file)]) == 1
        err = capsys.readouterr().err
        assert err.startswith(f"dispkin check: {job_file}:{line}:1: events: ") and reason in err, err


def test_a_bad_event_is_no_traceback_on_the_command_line(tmp_path):
    job_file = bad_job(tmp_path, BAD_EVENTS["two stops in a row"][0])
    result = subprocess.run(
        [sys.executable, "-m", "dispkin", "plan", str(job_file), "-o", str(tmp_path / "out")],
        capture_output=True,
        text=True,
        timeout=600,
    )
    assert result.returncode == 1 and "Traceback" not in result.stderr
    assert result.stderr.startswith(
        f"dispkin plan: {job_file}:11:13: events[1].stop: true: the motion is already stopped"
    )


def test_the_summary_lines_quoted_in_the_docs_are_the_code_s(tmp_path, capsys):
    """doc/job-output.md quotes the example's event lines and, for the example with its stop
    alone, the line of a motion that ends stopped: they are what `dispkin plan` prints."""
    doc = (ROOT / "doc" / "job-output.md").read_text(encoding="utf-8")
    section = doc.split("## Events in the summary", 1)[1].split("\n## ", 1)[0]
    blocks = [block.splitlines() for block in re.findall(r"```text\n(.*?)```", section, flags=re.S)]
    assert len(blocks) == 2
    assert cli.main(["plan", str(EXAMPLE), "-o", str(tmp_path / "all")]) == 0
    out = capsys.readouterr().out
    for line in blocks[0]:
        assert line.strip() == "..." or line in out.splitlines(), line
    stop_only = arm_job(EXAMPLE, tmp_path, name="stop_only.yaml")
    stop_only.write_text(
        "\n".join(
            line
            for line in stop_only.read_text().splitlines()
            if "resume: true" not in line and "override: 0.5" not in line
        )
        + "\n"
    )
    assert cli.main(["plan", str(stop_only), "-o", str(tmp_path / "stop")]) == 0
    out = capsys.readouterr().out
    assert blocks[1] == [out.splitlines()[2]]
