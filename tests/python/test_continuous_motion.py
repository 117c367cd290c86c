"""Continuous motion from Python and job files: corner blending within a tolerance
(plan(..., corner_tolerance=d), limits.corner_tolerance), Trajectory.stops, per-move limits
(Path.lin(..., velocity=, acceleration=), moves[].velocity) and the rotational limit
(Limits(angular_velocity=...), limits.angular_velocity in deg/s). doc/planning.md §9-§11."""

import math
import pathlib

import numpy as np
import pytest

import dispkin
from dispkin import jobs
from dispkin.shapes import icosahedron


def tool_set(radius=0.05):
    s = dispkin.MetricSet()
    s.add_relative(icosahedron(radius))
    return s


def pose_at(x, y, z, angle=0.0):
    return dispkin.Pose.from_xyzuvw([x, y, z, 0.0, 0.0, angle])


def lins(poses, **move):
    path = dispkin.Path.lin(poses[0], poses[1], **move)
    for a, b in zip(poses[1:], poses[2:]):
        path.then(dispkin.Path.lin(a, b, **move))
    return path


def fastest_speeds(traj, points, steps=4000):
    """Speed of the fastest point by chords of the planned motion, with the path position."""
    t = np.linspace(0.0, traj.duration, steps + 1)
    poses = traj.sample(t)
    world = np.einsum("nij,pj->npi", poses[:, :3, :3], points) + poses[:, None, :3, 3]
    speeds = np.linalg.norm(np.diff(world, axis=0), axis=2).max(axis=1) / np.diff(t)
    return speeds, traj.path_position(t[:-1])


def zigzag(count=50, step=0.05):
    return [pose_at(step * k, 0.02 * (k % 2), 0.0, 3.0 * (k % 3)) for k in range(count)]


def test_corner_tolerance_turns_a_pose_list_into_one_run():
    poses = zigzag()
    limits = dispkin.Limits(0.2, 2.0, 20.0)
    stopping = dispkin.plan(lins(poses), tool_set(), limits)
    assert len(stopping.stops) == len(poses) - 2
    assert all("corner_tolerance = 0" in reason for _, reason in stopping.stops)
    traj = dispkin.plan(lins(poses), tool_set(), limits, corner_tolerance=0.005)
    assert traj.stops == [] and traj.piece_count == 1
    assert traj.duration < 0.85 * stopping.duration
    np.testing.assert_allclose(traj.sample(traj.duration), poses[-1].matrix(), atol=1e-9)
    speeds, _ = fastest_speeds(traj, icosahedron(0.05))
    assert speeds.max() <= 0.2 * (1 + 1e-6)


def test_reversal_stops_and_says_why():
    a, b, c = pose_at(0, 0, 0), pose_at(0.3, 0, 0), pose_at(0.1, 0, 0)
    traj = dispkin.plan(lins([a, b, c]), tool_set(), dispkin.Limits(0.1, 1.0, 10.0), corner_tolerance=0.01)
    assert len(traj.stops) == 1
    s, reason = traj.stops[0]
    assert s == pytest.approx(traj.rest_positions()[1]) and "reverses" in reason


def test_blended_path_reports_its_corners():
    a, b, c = pose_at(0, 0, 0), pose_at(0.3, 0, 0), pose_at(0.3, 0.3, 0)
    blended, corners = lins([a, b, c]).blended(0.01)
    assert corners == [] and len(blended.sections()) > 2
    assert blended.move_starts[0] == 0 and len(blended.move_starts) == 2


def test_per_move_speed_holds_and_binds():
    poses = [pose_at(0.3 * k, 0, 0) for k in range(4)]
    path = dispkin.Path.lin(poses[0], poses[1])
    path.then(dispkin.Path.lin(poses[1], poses[2], velocity=0.05, acceleration=0.5))
    path.then(dispkin.Path.lin(poses[2], poses[3]))
    traj = dispkin.plan(path, tool_set(), dispkin.Limits(0.2, 1.0, 10.0))
    assert traj.piece_count == 1
    speeds, s = fastest_speeds(traj, icosahedron(0.05), 20000)
    slow = (s > 0.3 + 1e-3) & (s < 0.6 - 1e-3)
    assert speeds[slow].max() <= 0.05 * (1 + 1e-6)
    assert speeds[slow].max() >= 0.995 * 0.05
    assert speeds[~slow].max() >= 0.995 * 0.2


