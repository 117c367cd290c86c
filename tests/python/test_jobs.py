"""Job files: valid ones round-trip through `dispkin plan` (CSV / JSON parse back and agree with
the Python API on the same job), invalid ones give errors that name the key and its line."""

import csv
import json
import math
import pathlib
import re

import numpy as np
import pytest

import dispkin
from dispkin import cli, jobs

ROOT = pathlib.Path(__file__).resolve().parents[2]
EXAMPLE_JOBS = sorted((ROOT / "examples" / "jobs").glob("*.yaml"))
BAD = ROOT / "tests" / "data" / "jobs"

# bad job -> (key path the message names, line of that key, a fragment of the reason)
BAD_JOBS = {
    "bad_yaml_syntax.yaml": ("(job)", 4, "not valid YAML"),
    "bad_unknown_key.yaml": ("limits.velocty", 11, "unknown key"),
    "bad_missing_limits.yaml": ("(job)", 1, "missing required key `limits`"),
    "bad_xyzuvw_length.yaml": ("moves[1].lin.to.xyzuvw", 8, "expected at least 6 item(s), got 5"),
    "bad_negative_velocity.yaml": ("limits.velocity", 8, "-0.1 is less than or equal to the minimum of 0"),
    "bad_nan_pose.yaml": ("moves[0].lin.to.xyzuvw[1]", 6, "nan: must be finite"),
    "bad_two_move_kinds.yaml": ("moves[0]", 6, "expected exactly one of `lin` | `circ` | `spline` | `ptp`"),
    "bad_ptp.yaml": ("moves[1].ptp", 7, "a PTP move moves joints: it needs machine.serial_arm"),
    "bad_ptp_joints_size.yaml": ("moves[0].ptp.joints", 11, "expected 6 joint values"),
    "bad_ptp_outside_limits.yaml": ("moves[0].ptp.joints[1]", 12, "outside the position limits"),
    "bad_ptp_blend.yaml": ("moves[1].blend", 13, "a PTP move starts and ends at rest"),
    "bad_ptp_hexapod.yaml": ("moves[0].ptp", 9, "PTP moves are planned for serial arms only"),
    "bad_ptp_unreachable.yaml": ("moves[0].ptp.to", 12, "cannot reach this pose"),
    "bad_ptp_joints_and_to.yaml": ("moves[0].ptp", 11, "expected exactly one of `joints` | `to`"),
    "bad_unknown_shape.yaml": ("metric_set.points[0].shape", 3, "'dodecahedron' is not one of"),
    "bad_shape_missing_radius.yaml": ("metric_set.points[0]", 3, "missing required key `radius`"),
    "bad_quaternion_not_unit.yaml": ("moves[0].lin.to.quaternion", 8, "must be a unit quaternion"),
    "bad_missing_urdf.yaml": ("machine.serial_arm.urdf", 3, "does not exist"),
    "bad_q_start_size.yaml": ("machine.serial_arm.q_start", 6, "expected 6 joint values"),
    "bad_scurve_without_jerk.yaml": ("limits", 7, "needs a jerk limit"),
    "bad_blend_first_move.yaml": ("moves[0].blend", 7, "no previous move"),
    "bad_blend_too_long.yaml": ("moves[1].blend", 8, "blend"),
    "bad_duplicate_key.yaml": ("limits", 8, "duplicate key"),
    "bad_no_start.yaml": ("(job)", 1, "missing required key `start`"),
    "bad_group_without_points.yaml": ("metric_set.groups[0].group", 5, "no points belong to this group"),
    "bad_degenerate_circ.yaml": ("moves[0].circ", 6, ""),
    "bad_hexapod_two_sources.yaml": (
        "machine.hexapod",
        2,
        "expected exactly one of `file` | `description` | `symmetric`",
    ),
    "bad_output_path.yaml": ("output.csv", 9, "a file name, not a path"),
    "bad_not_a_mapping.yaml": ("(job)", 1, "a job is a mapping"),
    "bad_center_and_centre.yaml": (
        "metric_set.points[1].centre",
        5,
        "`centre` is an alias of `center`: give one of them, not both",
    ),
    "bad_center_on_points.yaml": ("metric_set.points[0].center", 4, "a parameter of shapes only"),
    "bad_deep_nesting.yaml": ("(job)", 4, "mappings and lists nest deeper than 32 levels"),
    "bad_alias_bomb.yaml": ("(job)", 7, "the job expands to more than 500000 values"),
    "bad_recursive_alias.yaml": ("(job)", 3, "the alias *loop is inside its own anchor"),
    "bad_huge_integer.yaml": ("limits.jerk", 8, "an integer of 97 bits: numbers must be within ±2^53"),
    "bad_long_integer.yaml": ("(job)", 8, "a value of 5000 characters, more than 4096"),
    "bad_tiny_sample_period.yaml": ("output.sample_period", 9, "1e-09: must be at least 1e-06 s"),
}


