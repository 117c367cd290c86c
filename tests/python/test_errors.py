"""Bad input fails early with a ValueError whose message names the argument and the value
(never a crash, a NaN in the output or a silently clamped result).

C++ std::invalid_argument arrives as ValueError through pybind11; shape errors are raised by
the binding layer before any C++ code runs.
"""

import re

import numpy as np
import pytest

import dispkin
from dispkin import shapes

NAN, INF = float("nan"), float("inf")


def well_formed():
    s = dispkin.MetricSet()
    s.add_relative(np.eye(3))
    return s


A = dispkin.Pose()
B = dispkin.Pose.from_xyzuvw([0.1, 0.0, 0.0, 0.0, 0.0, 0.5])
XI = np.array([0.1, 0.0, 0.0, 0.0, 0.0, 1.0])


def raises(match, call):
    with pytest.raises(ValueError, match=match):
        call()


@pytest.mark.parametrize(
    "call, match",
    [
        (lambda: dispkin.Pose(translation=(NAN, 0, 0)), r"^translation = \(nan, 0, 0\): must be finite"),
        (lambda: dispkin.Pose(translation=(0, INF, 0)), r"^translation = \(0, inf, 0\): must be finite"),
        (lambda: dispkin.Pose(quaternion=(NAN, 0, 0, 0)), r"^quaternion = \(nan, 0, 0, 0\): must be finite"),
        (lambda: dispkin.Pose.from_xyzuvw([0, 0, 0, INF, 0, 0]), r"^xyzuvw = \(0, 0, 0, inf, 0, 0\): must be finite"),
        (lambda: dispkin.Pose.from_xyzuvw(np.zeros(6), pivot=(0, NAN, 0)), r"^pivot = \(0, nan, 0\): must be finite"),
        (lambda: dispkin.Pose.exp([0, 0, 0, NAN, 0, 0]), r"^twist = \(0, 0, 0, nan, 0, 0\): must be finite"),
        (lambda: dispkin.Pose.from_matrix(np.full((4, 4), NAN)), r"^matrix = \(nan, .*\): must be finite"),
        (lambda: A.to_xyzuvw(pivot=(INF, 0, 0)), r"^pivot = \(inf, 0, 0\): must be finite"),
        (lambda: A.rotated_about_pivot(B, (0, 0, NAN)), r"^pivot = \(0, 0, nan\): must be finite"),
        (lambda: A.is_approx(B, NAN), r"^tol = nan: must be finite and not negative"),
        (lambda: well_formed().add_relative([[0, 0, 0], [1, NAN, 0]]), r"^points\[1\] = \(1, nan, 0\): must be finite"),
        (lambda: well_formed().add_absolute([INF, 0, 0]), r"^points\[0\] = \(inf, 0, 0\): must be finite"),
        (lambda: well_formed().add_sphere((NAN, 0, 0), 0.1), r"^center = \(nan, 0, 0\): must be finite"),
        (lambda: well_formed().add_sphere((0, 0, 0), NAN), r"^radius = nan: must be finite and not negative"),
        (lambda: dispkin.point_speed(XI, [NAN, 0, 0]), r"^point = \(nan, 0, 0\): must be finite"),
        (
            lambda: dispkin.point_speed([0, 0, 0, 0, 0, INF], [0, 0, 0]),
            r"^twist = \(0, 0, 0, 0, 0, inf\): must be finite",
        ),
        (lambda: dispkin.sphere_speed(XI, [0, 0, NAN], 0.1), r"^center = \(0, 0, nan\): must be finite"),
        (lambda: dispkin.sphere_speed(XI, [0, 0, 0], INF), r"^radius = inf: must be finite and not negative"),
        (lambda: dispkin.max_point_speed(well_formed(), A, [NAN, 0, 0, 0, 0, 0]), r"^twist = \(nan, 0, 0, 0, 0, 0\)"),
        (lambda: dispkin.interpolate(A, B, NAN), r"^tau = nan: must be finite"),
        (lambda: dispkin.interpolate(A, B, 0.5, pivot=(NAN, 0, 0)), r"^pivot = \(nan, 0, 0\): must be finite"),
        (
            lambda: dispkin.section_length(well_formed(), A, B, pivot=(0, INF, 0)),
            r"^pivot = \(0, inf, 0\): must be finite",
        ),
        (
            lambda: dispkin.convex_hull_vertices([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, NAN]]),
            r"^points\[3\] = \(0, 0, nan\)",
        ),
        (lambda: shapes.icosahedron(NAN), r"^radius = nan: must be finite and greater than zero"),
        (
            lambda: shapes.box((0.125, INF, 0.125)),
            r"^size = \(0.125, inf, 0.125\): edge lengths must be finite and positive",
        ),
        (lambda: A.transform([[0, 0, 0], [0, NAN, 0]]), r"^points\[1\] = \(0, nan, 0\): must be finite"),
        (
            lambda: dispkin.section_length(well_formed(), A, B, "screw", pivot=(NAN, 0, 0)),
            r"^pivot = \(nan, 0, 0\): must be finite",
        ),
        (lambda: shapes.icosphere(0.1, 1, center=(NAN, 0, 0)), r"^center = \(nan, 0, 0\): must be finite"),
        (lambda: shapes.spherical_shell(0.1, 10, center=(0, 0, INF)), r"^center = \(0, 0, inf\): must be finite"),
    ],
)
def test_nan_and_inf_are_refused_naming_the_argument(call, match):
    raises(match, call)


