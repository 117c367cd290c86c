"""Paths from Python: LIN / CIRC / PTP, sections, sampling, lengths against the sampled motion, errors."""

import math

import numpy as np
import pytest

import dispkin

DEG = math.pi / 180


def pose(x, y, z, u=0.0, v=0.0, w=0.0):
    return dispkin.Pose.from_xyzuvw([x, y, z, u, v, w])


def speeds_along(section, points, n=2001, h=1e-6):
    """Largest speed per unit tau of relative points along a section, by central differences."""
    best = 0.0
    for tau in np.linspace(0.0, 1.0, n):
        p, m = section.pose(tau + h), section.pose(tau - h)
        best = max(best, float(np.max(np.linalg.norm(p.transform(points) - m.transform(points), axis=1))) / (2 * h))
    return best


def test_lin_ends_sections_and_lengths():
    a, b = pose(0, 0, 0), pose(0.2, 0.1, 0, 10 * DEG, 0, 40 * DEG)
    path = dispkin.Path.lin(a, b)
    assert len(path) == 1 and path.sections()[0].kind == "lin"
    assert path.start.is_approx(a, 1e-12) and path.end.is_approx(b, 1e-12)
    tool = dispkin.MetricSet()
    tool.add_relative(dispkin.shapes.icosahedron(0.1))
    lengths = path.section_lengths(tool)
    assert lengths.shape == (1,)
    assert lengths[0] == pytest.approx(dispkin.section_length(tool, a, b, "decoupled"), rel=1e-15)
    sampled = speeds_along(path.sections()[0], dispkin.shapes.icosahedron(0.1), n=401)
    assert sampled <= lengths[0] * (1 + 1e-9)
    assert sampled >= lengths[0] * (1 - 1e-5)


def test_circ_follows_the_circle_and_its_sections_bound_the_speed():
    a = pose(0.3, 0.0, 0.1)
    via = pose(0.0, 0.3, 0.1, 0, 0, 20 * DEG)
    b = pose(-0.3, 0.0, 0.1, 0, 0, 60 * DEG)  # half a turn of the pivot
    path = dispkin.Path.circ(a, via, b)
    assert len(path) >= math.pi / 1e-3
    assert path.end.is_approx(b, 1e-12)
    mats = path.sample(np.linspace(0, 1, 101))
    assert mats.shape == (101, 4, 4)
    radii = np.linalg.norm(mats[:, :2, 3], axis=1)
    np.testing.assert_allclose(radii, 0.3, atol=1e-12)
    np.testing.assert_allclose(mats[:, 2, 3], 0.1, atol=1e-12)
    tool = dispkin.MetricSet()
    points = np.array([[0, 0, 0], [0.05, 0, 0], [0, 0.05, 0], [0, 0, 0.05]], dtype=float)
    tool.add_relative(points)
    lengths = path.section_lengths(tool)
    sections = path.sections()
    for k in (0, len(sections) // 2, len(sections) - 1):
        sampled = speeds_along(sections[k], points, n=201)
        assert lengths[k] >= sampled * (1 - 1e-7)
        assert lengths[k] <= sampled * (1 + 1e-3)
        assert sections[k].length(tool) == lengths[k]


def test_chained_path_and_sampling():
    a, b, c = pose(0, 0, 0), pose(0.2, 0, 0), pose(0.2, 0.1, 0)
    path = dispkin.Path.lin(a, b).then(dispkin.Path.lin(b, c))
    assert len(path) == 2
    # sizes 0.2 m and 0.1 m: u = 0.5 is 0.15 m along the first segment
    assert path.sample(0.5).is_approx(pose(0.15, 0, 0), 1e-14)
    assert path.sample(1.0).is_approx(c, 1e-14)


def test_ptp_is_a_joint_line():
    ptp = dispkin.Path.ptp([0.0, 1.0, 2.0], [1.0, 1.0, 0.0])
    assert isinstance(ptp, dispkin.JointPath)
    np.testing.assert_allclose(ptp.sample(0.5), [0.5, 1.0, 1.0])
    np.testing.assert_allclose(ptp.sample(3.0), [1.0, 1.0, 0.0])


@pytest.mark.parametrize(
    "build, message",
    [
        (lambda: dispkin.Path.circ(pose(0, 0, 0), pose(0.5, 0, 0), pose(1, 0, 0)), r"^via = .*collinear"),
        (lambda: dispkin.Path.circ(pose(0, 0, 0), pose(0, 0, 0), pose(1, 0, 0)), r"^via = .*coincides"),
        (lambda: dispkin.Path.circ(pose(0, 0, 0), pose(0, 1, 0), pose(1, 0, 0), tolerance=0.0), r"^tolerance = 0"),
        (lambda: dispkin.Path.lin(pose(0, 0, 0), pose(0, 0, 0)), r"coincide"),
        (lambda: dispkin.Path.lin(pose(0, 0, 0), pose(1, 0, 0), pivot=[0, float("nan"), 0]), r"^pivot = \(0, nan, 0\)"),
        (
            lambda: dispkin.Path.lin(pose(0, 0, 0), pose(1, 0, 0), pivot=[0, 0]),
            r"^pivot: expected an array of shape \(3,\), got shape \(2,\)",
        ),
        (lambda: dispkin.Path.lin(pose(0, 0, 0), pose(1, 0, 0), interpolation="spline"), r'^interpolation = "spline"'),
        (
            lambda: dispkin.Path.lin(pose(0, 0, 0), pose(1, 0, 0)).then(dispkin.Path.lin(pose(2, 0, 0), pose(3, 0, 0))),
            r"must start where the path ends",
        ),
        (
            lambda: dispkin.Path.lin(pose(0, 0, 0), pose(1, 0, 0)).sample([[0.5]]),
            r"^u: expected a number or an array of shape \(N,\), got shape \(1, 1\)",
        ),
        (lambda: dispkin.Path.lin(pose(0, 0, 0), pose(1, 0, 0)).sample([0.5, float("nan")]), r"^u = nan"),
        (lambda: dispkin.Path.ptp([0.0, 1.0], [1.0]), r"^q_end size = 1"),
    ],
)
def test_bad_input(build, message):
    with pytest.raises(ValueError, match=message):
        build()


@pytest.mark.parametrize("blend", [None, 0.01])
def test_a_closed_path_appended_to_itself_is_its_copy(blend):
    a, b = dispkin.Pose(), dispkin.Pose.from_xyzuvw([0.1, 0, 0, 0, 0, 0.2])
    loop = dispkin.Path.lin(a, b).then(dispkin.Path.lin(b, a), blend=0.01)
    twice = dispkin.Path.lin(a, b).then(dispkin.Path.lin(b, a), blend=0.01)
    twice.then(dispkin.Path.lin(a, b).then(dispkin.Path.lin(b, a), blend=0.01), blend=blend)
    loop.then(loop, blend=blend)
    assert len(loop) == len(twice) and loop.move_starts == twice.move_starts
    u = np.linspace(0, 1, 101)
    assert np.array_equal(loop.sample(u), twice.sample(u))
