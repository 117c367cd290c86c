"""The Python API contract: every public name exists, is documented, and behaves as specified
(argument names, defaults, shapes and dtypes of what comes back)."""

import inspect
import re
from pathlib import Path

import numpy as np
import pytest

import dispkin
from dispkin import shapes

FUNCTIONS = [
    "disp_distance",
    "section_length",
    "point_speed",
    "sphere_speed",
    "max_point_speed",
    "interpolate",
    "convex_hull_vertices",
]
POSE_MEMBERS = [
    "from_matrix",
    "from_xyzuvw",
    "exp",
    "matrix",
    "to_xyzuvw",
    "inverse",
    "quaternion",
    "translation",
    "rotation",
    "log",
    "transform",
    "rotated_about_pivot",
    "is_approx",
]
METRIC_SET_MEMBERS = [
    "add_relative",
    "add_absolute",
    "add_sphere",
    "set_group_speed",
    "groups",
    "relative_points",
    "absolute_points",
    "spheres",
    "group_speed",
    "is_well_formed",
    "require_well_formed",
    "point_count",
    "sphere_count",
    "reduce_to_hull",
]
SHAPES = ["box", "icosahedron", "icosphere", "spherical_shell", "sphere_approximation_errors"]


def tool():
    s = dispkin.MetricSet()
    s.add_relative((0.0, 0.0, 0.3))
    s.add_sphere((0.0, 0.0, 0.0), 0.1)
    return s


def test_every_public_name_exists_and_is_documented():
    for name in FUNCTIONS + ["Pose", "MetricSet", "shapes", "__version__"]:
        assert hasattr(dispkin, name), name
        assert name in dispkin.__all__, name
    for name in FUNCTIONS + ["Pose", "MetricSet"]:
        assert getattr(dispkin, name).__doc__.strip(), name
    for name in POSE_MEMBERS:
        assert getattr(dispkin.Pose, name).__doc__.strip(), name
    for name in METRIC_SET_MEMBERS:
        assert getattr(dispkin.MetricSet, name).__doc__.strip(), name
    for name in SHAPES:
        assert getattr(shapes, name).__doc__.strip(), name
    assert dispkin.__doc__.strip() and shapes.__doc__.strip()
    assert (Path(dispkin.__file__).parent / "py.typed").is_file()


def test_documented_units_and_frames():
    assert "metres" in dispkin.section_length.__doc__
    assert "body" in dispkin.MetricSet.add_relative.__doc__ and "world" in dispkin.MetricSet.add_absolute.__doc__
    assert "m/s" in dispkin.point_speed.__doc__


def test_keyword_names_and_defaults():
    a, b = dispkin.Pose(), dispkin.Pose(translation=(0.1, 0.0, 0.0))
    s = tool()
    p = dispkin.Pose(quaternion=(1.0, 0.0, 0.0, 0.0), translation=(1.0, 2.0, 3.0))
    assert p.translation.tolist() == [1.0, 2.0, 3.0]
    dispkin.Pose.from_xyzuvw(np.zeros(6), pivot=(0.0, 0.0, 0.1))
    p.to_xyzuvw(pivot=(0.0, 0.0, 0.1))
    assert dispkin.disp_distance(s, a, b) == dispkin.disp_distance(
        metric_set=s, pose_a=a, pose_b=b, norm="euclidean", system_velocity=None
    )
    assert dispkin.section_length(s, a, b) == dispkin.section_length(
        metric_set=s, pose_a=a, pose_b=b, interpolation="decoupled", pivot=(0, 0, 0), system_velocity=None
    )
    assert dispkin.interpolate(a, b, 0.5).is_approx(
        dispkin.interpolate(pose_a=a, pose_b=b, tau=0.5, interpolation="decoupled", pivot=(0, 0, 0)), 0.0
    )
    s.add_relative(points=np.eye(3), group=1)
    s.add_absolute(points=[1.0, 1.0, 1.0], group=2)
    s.add_sphere(center=(0, 0, 0), radius=0.2, absolute=True, group=2)
    s.set_group_speed(2, 0.5)
    assert s.groups == [0, 1, 2]
    np.testing.assert_array_equal(
        shapes.icosahedron(1.0), shapes.icosahedron(radius=1.0, center=(0, 0, 0), circumscribed=True)
    )