def test_non_unit_quaternion():
    raises(
        r"^quaternion \(w, x, y, z\) = \(1, 1, 0, 0\): must be a unit quaternion, its norm is 1\.41",
        lambda: dispkin.Pose(quaternion=(1, 1, 0, 0)),
    )
    raises(
        r"^quaternion \(w, x, y, z\) = \(0, 0, 0, 0\): must be a unit quaternion",
        lambda: dispkin.Pose(quaternion=(0, 0, 0, 0)),
    )


def test_non_rigid_matrix():
    m = np.eye(4)
    m[0, 0] = 2.0
    raises(
        r"^rotation = \(2, 0, 0, 0, 1, 0, 0, 0, 1\): must be orthonormal with determinant \+1",
        lambda: dispkin.Pose.from_matrix(m),
    )
    m = np.eye(4)
    m[3, 0] = 0.5
    raises(r"^matrix last row = \(0\.5, 0, 0, 1\): must be \(0, 0, 0, 1\)", lambda: dispkin.Pose.from_matrix(m))
    raises(
        r"^rotation = .*: must be orthonormal with determinant \+1",
        lambda: dispkin.Pose.from_matrix(np.diag([1.0, 1.0, -1.0, 1.0])),
    )


@pytest.mark.parametrize(
    "build, parts",
    [
        (lambda s: s.add_relative([0.1, 0.2, 0.3]), "1 object"),  # a single point
        (
            lambda s: s.add_relative([[0, 0, 0], [0.1, 0.1, 0.1], [0.3, 0.3, 0.3], [-1, -1, -1]]),
            "4 objects",
        ),  # collinear
        (lambda s: s.add_sphere((0, 0, 0), 0.0), "1 object"),  # a ball of radius 0 is a point
        (lambda s: None, None),  # empty
    ],
)
def test_degenerate_sets_are_refused(build, parts):
    s = dispkin.MetricSet()
    build(s)
    assert not s.is_well_formed()
    why = (
        "the set is empty"
        if parts is None
        else re.escape(f"its relative part ({parts}) and its absolute part (0 objects) are each at most collinear")
    )
    match = r'^metric_set = "MetricSet": is not well-formed: ' + why
    for call in (
        s.require_well_formed,
        lambda: dispkin.disp_distance(s, A, B),
        lambda: dispkin.section_length(s, A, B, "screw"),
        lambda: dispkin.section_length(s, A, B, "decoupled"),
    ):
        raises(match, call)


def test_negative_radius():
    raises(r"^radius = -0\.25: must be finite and not negative", lambda: well_formed().add_sphere((0, 0, 0), -0.25))
    raises(r"^radius = -0\.25: must be finite and not negative", lambda: dispkin.sphere_speed(XI, (0, 0, 0), -0.25))
    raises(r"^radius = -1: must be finite and greater than zero", lambda: shapes.icosahedron(-1.0))
    raises(r"^radius = 0: must be finite and greater than zero", lambda: shapes.icosphere(0.0, 2))
    raises(r"^radius = -1: must be finite and greater than zero", lambda: shapes.spherical_shell(-1.0, 20))
    raises(r"^radius = -0\.5: must be finite and not negative", lambda: shapes.sphere_approximation_errors(XI, -0.5))


