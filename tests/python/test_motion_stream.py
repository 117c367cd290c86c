"""MotionStream from Python (doc/events.md section 5): a control loop that appends moves as it
samples, stops, resumes and changes the override; what was sampled never changes, the motion
never stops while moves come in time, and no tool point exceeds its limit."""

import math

import numpy as np
import pytest

import dispkin

DEG = math.pi / 180


def pose(x, y, z, w=0.0):
    return dispkin.Pose.from_xyzuvw([x, y, z, 0.0, 0.0, w])


def tool():
    points = dispkin.shapes.icosphere(0.1, 2)
    tool = dispkin.MetricSet()
    tool.add_relative(points)
    return tool, points


def moves(count):
    poses = [pose(0.08 * k, 0.03 * (k % 2), 0.0, 4 * DEG * k) for k in range(count + 1)]
    return [dispkin.Path.lin(a, b) for a, b in zip(poses, poses[1:])]


def max_point_speed(stream, points, steps=20000):
    t = np.linspace(0.0, stream.duration, steps + 1)
    mats = stream.sample(t)
    world = np.einsum("nij,pj->npi", mats[:, :3, :3], points) + mats[:, None, :3, 3]
    return float(np.max(np.linalg.norm(np.diff(world, axis=0), axis=2)) / (t[1] - t[0]))


def test_a_loop_that_appends_in_time_never_stops_and_keeps_what_it_sampled():
    set_, points = tool()
    limits = dispkin.Limits(0.2, 1.0, 10.0)
    stream = dispkin.MotionStream(set_, limits, corner_tolerance=0.002)
    queue = moves(10)
    stream.append(queue.pop(0), 0.0)
    stream.append(queue.pop(0), 0.0)
    t, dt, sampled = 0.0, 1e-3, []
    # A 1 kHz loop: a new move whenever less than a second (about two moves) is planned ahead; a
    # move comes in time when it comes before the motion enters the last move appended.
    while not stream.done(t):
        if queue and stream.duration - t < 1.0:
            stream.append(queue.pop(0), t)
        sampled.append((t, stream.sample(t)))
        t += dt
    assert stream.leg_count == 1 and not queue
    assert stream.changed_from < stream.duration  # the last append took over while moving
    times = np.array([x[0] for x in sampled])
    assert np.array_equal(stream.sample(times), np.array([x[1] for x in sampled]))
    speeds = stream.path_velocity(times[(times > 0.05) & (times < stream.duration - 0.05)])
    assert np.min(speeds) > 0.0  # never at rest between moves
    assert max_point_speed(stream, points) <= 0.2 * (1 + 1e-6)


def test_stop_resume_override_and_a_late_move():
    set_, points = tool()
    stream = dispkin.MotionStream(set_, dispkin.Limits(0.2, 1.0, 10.0), corner_tolerance=0.002)
    queue = moves(4)
    stream.append(queue[0], 0.0)
    stream.append(queue[1], 0.0)
    t = 0.3
    before = stream.sample(np.linspace(0.0, t, 100, endpoint=False))
    stream.stop(t)
    assert stream.stopped
    assert np.array_equal(stream.sample(np.linspace(0.0, t, 100, endpoint=False)), before)
    stream.append(queue[2], t + 0.1)
    assert stream.waiting_moves == 1
    rest = stream.duration
    assert stream.path_velocity(rest + 0.2) == pytest.approx(0.0, abs=1e-12)
    stream.resume(rest + 0.5)
    stream.set_override(rest + 0.8, 0.5)
    assert stream.override_factor == 0.5
    late = stream.duration + 0.3
    stream.append(queue[3], late)
    assert stream.leg_count == 2
    assert np.allclose(stream.sample(stream.duration), queue[3].end.matrix(), atol=1e-9)
    assert max_point_speed(stream, points) <= 0.2 * (1 + 1e-6)


@pytest.mark.parametrize(
    "call, error, message",
    [
        (lambda s, p: s.stop(0.0), ValueError, "nothing was appended yet"),
        (lambda s, p: (s.append(p[0], 1.0), s.append(p[0], 2.0)), ValueError, "path.start"),
        (
            lambda s, p: (s.append(p[0], 1.0), s.append(p[1], 0.5)),
            ValueError,
            r"t = 0\.5: must be finite and not before the last request",
        ),
        (lambda s, p: (s.append(p[0], 1.0), s.resume(1.5)), ValueError, "resumes a stopped motion only"),
        (lambda s, p: s.set_override(0.0, 0.0), ValueError, r"factor = 0: must be in \[0\.001, 10\]"),
        (lambda s, p: s.append(p[0], math.nan), ValueError, "t = nan"),
    ],
)
def test_bad_requests_are_refused_naming_the_argument(call, error, message):
    stream = dispkin.MotionStream(tool()[0], dispkin.Limits(0.2, 1.0, 10.0))
    with pytest.raises(error, match=message):
        call(stream, moves(2))


def test_bad_construction():
    with pytest.raises(ValueError, match="corner_tolerance = -1"):
        dispkin.MotionStream(tool()[0], dispkin.Limits(0.2, 1.0, 10.0), corner_tolerance=-1.0)
    with pytest.raises(ValueError, match='profile = "sine"'):
        dispkin.MotionStream(tool()[0], dispkin.Limits(0.2, 1.0, 10.0), profile="sine")


def test_a_long_stream_forgets_what_it_ran_and_goes_on_the_same():
    set_, _ = tool()
    stream = dispkin.MotionStream(set_, dispkin.Limits(0.2, 1.0, 10.0), corner_tolerance=0.002)
    queue = moves(8)
    stream.append(queue.pop(0), 0.0)
    t = 0.0
    while queue:
        t = 0.5 * (t + stream.duration)
        stream.append(queue.pop(0), t)
    cut = 0.5 * stream.duration
    times = np.linspace(cut, stream.duration, 501)
    before = stream.sample(times)
    stream.forget_before(cut)
    assert np.array_equal(stream.sample(times), before)
    assert stream.leg_count == 1
