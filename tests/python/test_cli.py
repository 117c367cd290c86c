"""The command line: `dispkin demo` prints real figures computed with the API, `--help` works."""

import math
import re
import subprocess
import sys

import numpy as np
import pytest

import dispkin
from dispkin import cli


def figure(text, label):
    """The first number after `label` in the demo output."""
    match = re.search(re.escape(label) + r"[^0-9]*([0-9.]+)", text)
    assert match, label
    return float(match.group(1))


def test_demo_prints_the_figures_it_computes(capsys):
    assert cli.main(["demo", "--moves", "200", "--seed", "7", "--no-job"]) == 0
    out = capsys.readouterr().out
    tool = cli.demo_tool()
    a, b = cli.demo_move()
    chord = dispkin.disp_distance(tool, a, b)
    lin = dispkin.section_length(tool, a, b, interpolation="decoupled")
    screw = dispkin.section_length(tool, a, b, interpolation="screw")
    kdl = cli.kdl_path_length(a, b)
    assert figure(out, "chord distance (DISP)") == pytest.approx(chord, abs=5e-7)
    assert figure(out, "section length, LIN (exact)") == pytest.approx(lin, abs=5e-7)
    assert f"-> {lin / 0.1:.4f} s at 0.1 m/s" in out
    assert figure(out, "section length, screw (exact)") == pytest.approx(screw, abs=5e-7)
    assert f"moves at {lin / kdl:.3f}x the commanded 0.1 m/s" in out
    ratios = cli.sweep_ratios(200, 7)
    assert len(ratios) == 200
    assert f"move {ratios.mean():.3f}x the commanded speed on average and up to {ratios.max():.3f}x" in out
    assert "sweep: 200 random LIN moves (seed 7" in out
    lines = out.strip().splitlines()
    assert lines[-1].startswith("computed: ") and len(lines) <= 12
    # The figures make sense: chord <= exact length; the tip at 0.3 m turns faster than the
    # 0.1 m equivalent radius lets KDL assume, so KDL under-estimates the path.
    assert chord <= lin and chord <= screw and lin > kdl


def test_demo_plans_its_job_and_replans_the_edited_one(tmp_path, capsys):
    """`dispkin demo -o DIR` writes DIR/job.yaml from the built-in job, plans it with plots; after
    an edit of the job file the next run plans the edited job (the newcomer's loop of `make demo`)."""
    import yaml

    from dispkin import jobs

    outdir = tmp_path / "demo"
    assert cli.main(["demo", "--moves", "20", "-o", str(outdir)]) == 0
    out = capsys.readouterr().out
    job_file = outdir / "job.yaml"
    assert job_file.read_text() == cli.DEMO_JOB and f"wrote the demo job to {job_file}" in out
    for name in ("demo.csv", "demo.json", "demo_summary.txt", "demo.png"):
        assert (outdir / name).stat().st_size > 0
    assert f"Edit {job_file}" in out.strip().splitlines()[-1]
    first = jobs.plan_job(jobs.load_job(job_file)).duration
    assert f"duration {first:.4f} s" in out

    edited = yaml.safe_load(job_file.read_text())
    edited["limits"]["velocity"] = 0.005  # a quarter of the speed, below the legs' 0.01 m/s
    job_file.write_text(yaml.safe_dump(edited))
    assert cli.main(["demo", "--moves", "20", "-o", str(outdir)]) == 0
    out = capsys.readouterr().out
    assert "wrote the demo job" not in out  # the edited file is kept
    second = jobs.plan_job(jobs.load_job(job_file)).duration
    assert second > first * 1.3 and f"duration {second:.4f} s" in out


def test_demo_move_is_the_specified_one():
    a, b = cli.demo_move()
    assert a.is_approx(dispkin.Pose(), 0.0)
    np.testing.assert_allclose(b.to_xyzuvw(), [0.05, 0.02, 0.0, math.radians(10), 0.0, math.radians(30)], atol=1e-15)
    tool = cli.demo_tool()
    np.testing.assert_array_equal(tool.relative_points(0), [[0.0, 0.0, 0.3]])
    assert [(c.tolist(), r, absolute) for c, r, absolute in tool.spheres(0)] == [([0.0, 0.0, 0.0], 0.1, False)]