def test_angular_limit_holds_and_binds():
    a = pose_at(0, 0, 0)
    b = dispkin.Pose.from_xyzuvw([0.05, 0, 0, 0, 0, 120])
    limits = dispkin.Limits(0.2, 5.0, angular_velocity=0.5, angular_acceleration=4.0)
    assert limits.angular_velocity == 0.5 and "angular_velocity=0.5" in repr(limits)
    traj = dispkin.plan(dispkin.Path.lin(a, b), tool_set(0.01), limits, "trapezoid")
    t = np.linspace(0.0, traj.duration, 20001)
    twist = traj.body_twist(t)
    omega = np.linalg.norm(twist[:, 3:], axis=1)
    assert omega.max() <= 0.5 * (1 + 1e-9)
    assert omega.max() >= 0.5 * (1 - 1e-9)


@pytest.mark.parametrize("bad", [-1.0, float("nan"), float("inf")])
def test_bad_corner_tolerance_is_named(bad):
    with pytest.raises(ValueError, match="corner_tolerance"):
        dispkin.plan(
            lins([pose_at(0, 0, 0), pose_at(0.1, 0, 0)]),
            tool_set(),
            dispkin.Limits(0.1, 1.0, 10.0),
            corner_tolerance=bad,
        )


@pytest.mark.parametrize("key", ["velocity", "acceleration"])
@pytest.mark.parametrize("bad", [0.0, -0.5, float("nan")])
def test_bad_move_limits_are_named(key, bad):
    with pytest.raises(ValueError, match=key):
        dispkin.Path.lin(pose_at(0, 0, 0), pose_at(0.1, 0, 0), **{key: bad})


@pytest.mark.parametrize("key", ["angular_velocity", "angular_acceleration"])
def test_bad_angular_limits_are_named(key):
    with pytest.raises(ValueError, match=key):
        dispkin.Limits(0.1, 1.0, **{key: -1.0})


def write_pose_list_job(path, count=50, extra_limits="", move_extra=""):
    moves = "\n".join(
        f"  - lin: {{to: {{xyzuvw: [{0.05 * k:.3f}, {0.02 * (k % 2):.3f}, 0, 0, 0, {3.0 * (k % 3):.1f}]}}}}{move_extra}"
        for k in range(1, count)
    )
    path.write_text(f"""name: pose_list
metric_set:
  points:
    - shape: icosahedron
      radius: 0.05
start: {{xyzuvw: [0, 0, 0, 0, 0, 0]}}
moves:
{moves}
limits:
  velocity: 0.2
  acceleration: 2.0
  jerk: 20.0
{extra_limits}""")
    return path


def test_job_with_corner_tolerance_plans_one_continuous_move(tmp_path):
    job = jobs.load_job(write_pose_list_job(tmp_path / "list.yaml", extra_limits="  corner_tolerance: 0.005\n"))
    traj = jobs.plan_job(job)
    assert traj.stops == [] and traj.piece_count == 1
    stopping = jobs.plan_job(jobs.load_job(write_pose_list_job(tmp_path / "stops.yaml")))
    assert len(stopping.stops) == 48


def test_job_angular_limit_is_in_degrees(tmp_path):
    job = jobs.load_job(write_pose_list_job(tmp_path / "ang.yaml", 3, "  angular_velocity: 30\n"))
    assert job.limits.angular_velocity == pytest.approx(math.radians(30))


def test_job_move_velocity(tmp_path):
    job = jobs.load_job(write_pose_list_job(tmp_path / "v.yaml", 4, move_extra="\n    velocity: 0.05"))
    traj = jobs.plan_job(job)
    speeds, _ = fastest_speeds(traj, icosahedron(0.05))
    assert speeds.max() <= 0.05 * (1 + 1e-6)


def test_job_bad_corner_tolerance_names_the_key(tmp_path):
    with pytest.raises(jobs.JobError, match=r"limits\.corner_tolerance"):
        jobs.load_job(write_pose_list_job(tmp_path / "bad.yaml", 3, "  corner_tolerance: -1\n"))


def test_the_pose_list_example_is_one_continuous_run():
    example = pathlib.Path(__file__).resolve().parents[2] / "examples" / "jobs" / "pose_list_continuous.yaml"
    job = jobs.load_job(example)
    assert len(job.moves) == 49 and job.corner_tolerance == 0.001
    traj = jobs.plan_job(job)
    assert traj.stops == [] and traj.piece_count == 1
    # It reaches the speed limit: the fastest point runs at v somewhere.
    speeds, _ = fastest_speeds(traj, np.vstack([icosahedron(0.02), icosahedron(0.02) + [0, 0, 0.2]]))
    assert 0.995 * 0.1 <= speeds.max() <= 0.1 * (1 + 1e-6)