def test_the_corpus_is_complete():
    assert sorted(p.name for p in BAD.glob("bad_*.yaml")) == sorted(BAD_JOBS)


@pytest.mark.parametrize("name", sorted(BAD_JOBS))
def test_bad_job_gives_a_pointed_error(name):
    key_path, line, reason = BAD_JOBS[name]
    with pytest.raises(jobs.JobError) as info:
        jobs.load_job(BAD / name)
    first = str(info.value).splitlines()[0]
    assert first.startswith(f"{BAD / name}:{line}:"), first
    assert f": {key_path}: " in first or (key_path == "(job)" and "not valid YAML" in first), first
    assert reason in first, first
    assert info.value.line == line
    assert isinstance(info.value, ValueError)


@pytest.mark.parametrize("name", sorted(BAD_JOBS))
def test_cli_check_rejects_bad_job(name, capsys):
    assert cli.main(["check", str(BAD / name)]) == 1
    captured = capsys.readouterr()
    assert captured.err.startswith(f"dispkin check: {BAD / name}:{BAD_JOBS[name][1]}:")
    assert not captured.out


def test_every_schema_violation_is_reported(tmp_path):
    job = tmp_path / "two.yaml"
    job.write_text((BAD / "bad_unknown_key.yaml").read_text().replace("acceleration: 1.0", "acceleration: 0"))
    with pytest.raises(jobs.JobError) as info:
        jobs.load_job(job)
    lines = str(info.value).splitlines()
    assert len(lines) == 2
    assert ":9:" in lines[0] and "limits.acceleration" in lines[0]
    assert ":11:" in lines[1] and "limits.velocty" in lines[1]


def test_schema_is_shipped_and_valid():
    import jsonschema

    schema = jobs.load_schema()
    jsonschema.Draft202012Validator.check_schema(schema)
    assert jobs.SCHEMA_PATH.parent == pathlib.Path(dispkin.__file__).parent
    assert "DEGREES" in schema["$defs"]["pose"]["description"]


def test_yaml_floats_with_exponent_are_numbers(tmp_path):
    job = tmp_path / "exp.yaml"
    job.write_text(
        (EXAMPLE_JOBS[0].parent / "blended_tool_move.yaml")
        .read_text()
        .replace("acceleration: 1.0", "acceleration: 1e0")
    )
    assert jobs.load_job(job).limits.acceleration == 1.0


def test_control_character_is_a_job_error(tmp_path):
    # Found by tests/fuzz/fuzz_jobs.py: PyYAML's reader refuses a control character when the
    # loader is made, which escaped as yaml.reader.ReaderError instead of a JobError.
    job = tmp_path / "ctrl.yaml"
    job.write_text("name: x\nlimits: {velocity: 0.1,\x1a acceleration: 1.0}\n")
    with pytest.raises(jobs.JobError) as info:
        jobs.load_job(job)
    assert str(info.value) == (f"{job}:2:24: not valid YAML: special characters are not allowed (character #x001a)")
    assert info.value.line == 2