def test_pose_api_shapes_and_dtypes():
    p = dispkin.Pose.from_xyzuvw([0.05, 0.02, 0.0, 0.1, 0.2, 0.3])
    for value, shape in [
        (p.matrix(), (4, 4)),
        (p.to_xyzuvw(), (6,)),
        (p.quaternion, (4,)),
        (p.translation, (3,)),
        (p.rotation(), (3, 3)),
        (p.log(), (6,)),
        (p.transform([0.0, 0.0, 1.0]), (3,)),
        (p.transform(np.zeros((5, 3))), (5, 3)),
        (p.transform(np.zeros((0, 3))), (0, 3)),
    ]:
        assert isinstance(value, np.ndarray) and value.shape == shape and value.dtype == np.float64
    assert isinstance(p * p, dispkin.Pose) and isinstance(p.inverse(), dispkin.Pose)
    assert isinstance(dispkin.Pose.exp(np.zeros(6)), dispkin.Pose)
    assert isinstance(dispkin.Pose.from_matrix(np.eye(4)), dispkin.Pose)
    # integers and lists are numbers too
    assert dispkin.Pose(quaternion=[1, 0, 0, 0], translation=[1, 2, 3]).translation.dtype == np.float64
    with pytest.raises(TypeError):
        p * 2.0
    # returned arrays are copies: changing them does not change the pose
    t = p.translation
    t[:] = 0.0
    assert p.translation.tolist() == [0.05, 0.02, 0.0]


def test_pose_quaternion_is_w_first():
    half = np.sqrt(0.5)
    p = dispkin.Pose(quaternion=(half, 0.0, 0.0, half))  # 90° about z
    np.testing.assert_allclose(p.transform([1.0, 0.0, 0.0]), [0.0, 1.0, 0.0], atol=1e-15)
    np.testing.assert_allclose(p.quaternion, [half, 0.0, 0.0, half], atol=1e-16)


def test_metric_set_helpers():
    s = dispkin.MetricSet()
    assert s.groups == [] and s.point_count == 0 and s.sphere_count == 0 and not s.is_well_formed()
    assert repr(s) == "MetricSet(groups=[], points=0, spheres=0, well_formed=False)"
    s.add_relative(np.array([[0.0, 0.0, 0.3], [0.1, 0.0, 0.0]]))
    s.add_relative((0.0, 0.2, 0.0))
    s.add_absolute(np.ones((2, 3)), group=4)
    s.add_sphere((0.0, 0.0, 0.1), 0.05)
    s.add_sphere((1.0, 0.0, 0.0), 0.5, absolute=True)
    s.set_group_speed(4, 0.25)
    assert s.groups == [0, 4]
    assert s.point_count == 5 and s.sphere_count == 2
    np.testing.assert_array_equal(s.relative_points(0), [[0, 0, 0.3], [0.1, 0, 0], [0, 0.2, 0]])
    assert s.absolute_points(0).shape == (0, 3) and s.absolute_points(4).shape == (2, 3)
    assert s.relative_points(4).shape == (0, 3)
    spheres = s.spheres(0)
    assert [(c.tolist(), r, absolute) for c, r, absolute in spheres] == [
        ([0.0, 0.0, 0.1], 0.05, False),
        ([1.0, 0.0, 0.0], 0.5, True),
    ]
    assert s.spheres(4) == []
    assert s.group_speed(4) == 0.25 and s.group_speed(0) is None
    assert s.is_well_formed()
    s.require_well_formed()
    assert repr(s) == "MetricSet(groups=[0, 4], points=5, spheres=2, group_speeds={4: 0.25}, well_formed=True)"
    # read-only views
    with pytest.raises(AttributeError):
        s.point_count = 3
    with pytest.raises(ValueError, match=r"^group = 7: no such group in the set$"):
        s.relative_points(7)
    with pytest.raises(ValueError, match=r"^group = 7: no such group in the set$"):
        s.group_speed(7)