@pytest.mark.parametrize(
    "call, match",
    [
        (
            lambda: well_formed().add_relative(np.zeros((4, 2))),
            r"^points: expected an array of shape \(3,\) or \(N, 3\), got shape \(4, 2\)$",
        ),
        (
            lambda: well_formed().add_absolute(np.zeros(4)),
            r"^points: expected an array of shape \(3,\) or \(N, 3\), got shape \(4,\)$",
        ),
        (lambda: well_formed().add_relative(np.zeros((2, 3, 3))), r"^points: expected .*, got shape \(2, 3, 3\)$"),
        (lambda: well_formed().add_relative(5.0), r"^points: expected .*, got shape \(\)$"),
        (
            lambda: well_formed().add_relative("abc"),
            r"^points: expected an array of shape \(3,\) or \(N, 3\) of numbers, got str$",
        ),
        (
            lambda: well_formed().add_sphere((0, 0), 0.1),
            r"^center: expected an array of shape \(3,\), got shape \(2,\)$",
        ),
        (
            lambda: dispkin.Pose(quaternion=(1, 0, 0)),
            r"^quaternion: expected an array of shape \(4,\), got shape \(3,\)$",
        ),
        (
            lambda: dispkin.Pose(translation=np.zeros((1, 3))),
            r"^translation: expected an array of shape \(3,\), got shape \(1, 3\)$",
        ),
        (
            lambda: dispkin.Pose.from_matrix(np.eye(3)),
            r"^matrix: expected an array of shape \(4, 4\), got shape \(3, 3\)$",
        ),
        (
            lambda: dispkin.Pose.from_xyzuvw(np.zeros(5)),
            r"^xyzuvw: expected an array of shape \(6,\), got shape \(5,\)$",
        ),
        (lambda: dispkin.Pose.exp(np.zeros((6, 1))), r"^twist: expected an array of shape \(6,\), got shape \(6, 1\)$"),
        (
            lambda: A.transform(np.zeros((3, 4))),
            r"^points: expected an array of shape \(3,\) or \(N, 3\), got shape \(3, 4\)$",
        ),
        (
            lambda: dispkin.point_speed(np.zeros(3), np.zeros(3)),
            r"^twist: expected an array of shape \(6,\), got shape \(3,\)$",
        ),
        (
            lambda: dispkin.point_speed(XI, np.zeros(2)),
            r"^point: expected an array of shape \(3,\) or \(N, 3\), got shape \(2,\)$",
        ),
        (
            lambda: dispkin.sphere_speed(XI, np.zeros(4), 0.1),
            r"^center: expected an array of shape \(3,\), got shape \(4,\)$",
        ),
        (
            lambda: dispkin.section_length(well_formed(), A, B, pivot=(0, 0)),
            r"^pivot: expected an array of shape \(3,\), got shape \(2,\)$",
        ),
        (
            lambda: dispkin.convex_hull_vertices(np.zeros(3)),
            r"^points: expected an array of shape \(N, 3\), got shape \(3,\)$",
        ),
        (lambda: shapes.box((1, 1)), r"^size: expected an array of shape \(3,\), got shape \(2,\)$"),
    ],
)
def test_wrong_array_shapes_name_the_argument_and_the_shape(call, match):
    raises(match, call)


def test_unknown_interpolation_and_norm_names():
    s = well_formed()
    raises(
        r'^interpolation = "spline": must be "decoupled" or "screw"$',
        lambda: dispkin.section_length(s, A, B, interpolation="spline"),
    )
    raises(
        r'^interpolation = "LIN": must be "decoupled" or "screw"$',
        lambda: dispkin.interpolate(A, B, 0.5, interpolation="LIN"),
    )
    raises(r'^norm = "l2": must be "euclidean", "max" or "l1"$', lambda: dispkin.disp_distance(s, A, B, norm="l2"))
    raises(
        r'^norm = "Euclidean": must be "euclidean", "max" or "l1"$',
        lambda: dispkin.disp_distance(s, A, B, norm="Euclidean"),
    )


def test_group_speeds_and_system_velocity():
    s = well_formed()
    raises(
        r"^speed = 0: must be in \[1e-12, 1e12\] \(finite, positive, inside dispkin's numeric range\)$",
        lambda: s.set_group_speed(1, 0.0),
    )
    raises(
        r"^speed = -0\.5: must be in \[1e-12, 1e12\] \(finite, positive, inside dispkin's numeric range\)$",
        lambda: s.set_group_speed(1, -0.5),
    )
    raises(
        r"^speed = nan: must be in \[1e-12, 1e12\] \(finite, positive, inside dispkin's numeric range\)$",
        lambda: s.set_group_speed(1, NAN),
    )
    raises(r"^group = -1: must be a non-negative integer$", lambda: s.add_relative([0, 0, 0], group=-1))
    assert s.groups == [0]  # nothing was added by the failed calls
    s.add_relative([1.0, 1.0, 1.0], group=2)
    s.set_group_speed(2, 0.05)
    missing = r"^system_velocity is missing: group 2 has its own speed limit"
    raises(missing, lambda: dispkin.disp_distance(s, A, B))
    raises(missing, lambda: dispkin.section_length(s, A, B))
    raises(missing, lambda: dispkin.max_point_speed(s, A, XI))
    for v in (0.0, -1.0, NAN, INF):
        value = {0.0: "0", -1.0: "-1", NAN: "nan", INF: "inf"}[v]
        match = (
            rf"^system_velocity = {value}: "
            + r"must be in \[1e-12, 1e12\] \(finite, positive, inside dispkin's numeric range\)$"
        )
        raises(match, lambda: dispkin.disp_distance(s, A, B, system_velocity=v))
        raises(match, lambda: dispkin.section_length(s, A, B, system_velocity=v))
        raises(match, lambda: dispkin.max_point_speed(s, A, XI, system_velocity=v))
        # refused even when no group needs it
        raises(match, lambda: dispkin.disp_distance(well_formed(), A, B, system_velocity=v))


def test_shape_builder_counts():
    raises(r"^subdivisions = 8: must be between 0 and 7", lambda: shapes.icosphere(0.1, 8))
    raises(r"^subdivisions = -1: must be between 0 and 7", lambda: shapes.icosphere(0.1, -1))
    raises(r"^count = 3: must be at least 4", lambda: shapes.spherical_shell(0.1, 3))
    raises(
        r"^twist = \(0.0, 0.0, 0.0, 0.0, 0.0, 0.0\): the sphere does not move",
        lambda: shapes.sphere_approximation_errors(np.zeros(6), 0.1),
    )