def test_libyaml_reads_what_pyyaml_reads_with_the_same_places(monkeypatch):
    # Job files are parsed by libyaml's C parser (PyYAML's wheels carry it); the pure-Python
    # parser, kept for the messages of files that are no valid YAML, gives the same data and the
    # same line and column for every key of every example job.
    import yaml
    from dispkin.job import reader

    assert yaml.__with_libyaml__ and reader._FastLoader is not None and issubclass(reader._FastLoader, yaml.CSafeLoader)
    fast = [reader.Source(job) for job in EXAMPLE_JOBS]
    monkeypatch.setattr(reader, "_FastLoader", None)
    pure = [reader.Source(job) for job in EXAMPLE_JOBS]
    for a, b in zip(fast, pure):
        assert a.data == b.data and a.marks == b.marks, a.path


@pytest.mark.parametrize(
    "tagged, shown",
    [
        ("[1, !!int , 2]", ":17:24: not valid YAML: '' is no int"),  # IndexError in PyYAML's constructor
        ("!!float", ":17:20: not valid YAML: '' is no float"),
        ("!!bool maybe", ":17:20: not valid YAML: 'maybe' is no bool"),  # KeyError
        ("!!timestamp x", ":17:20: not valid YAML: 'x' is no timestamp"),  # AttributeError
    ],
)
def test_a_scalar_its_tag_cannot_make_is_a_job_error(tmp_path, tagged, shown):
    # Found by tests/fuzz/fuzz_jobs.py: `!!int` before a comma is an empty scalar, on which
    # PyYAML's int constructor raises IndexError (both parsers), which escaped load_job.
    job = tmp_path / "tagged.yaml"
    job.write_text(
        (EXAMPLE_JOBS[0].parent / "blended_tool_move.yaml")
        .read_text()
        .replace("velocity: 0.25", f"velocity: {tagged}", 1)
    )
    with pytest.raises(jobs.JobError) as info:
        jobs.load_job(job)
    assert shown in str(info.value), str(info.value)


def test_unknown_numeric_key_is_a_job_error(tmp_path):
    # Found by tests/fuzz/fuzz_jobs.py: unknown keys were sorted for the message, and a YAML key
    # that is a number cannot be compared with the names (TypeError).
    job = tmp_path / "number_key.yaml"
    job.write_text(
        (EXAMPLE_JOBS[0].parent / "blended_tool_move.yaml")
        .read_text()
        .replace("acceleration: 1.0", "acceleration: 1.0, 0: 1, zz: 2")
    )
    with pytest.raises(jobs.JobError) as info:
        jobs.load_job(job)
    assert (
        "limits.0: unknown key (allowed here: acceleration, angular_acceleration, angular_velocity, corner_tolerance, jerk, profile, velocity)"
        in str(info.value)
    )


# --- valid jobs ------------------------------------------------------------------------------