def test_reduce_to_hull_returns_a_new_set():
    s = dispkin.MetricSet()
    cube = shapes.box((0.2, 0.2, 0.2))
    s.add_relative(np.vstack([cube, np.zeros((1, 3)), 0.05 * cube]))
    s.add_sphere((0, 0, 0), 0.1)
    reduced = s.reduce_to_hull()
    assert isinstance(reduced, dispkin.MetricSet) and reduced is not s
    assert s.point_count == 17 and reduced.point_count == 8
    np.testing.assert_array_equal(reduced.relative_points(0), cube)
    assert reduced.sphere_count == 1


def test_disp_functions_return_what_they_say():
    s = tool()
    a = dispkin.Pose()
    b = dispkin.Pose.from_xyzuvw([0.05, 0.02, 0.0, np.radians(10), 0.0, np.radians(30)])
    for norm in ("euclidean", "max", "l1"):
        assert isinstance(dispkin.disp_distance(s, a, b, norm=norm), float)
    # the max norm is at most, the L1 norm at least, the Euclidean one
    d = {norm: dispkin.disp_distance(s, a, b, norm=norm) for norm in ("euclidean", "max", "l1")}
    assert d["max"] <= d["euclidean"] <= d["l1"] <= np.sqrt(3) * d["euclidean"]
    for kind in ("decoupled", "screw"):
        assert dispkin.section_length(s, a, b, interpolation=kind) >= d["euclidean"]
    # interpolate: the ends are the poses, the decoupled pivot moves on a straight line
    pivot = np.array([0.0, 0.0, 0.3])
    for kind in ("decoupled", "screw"):
        assert dispkin.interpolate(a, b, 0.0, kind, pivot).is_approx(a, 1e-15)
        assert dispkin.interpolate(a, b, 1.0, kind, pivot).is_approx(b, 1e-15)
    mid = dispkin.interpolate(a, b, 0.25, "decoupled", pivot)
    np.testing.assert_allclose(mid.transform(pivot), 0.75 * a.transform(pivot) + 0.25 * b.transform(pivot), atol=1e-15)
    # point_speed: float for a point, (N,) for (N, 3)
    xi = np.array([0.1, 0.0, 0.0, 0.0, 0.0, 1.0])
    assert dispkin.point_speed(xi, [0.0, 0.0, 0.0]) == pytest.approx(0.1, abs=1e-17)
    speeds = dispkin.point_speed(xi, np.array([[0.0, 0.0, 0.0], [0.0, -0.1, 0.0], [1.0, 0.0, 5.0]]))
    assert speeds.shape == (3,) and speeds.dtype == np.float64
    np.testing.assert_allclose(speeds, [0.1, 0.2, np.hypot(0.1, 1.0)], rtol=1e-15)
    assert dispkin.sphere_speed(xi, (0.0, 0.0, 0.0), 0.1) == pytest.approx(0.2, rel=1e-15)
    assert dispkin.max_point_speed(s, a, xi) == pytest.approx(0.2, rel=1e-15)
    hull = dispkin.convex_hull_vertices(np.vstack([shapes.box((1, 1, 1)), np.zeros((3, 3))]))
    assert hull.shape == (8, 3) and hull.dtype == np.float64


def test_shapes_submodule_wraps_the_core():
    assert shapes.icosahedron(0.1).shape == (12, 3)
    assert shapes.box((0.1, 0.2, 0.3)).shape == (8, 3)
    assert shapes.icosphere(0.1, 2).shape == (162, 3)
    assert shapes.spherical_shell(0.1, 50).shape == (50, 3)
    assert dispkin.shapes is shapes and set(SHAPES) <= set(shapes.__all__)


def test_module_help_lists_the_signatures():
    text = dispkin.section_length.__doc__
    assert re.search(
        r"section_length\(metric_set: .*MetricSet, pose_a: .*Pose, pose_b: .*Pose, interpolation: str = 'decoupled'",
        text,
    )
    assert "pivot" in inspect.getdoc(dispkin.section_length)
