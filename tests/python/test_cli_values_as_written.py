"""Job values refused at their keys as written: blends too small to build, angular limits in
degrees, a symmetric hexapod's parameters."""

import re

import pytest

from dispkin import jobs

from _cli_jobs import LIN, ROOT, example_job, plan


# --- values as written, at their keys ----------------------------------------------------------

BLENDED = """name: blended
metric_set:
  points:
    - {shape: icosahedron, radius: 0.02, center: [0, 0, 0]}
start: {xyzuvw: [0, 0, 0, 0, 0, 0]}
moves:
  - lin: {to: {xyzuvw: [0.3, 0, 0, 0, 0, 10]}}
  - lin: {to: {xyzuvw: [0.3, 0.2, 0, 0, 0, 40]}}
    BLEND
    orientation_blend: ORIENTATION
limits: {velocity: 0.25, acceleration: 1.0, jerk: 10.0}
"""


@pytest.mark.parametrize("orientation", ["nested_slerp", "rotation_vector"])
@pytest.mark.parametrize(
    "blend, reason",
    [
        (
            "blend_weight: 1e-300",
            "moves[1].blend_weight: 1e-300: must be at least 1e-05: a smaller share puts the blend's ends",
        ),
        ("blend_weight: 9e-6", "moves[1].blend_weight: 9e-06: must be at least 1e-05"),
        ("blend: 1e-300", "moves[1].blend: 1e-300: must be at least 1e-09 m, the smallest blend dispkin builds"),
    ],
)
def test_blends_too_small_to_build_are_refused_at_their_key(tmp_path, capsys, blend, reason, orientation):
    job_file = tmp_path / "blended.yaml"
    job_file.write_text(BLENDED.replace("BLEND", blend).replace("ORIENTATION", orientation))
    assert plan(job_file, tmp_path / "out") == 1
    assert capsys.readouterr().err.startswith(f"dispkin plan: {job_file}:9:5: {reason}")
    with pytest.raises(jobs.JobError) as info:
        jobs.load_job(job_file)
    assert str(info.value).startswith(f"{job_file}:9:5: {reason}")


@pytest.mark.parametrize("orientation", ["nested_slerp", "rotation_vector"])
def test_the_smallest_blend_weight_plans(tmp_path, capsys, orientation):
    job_file = tmp_path / "blended.yaml"
    job_file.write_text(BLENDED.replace("BLEND", "blend_weight: 1e-5").replace("ORIENTATION", orientation))
    assert plan(job_file, tmp_path / "out") == 0
    capsys.readouterr()


def test_a_planning_failure_names_the_blend_that_has_no_length(tmp_path):
    # A blend below the sizes the builder refuses cannot be written in a job any more; the
    # mapping from a section without length to its key is checked on the parts directly.
    job = jobs.load_job(ROOT / "examples" / "jobs" / "blended_tool_move.yaml")
    from dispkin.job import planning

    assert planning._failed_at(job, job.parts[0]) == (("moves", 0), None)  # every section has a length
    with pytest.raises(jobs.JobError) as info:
        planning._planned(
            job, job.parts[0], lambda: (_ for _ in ()).throw(ValueError("segments[0].length = 0: must be finite"))
        )
    assert re.match(
        rf"{re.escape(str(job.file))}:\d+:\d+: moves\[0\]: planning failed: segments\[0\]\.length = 0", str(info.value)
    )


@pytest.mark.parametrize(
    "limit, unit",
    [
        ("angular_velocity: 1e300", "deg/s"),
        ("angular_velocity: 1e-300", "deg/s"),
        ("angular_acceleration: 1e300", "deg/s²"),
    ],
)
def test_angular_limits_are_refused_in_degrees_at_their_key(tmp_path, limit, unit):
    key, value = limit.split(": ")
    job_file = example_job(LIN, tmp_path, f"limits: {{velocity: 0.25, acceleration: 1.0, jerk: 10.0, {limit}}}")
    with pytest.raises(jobs.JobError) as info:
        jobs.load_job(job_file)
    assert re.match(
        rf"{re.escape(str(job_file))}:\d+:\d+: limits\.{key}: {re.escape(repr(float(value)))}: "
        rf"must be in \[5\.72958e-11, 5\.72958e\+13\] {unit}$",
        str(info.value),
    ), str(info.value)


@pytest.mark.parametrize(
    "key, value, reason",
    [
        ("base_gap", "200", "200: must be in [0, 120) deg"),
        ("platform_gap", "-5", "-5: must be in [0, 120) deg"),
        ("leg_speed", "1e300", "1e+300: must be in [1e-12, 1e12]"),
    ],
)
def test_a_symmetric_hexapod_is_refused_at_the_key_as_written(tmp_path, key, value, reason):
    symmetric = {
        "base_radius": "0.15",
        "base_gap": "20",
        "platform_radius": "0.1",
        "platform_gap": "20",
        "height": "0.2",
        "leg_min": "0.15",
        "leg_max": "0.32",
        "leg_speed": "0.01",
        key: value,
    }
    job_file = tmp_path / "hexapod.yaml"
    job_file.write_text(
        "machine:\n  hexapod:\n    symmetric: {" + ", ".join(f"{k}: {v}" for k, v in symmetric.items()) + "}\n"
        "metric_set:\n  points:\n    - relative: [[0, 0, 0.3]]\n"
        "moves:\n  - lin: {to: {xyzuvw: [0.01, 0, 0.2, 0, 0, 0]}}\n"
        "limits: {velocity: 0.1, acceleration: 0.5, jerk: 5.0}\n"
    )
    with pytest.raises(jobs.JobError) as info:
        jobs.load_job(job_file)
    assert re.match(
        rf"{re.escape(str(job_file))}:3:\d+: machine\.hexapod\.symmetric\.{key}: {re.escape(reason)}", str(info.value)
    ), str(info.value)