def read_csv(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    return rows[0], np.array(rows[1:], dtype=float)


@pytest.mark.parametrize("job_file", EXAMPLE_JOBS, ids=lambda p: p.name)
def test_example_job_round_trips_through_the_cli(job_file, tmp_path, capsys):
    assert cli.main(["check", str(job_file)]) == 0
    assert "valid job" in capsys.readouterr().out
    assert cli.main(["plan", str(job_file), "-o", str(tmp_path / "out"), "--plot"]) == 0
    printed = capsys.readouterr().out
    job = jobs.load_job(job_file)
    out = tmp_path / "out"
    header, table = read_csv(out / job.outputs["csv"])
    document = json.loads((out / job.outputs["json"]).read_text())
    # The same job through the Python API (part by part when it has PTP moves; with its events
    # applied when it has some, tests/python/test_job_events.py).
    if job.has_ptp or job.events:
        traj = jobs.plan_job(job)
    else:
        traj = dispkin.plan(
            job.path,
            job.metric_set,
            job.limits,
            job.profile,
            joint_metric=job.hexapod if job.joint_metric else None,
            corner_tolerance=job.corner_tolerance,
        )
    t = table[:, 0]
    assert t[0] == 0.0 and t[-1] == pytest.approx(traj.duration, rel=1e-15)
    np.testing.assert_allclose(np.diff(t)[:-1], job.sample_period, rtol=1e-9)
    assert document["dispkin"]["summary"]["duration"] == pytest.approx(traj.duration, rel=1e-15)
    assert f"duration {traj.duration:.4f} s" in printed
    # ROS JointTrajectory fields.
    assert document["joint_names"] == job.joint_names
    assert len(document["points"]) == len(t)
    for k in (0, len(t) // 2, len(t) - 1):
        point = document["points"][k]
        assert set(point) == {"positions", "velocities", "accelerations", "effort", "time_from_start"}
        stamp = point["time_from_start"]
        assert stamp["sec"] + stamp["nanosec"] * 1e-9 == pytest.approx(t[k], abs=1e-9)
        assert 0 <= stamp["nanosec"] < 1_000_000_000
    # Poses: the API's poses (tool in work with frames), XYZUVW in metres and degrees.
    poses = traj.sample(t)
    if job.frames is not None:
        expected = np.array([job.frames.xyzuvw(dispkin.Pose.from_matrix(m)) for m in poses])
    else:
        expected = np.array([dispkin.Pose.from_matrix(m).to_xyzuvw() for m in poses])
    expected[:, 3:] = np.degrees(expected[:, 3:])
    pose_columns = [header.index(c) for c in jobs.POSE_COLUMNS]
    np.testing.assert_allclose(table[:, pose_columns], expected, atol=1e-12)
    np.testing.assert_allclose(document["dispkin"]["poses_xyzuvw"], expected, atol=1e-12)
    # The fastest point never exceeds its group's limit, and the path velocity matches.
    twists = traj.body_twist(t)
    fastest = [
        dispkin.max_point_speed(job.metric_set, dispkin.Pose.from_matrix(m), xi, job.limits.velocity)
        for m, xi in zip(poses, twists)
    ]
    assert max(fastest) <= job.limits.velocity * (1 + 1e-6)
    np.testing.assert_allclose(table[:, header.index("path_velocity_mps")], traj.path_velocity(t), atol=1e-15)
    for group, g in document["dispkin"]["summary"]["groups"].items():
        assert g["peak_speed"] <= g["limit"] * (1 + 1e-6)
    # Joints: positions agree with the machine's own inverse kinematics.
    if job.hexapod is not None:
        legs = job.hexapod.inverse(poses)
        np.testing.assert_allclose(table[:, [header.index(f"{n}.position") for n in job.joint_names]], legs, atol=1e-15)
        np.testing.assert_allclose([p["positions"] for p in document["points"]], legs, atol=1e-15)
        assert document["dispkin"]["summary"]["legs"]["within_limits"]
    elif job.arm is not None:
        q = np.array([p["positions"] for p in document["points"]])
        for qk, m in zip(q, poses):
            np.testing.assert_allclose(job.arm.forward(qk).matrix(), m, atol=1e-9)
        np.testing.assert_allclose(q[0], job.q_start, atol=1e-9)
        np.testing.assert_allclose(table[:, [header.index(f"{n}.position") for n in job.joint_names]], q, atol=1e-15)
    else:
        assert document["joint_names"] == [] and document["points"][0]["positions"] == []
    png = out / (pathlib.Path(job.outputs["csv"]).stem + ".png")
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def finite_difference(values, t):
    return np.gradient(values, t, axis=0)


# A PTP move's q̈ = Δq ((du/ds) s̈ + m (du/ds) ṡ²) steps where the slope m of its rate changes, at
# the junctions of its joint sections (doc/ptp.md): there a central difference of the velocities
# averages the two sides, and one of the positions errs by up to dt/4 of the step. The velocity
# check allows that much; the acceleration check is made on the Cartesian moves.
@pytest.mark.parametrize("name", ["hexapod_scan.yaml", "ur5e_lin_move.yaml", "ur5e_ptp_and_lin.yaml"])
def test_joint_velocities_and_accelerations_are_the_derivatives(name):
    job = jobs.load_job(ROOT / "examples" / "jobs" / name)
    traj = jobs.plan_job(job)
    dt = 1e-3
    samples = jobs.sample_job(job, traj, period=dt)
    inner = slice(2, -2)
    steps = np.abs(np.diff(samples.accelerations, axis=0)).max() if job.has_ptp else 0.0
    np.testing.assert_allclose(
        samples.velocities[inner],
        finite_difference(samples.positions, samples.time)[inner],
        atol=1e-4 * np.abs(samples.velocities).max() + 0.25 * dt * steps,
    )
    check = np.zeros(len(samples.time), dtype=bool)
    check[inner] = True
    if job.has_ptp:
        which = traj.part_indices(samples.time)
        for k, (part, _) in enumerate(traj.parts):
            if part.kind == "ptp":
                check &= ~np.convolve(which == k, np.ones(5), mode="same").astype(bool)
        assert check.sum() > 100
    np.testing.assert_allclose(
        samples.accelerations[check],
        finite_difference(samples.velocities, samples.time)[check],
        atol=2e-2 * np.abs(samples.accelerations).max(),
    )


def test_ur_job_is_the_python_example_move():
    job = jobs.load_job(ROOT / "examples" / "jobs" / "ur5e_lin_move.yaml")
    arm = job.arm
    start = arm.forward(job.q_start)
    goal = (
        dispkin.Pose((1, 0, 0, 0), (0.2, 0.1, -0.1))
        * start
        * dispkin.Pose.from_xyzuvw([0, 0, 0, 0, 0, math.radians(30)])
    )
    assert job.path.start.is_approx(start, 1e-12) and job.path.end.is_approx(goal, 1e-12)
    samples = jobs.sample_job(job, jobs.plan_job(job))
    torques = [
        arm.torques(q, qd, qdd) for q, qd, qdd in zip(samples.positions, samples.velocities, samples.accelerations)
    ]
    np.testing.assert_allclose(samples.effort, torques, rtol=1e-12, atol=1e-12)


def test_hexapod_from_file_and_inline_description_match_symmetric(tmp_path):
    scan = (ROOT / "examples" / "jobs" / "hexapod_scan.yaml").read_text()
    reference = jobs.load_job(ROOT / "examples" / "jobs" / "hexapod_scan.yaml")
    reference.hexapod.save(str(tmp_path / "hexapod.json"))
    symmetric = re.search(r"    symmetric:.*?leg_speed: 0.01}\n", scan, flags=re.S).group(0)
    (tmp_path / "from_file.yaml").write_text(scan.replace(symmetric, "    file: hexapod.json\n"))
    description = json.loads(reference.hexapod.to_json())
    (tmp_path / "inline.yaml").write_text(scan.replace(symmetric, f"    description: {json.dumps(description)}\n"))
    expected = jobs.plan_job(reference).duration
    for name in ("from_file.yaml", "inline.yaml"):
        job = jobs.load_job(tmp_path / name)
        np.testing.assert_array_equal(job.hexapod.base_joints, reference.hexapod.base_joints)
        assert jobs.plan_job(job).duration == pytest.approx(expected, rel=1e-15)


def test_blend_removes_the_stops_and_matches_the_api():
    job = jobs.load_job(ROOT / "examples" / "jobs" / "blended_tool_move.yaml")

    def pose(x, y, yaw):
        return dispkin.Pose.from_xyzuvw([x, y, 0, 0, 0, math.radians(yaw)])

    path = dispkin.Path.lin(pose(0, 0, 0), pose(0.3, 0, 10))
    path.then(dispkin.Path.circ(pose(0.3, 0, 10), pose(0.45, 0.1, 20), pose(0.3, 0.2, 30)), blend=0.03)
    path.then(dispkin.Path.lin(pose(0.3, 0.2, 30), pose(0, 0.2, 40)), blend=0.03)
    api = dispkin.plan(path, job.metric_set, job.limits)
    traj = jobs.plan_job(job)
    assert traj.piece_count == 1 and [m.kind for m in job.moves] == ["lin", "circ", "lin"]
    assert traj.duration == pytest.approx(api.duration, rel=1e-12)


NESTED_SLERP_JOB = """
name: nested_slerp
metric_set:
  points:
    - {shape: icosahedron, radius: 0.02, center: [0, 0, 0.2]}
start: {xyzuvw: [0, 0, 0, 0, 0, 0]}
moves:
  - lin: {to: {xyzuvw: [0.3, 0, 0, 0, 0, 20]}}
  - lin: {to: {xyzuvw: [0.3, 0.25, 0, 10, 0, 60]}}
    BLEND
limits: {velocity: 0.25, acceleration: 1.0, jerk: 10.0}
"""


def test_blend_weight_and_nested_slerp_match_the_api(tmp_path):
    """`blend_weight` and `orientation_blend` of a move are Path.then's weight and orientation_blend."""

    def pose(x, y, u, w):
        return dispkin.Pose.from_xyzuvw([x, y, 0, math.radians(u), 0, math.radians(w)])

    for keys, kwargs in (
        ("blend_weight: 0.3", {"weight": 0.3}),
        (
            "blend_weight: 0.3\n    orientation_blend: nested_slerp",
            {"weight": 0.3, "orientation_blend": "nested_slerp"},
        ),
        ("blend: 0.05\n    orientation_blend: nested_slerp", {"blend": 0.05, "orientation_blend": "nested_slerp"}),
    ):
        (tmp_path / "job.yaml").write_text(NESTED_SLERP_JOB.replace("BLEND", keys))
        job = jobs.load_job(tmp_path / "job.yaml")
        path = dispkin.Path.lin(pose(0, 0, 0, 0), pose(0.3, 0, 0, 20))
        path.then(dispkin.Path.lin(pose(0.3, 0, 0, 20), pose(0.3, 0.25, 10, 60)), **kwargs)
        api = dispkin.plan(path, job.metric_set, job.limits)
        traj = jobs.plan_job(job)
        assert traj.piece_count == 1 and traj.stops == [], keys  # one run through the blend
        assert traj.duration == pytest.approx(api.duration, rel=1e-12), keys
        assert ("nested SLERP" in job.moves[1].blend_text()) == ("nested_slerp" in keys)


@pytest.mark.parametrize(
    "keys, key, message",
    [
        ("blend: 0.05\n    blend_weight: 0.3", "moves[1].blend_weight", "not both"),
        ("orientation_blend: nested_slerp", "moves[1].orientation_blend", "no blend to shape"),
        ("blend_weight: 0.7", "moves[1].blend_weight", "0.7"),
        ("blend_weight: 0.3\n    orientation_blend: slerpy", "moves[1].orientation_blend", "slerpy"),
    ],
)
def test_blend_weight_and_orientation_blend_errors_name_the_key(tmp_path, keys, key, message):
    (tmp_path / "job.yaml").write_text(NESTED_SLERP_JOB.replace("BLEND", keys))
    with pytest.raises(jobs.JobError) as error:
        jobs.plan_job(jobs.load_job(tmp_path / "job.yaml"))
    assert key in str(error.value) and message in str(error.value)


def test_center_is_the_spelling_and_centre_its_alias(tmp_path):
    """Job files spell `center` as the API does; `centre` (earlier job files) builds the same job."""
    for example in ("blended_tool_move.yaml", "ur5e_lin_move.yaml"):
        text = (ROOT / "examples" / "jobs" / example).read_text()
        assert "center: [" in text and "centre" not in text
        text = text.replace("urdf: ../../tests/", f"urdf: {ROOT}/tests/")  # the copy is elsewhere
        (tmp_path / example).write_text(text.replace("center: [", "centre: ["))
        center, centre = jobs.load_job(ROOT / "examples" / "jobs" / example), jobs.load_job(tmp_path / example)
        assert center.metric_set.groups == centre.metric_set.groups
        for group in center.metric_set.groups:
            np.testing.assert_array_equal(
                center.metric_set.relative_points(group), centre.metric_set.relative_points(group)
            )
            assert [(c.tolist(), r, a) for c, r, a in center.metric_set.spheres(group)] == [
                (c.tolist(), r, a) for c, r, a in centre.metric_set.spheres(group)
            ]
        assert jobs.plan_job(center).duration == jobs.plan_job(centre).duration
    # The centre is used, whichever the spelling: a tool tip 0.2 m off the flange is slower to turn.
    job = (ROOT / "examples" / "jobs" / "blended_tool_move.yaml").read_text()
    for key in ("center", "centre"):
        (tmp_path / f"{key}.yaml").write_text(job.replace("center: [0, 0, 0.2]", f"{key}: [0, 0, 0.5]"))
        assert (
            jobs.plan_job(jobs.load_job(tmp_path / f"{key}.yaml")).duration
            > jobs.plan_job(jobs.load_job(ROOT / "examples" / "jobs" / "blended_tool_move.yaml")).duration
        )


def test_time_from_start_carries_nanoseconds():
    assert jobs.time_from_start(1.9999999999) == {"sec": 2, "nanosec": 0}
    assert jobs.time_from_start(0.25) == {"sec": 0, "nanosec": 250_000_000}


def test_sample_times_end_exactly_at_the_duration():
    np.testing.assert_allclose(jobs.sample_times(1.0, 0.25), [0, 0.25, 0.5, 0.75, 1.0])
    assert jobs.sample_times(1.1, 0.25)[-1] == 1.1 and len(jobs.sample_times(1.1, 0.25)) == 6


def test_user_guide_minimal_job_runs_as_documented(tmp_path, capsys, monkeypatch):
    readme = (ROOT / "doc" / "user-guide.md").read_text(encoding="utf-8")
    block = re.search(r"```yaml\n(.*?)```", readme, flags=re.S).group(1)
    (tmp_path / "lin.yaml").write_text(block)
    monkeypatch.chdir(tmp_path)
    assert cli.main(["check", "lin.yaml"]) == 0
    assert cli.main(["plan", "lin.yaml", "-o", "out", "--plot"]) == 0
    for name in ("lin.csv", "lin.json", "lin.summary.txt", "lin.png"):
        assert (tmp_path / "out" / name).stat().st_size > 0
    # The error quoted in the user guide is the one the code gives.
    quoted = re.search(
        r"`lin\.yaml:11:3: (limits\.velocty: unknown key \(allowed here: [^)]*\))`", readme.replace("\n", " ")
    )
    with pytest.raises(jobs.JobError) as info:
        jobs.load_job(BAD / "bad_unknown_key.yaml")
    assert str(info.value).endswith(":11:3: " + quoted.group(1))


# --- PTP moves ---------------------------------------------------------------------------------


def test_ptp_job_mixes_joint_and_cartesian_moves():
    job = jobs.load_job(ROOT / "examples" / "jobs" / "ur5e_ptp_and_lin.yaml")
    assert job.has_ptp and job.path is None
    assert [m.kind for m in job.moves] == ["ptp", "lin", "ptp"]
    assert [p.kind for p in job.parts] == ["ptp", "path", "ptp"]
    arm = job.arm
    first, run, last = job.parts
    # The first PTP move starts at q_start and ends at the given joints; the LIN starts at its end pose.
    np.testing.assert_array_equal(first.path.start, job.q_start)
    np.testing.assert_array_equal(first.path.end, job.moves[0].path.end)
    assert run.path.start.is_approx(arm.forward(first.path.end), 1e-12)
    np.testing.assert_array_equal(run.q_start, first.path.end)
    # The last PTP move goes to the pose given, on the IK branch nearest to the joints where it starts.
    target = dispkin.Pose.from_xyzuvw(_xyzuvw_radians(job, 2))
    assert arm.forward(last.path.end).is_approx(target, 1e-9)
    solutions = arm.inverse(target, offer_equivalents=True)  # the branch may continue into a 2π copy
    np.testing.assert_allclose(last.path.end, dispkin.SerialArm.nearest(solutions, last.path.start), atol=1e-12)
    assert arm.forward(last.path.start).is_approx(run.path.end, 1e-9)
    traj = jobs.plan_job(job)
    assert isinstance(traj, jobs.JobTrajectory)
    assert traj.duration == pytest.approx(sum(t.duration for _, t in traj.parts), rel=1e-15)
    samples = jobs.sample_job(job, traj, period=2e-3)
    # Joints continuous through the junctions (at rest there), poses the arm's forward kinematics.
    steps = np.abs(np.diff(samples.positions, axis=0)).max(axis=0)
    assert np.all(steps <= 2e-3 * arm.joint_limits.velocity * 1.001)
    for k in range(0, len(samples.time), 50):
        pose = arm.forward(samples.positions[k])
        expected = pose.to_xyzuvw()
        expected[3:] = np.degrees(expected[3:])
        np.testing.assert_allclose(samples.xyzuvw[k], expected, atol=1e-9)
    # No point faster than its limit; the joint velocities within the URDF's.
    assert samples.fastest_point_speed.max() <= job.limits.velocity * (1 + 1e-6)
    assert np.all(np.abs(samples.velocities) <= arm.joint_limits.velocity * (1 + 1e-6))
    summary = jobs.summarize(job, traj, samples)
    assert summary["moves"] == ["ptp", "lin", "ptp"] and summary["joints"]["within_limits"]
    assert summary["rest_to_rest_pieces"] == 3


def _xyzuvw_radians(job, move):
    """The `to` pose of a job's ptp move as XYZUVW in metres and radians."""
    import yaml

    data = yaml.safe_load(job.file.read_text())
    x = np.asarray(data["moves"][move]["ptp"]["to"]["xyzuvw"], dtype=float)
    return np.concatenate([x[:3], np.radians(x[3:])])


def test_ptp_job_csv_and_json_carry_the_joint_line(tmp_path, capsys):
    job_file = ROOT / "examples" / "jobs" / "ur5e_ptp_and_lin.yaml"
    assert cli.main(["plan", str(job_file), "-o", str(tmp_path)]) == 0
    capsys.readouterr()
    job = jobs.load_job(job_file)
    header, table = read_csv(tmp_path / job.outputs["csv"])
    document = json.loads((tmp_path / job.outputs["json"]).read_text())
    traj = jobs.plan_job(job)
    ptp_part, ptp_traj = traj.parts[0]
    t = table[:, 0]
    inside = t < traj.start_times[1]
    q = table[:, [header.index(f"{n}.position") for n in job.joint_names]]
    qd = table[:, [header.index(f"{n}.velocity") for n in job.joint_names]]
    np.testing.assert_allclose(q[inside], ptp_traj.joint_positions(t[inside]), atol=1e-15)
    np.testing.assert_allclose(qd[inside], ptp_traj.joint_velocities(t[inside]), atol=1e-15)
    np.testing.assert_allclose([p["positions"] for p in document["points"]], q, atol=1e-15)
    np.testing.assert_allclose(q[-1], traj.parts[-1][0].path.end, atol=1e-15)


def test_ptp_move_to_a_pose_in_the_work_frame(tmp_path):
    text = (ROOT / "examples" / "jobs" / "ur5e_ptp_and_lin.yaml").read_text()
    job_file = tmp_path / "job.yaml"
    job_file.write_text(
        text.replace("urdf: ../../tests/data/urdf/", f"urdf: {ROOT / 'tests' / 'data' / 'urdf'}/").replace(
            "metric_set:", "frames:\n  work: {xyzuvw: [0.1, 0, 0, 0, 0, 0]}\nmetric_set:", 1
        )
    )
    job = jobs.load_job(job_file)
    target = job.frames.platform_pose(dispkin.Pose.from_xyzuvw(_xyzuvw_radians(job, 2)))
    assert job.arm.forward(job.parts[-1].path.end).is_approx(target, 1e-9)
