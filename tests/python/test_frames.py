"""Work and tool frames from Python: commands converted to platform poses and back, XYZUVW
about the tool origin, generated metric sets against brute force over their points."""

import numpy as np
import pytest

import dispkin
from _helpers import rng_for


def random_pose(rng, scale):
    return dispkin.Pose.exp(np.concatenate([rng.uniform(-scale, scale, 3), rng.uniform(-1.0, 1.0, 3)]))


def test_command_round_trip_is_the_identity():
    rng = rng_for("frames round trip")
    for _ in range(200):
        frames = dispkin.WorkToolFrames(random_pose(rng, 0.5), random_pose(rng, 0.1))
        command = random_pose(rng, 0.3)
        assert frames.tool_in_work(frames.platform_pose(command)).is_approx(command, 1e-12)
        platform = random_pose(rng, 0.3)
        assert frames.platform_pose(frames.tool_in_work(platform.matrix())).is_approx(platform, 1e-12)
        # W X = T F
        w_x = frames.work.matrix() @ command.matrix()
        t_f = frames.platform_pose(command).matrix() @ frames.tool.matrix()
        np.testing.assert_allclose(w_x, t_f, rtol=0, atol=1e-12)


def test_xyzuvw_rotates_about_the_tool_origin():
    rng = rng_for("frames xyzuvw")
    frames = dispkin.WorkToolFrames(random_pose(rng, 0.5), random_pose(rng, 0.1))
    a = np.array([0.01, -0.02, 0.03, 0.1, -0.2, 0.3])
    b = a + [0, 0, 0, 0.2, 0.1, -0.1]
    pa, pb = frames.platform_pose_xyzuvw(a), frames.platform_pose_xyzuvw(b)
    np.testing.assert_allclose(pa.transform(frames.pivot), pb.transform(frames.pivot), rtol=0, atol=1e-12)
    np.testing.assert_allclose(frames.xyzuvw(pa), a, rtol=0, atol=1e-12)


def test_generated_set_fastest_point_is_brute_force_over_its_points():
    rng = rng_for("frames envelopes")
    for _ in range(100):
        frames = dispkin.WorkToolFrames(random_pose(rng, 0.5), random_pose(rng, 0.1))
        s = dispkin.MetricSet()
        frames.add_tool_envelope(s, 0.02)
        frames.add_work_envelope(s, 0.2, "icosahedron", group=1)
        # The points, independently: a circumscribed icosahedron placed with each frame.
        ico = dispkin.shapes.icosahedron(1.0)
        relative = ico * 0.02 @ frames.tool.rotation().T + frames.tool.translation
        absolute = ico * 0.2 @ frames.work.rotation().T + frames.work.translation
        pose = random_pose(rng, 0.5)
        twist = rng.uniform(-1, 1, 6)
        v, w = twist[:3], twist[3:]
        body_abs = (absolute - pose.translation) @ pose.rotation()
        expected = max(np.max(np.linalg.norm(v + np.cross(w, p), axis=1)) for p in (relative, body_abs))
        assert dispkin.max_point_speed(s, pose, twist) == pytest.approx(expected, rel=1e-12)


def test_sphere_envelopes_are_exact_spheres():
    frames = dispkin.WorkToolFrames(tool=dispkin.Pose.from_xyzuvw([0.01, 0, 0.05, 0, 0, 0]))
    s = dispkin.MetricSet()
    frames.add_tool_envelope(s, 0.03, "sphere")
    frames.add_work_envelope(s, 0.1, envelope="sphere", group=2)
    assert s.point_count == 0
    assert s.sphere_count == 2
    pose = dispkin.Pose.from_xyzuvw([0.1, 0.2, 0.3, 0.2, -0.1, 0.4])
    twist = np.array([0.1, -0.2, 0.05, 0.3, 0.2, -0.4])
    tool_only = dispkin.MetricSet()
    frames.add_tool_envelope(tool_only, 0.03, "sphere")
    expected = dispkin.sphere_speed(twist, frames.pivot, 0.03)
    assert dispkin.max_point_speed(tool_only, pose, twist) == pytest.approx(expected, rel=1e-15)


def test_bad_input():
    frames = dispkin.WorkToolFrames()
    s = dispkin.MetricSet()
    with pytest.raises(ValueError, match="radius = 0"):
        frames.add_tool_envelope(s, 0.0)
    with pytest.raises(ValueError, match='envelope = "cube"'):
        frames.add_work_envelope(s, 0.1, "cube")
    with pytest.raises(ValueError, match="group = -1"):
        frames.add_tool_envelope(s, 0.1, group=-1)
    with pytest.raises(ValueError, match="xyzuvw"):
        frames.platform_pose_xyzuvw([0, 0, 0, np.nan, 0, 0])
    with pytest.raises(ValueError, match="work"):
        dispkin.WorkToolFrames(work=np.zeros((3, 3)))