def test_kdl_path_length_is_max_of_translation_and_eqradius_angle():
    assert cli.kdl_path_length(dispkin.Pose(), dispkin.Pose(translation=(0.3, 0.4, 0.0))) == pytest.approx(
        0.5, rel=1e-15
    )
    turn = dispkin.Pose.exp([0.0, 0.0, 0.0, 0.0, 0.0, 1.2])
    assert cli.kdl_path_length(dispkin.Pose(), turn, eqradius=0.1) == pytest.approx(0.12, rel=1e-15)
    both = dispkin.Pose(quaternion=turn.quaternion, translation=(0.05, 0.0, 0.0))
    assert cli.kdl_path_length(dispkin.Pose(), both, eqradius=0.1) == pytest.approx(0.12, rel=1e-15)


def test_sweep_ratio_matches_the_closed_form_for_a_ball_at_the_tcp():
    # Ball of radius ρ = eqradius around the TCP, decoupled section with the TCP as pivot:
    # L = sqrt(Δp∥² + (|Δp⊥| + θρ)²) (doc/section-length.md eq. 8), so 1 <= L / max(|Δp|, ρθ) <= 2.
    moves = cli.random_lin_moves(500, 3)
    ratios = cli.sweep_ratios(500, 3)
    rho = cli.EQRADIUS
    for end, ratio in zip(moves, ratios):
        dp = end.translation
        w = end.log()[3:]  # start is the identity: body = world axis
        theta = np.linalg.norm(w)
        along = dp @ (w / theta)
        across = np.linalg.norm(dp - along * w / theta)
        expected = math.hypot(along, across + theta * rho) / max(np.linalg.norm(dp), rho * theta)
        assert ratio == pytest.approx(expected, rel=1e-12)
        assert 1.0 - 1e-12 <= ratio <= 2.0 + 1e-12
        assert np.linalg.norm(dp) <= cli.SWEEP_MAX_TRANSLATION and theta <= cli.SWEEP_MAX_ANGLE + 1e-15


def test_bad_arguments_exit_with_usage_errors(capsys):
    for argv in (["demo", "--moves", "0"], ["demo", "--moves", "x"], ["frobnicate"], []):
        with pytest.raises(SystemExit) as exit_info:
            cli.main(argv)
        assert exit_info.value.code == 2
    assert "usage: dispkin" in capsys.readouterr().err


def test_python_dash_m_dispkin_help():
    result = subprocess.run([sys.executable, "-m", "dispkin", "--help"], capture_output=True, text=True, timeout=60)
    assert result.returncode == 0
    assert "usage: dispkin" in result.stdout and "demo" in result.stdout
    result = subprocess.run(
        [sys.executable, "-m", "dispkin", "demo", "--help"], capture_output=True, text=True, timeout=60
    )
    assert result.returncode == 0 and "--moves" in result.stdout and "--seed" in result.stdout
    result = subprocess.run([sys.executable, "-m", "dispkin", "--version"], capture_output=True, text=True, timeout=60)
    assert result.returncode == 0 and result.stdout.strip() == f"dispkin {dispkin.__version__}"


def test_job_commands_document_every_option():
    for command, options in (("check", ["JOB.yaml"]), ("plan", ["JOB.yaml", "--outdir", "--plot", "OUTDIR"])):
        result = subprocess.run(
            [sys.executable, "-m", "dispkin", command, "--help"], capture_output=True, text=True, timeout=60
        )
        assert result.returncode == 0
        for option in options:
            assert option in result.stdout, (command, option)
    result = subprocess.run([sys.executable, "-m", "dispkin", "--help"], capture_output=True, text=True, timeout=60)
    assert "check" in result.stdout and "plan" in result.stdout


def test_plan_of_a_missing_job_file_fails_cleanly(capsys, tmp_path):
    assert cli.main(["plan", str(tmp_path / "nope.yaml")]) == 1
    err = capsys.readouterr().err
    assert err.startswith("dispkin plan: ") and "nope.yaml: cannot read the job file" in err
