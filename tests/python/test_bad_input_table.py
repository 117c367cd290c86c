"""The bad-input table: every public Python entry point × every kind of bad input, one row each,
asserting the exception type AND that the message names the argument and shows the value
("<argument> = <value>: <reason>").

Rows whose entry point does NOT reject the input are strict xfails carrying the observed
behaviour, so a fix turns them into failures that ask for the row to be promoted.

tests/BAD_INPUT.md is generated from ROWS by tests/python/make_bad_input_table.py; the last
test checks it is up to date.
"""

import atexit
import json
import math
import pathlib
import re
import shutil
import tempfile

import numpy as np
import pytest

import dispkin
from dispkin import shapes

NAN, INF = float("nan"), float("inf")


def good_set():
    s = dispkin.MetricSet()
    s.add_relative(np.eye(3))
    return s


def collinear_set():
    s = dispkin.MetricSet()
    s.add_relative([[0, 0, 0], [1, 0, 0], [2, 0, 0]])
    return s


def hexapod():
    return dispkin.Hexapod.symmetric(0.15, math.radians(20), 0.10, math.radians(20), 0.20, 0.15, 0.32, 0.01)


def hexapod_json(**change):
    d = json.loads(hexapod().to_json())
    d.update(change)
    return json.dumps(d)


LEGS = json.loads(hexapod().to_json())["legs"]


def leg_changed(**change):
    legs = json.loads(json.dumps(LEGS))
    legs[0].update(change)
    return legs


def without(key):
    d = json.loads(hexapod().to_json())
    del d[key]
    return json.dumps(d)


A = dispkin.Pose()
B = dispkin.Pose.from_xyzuvw([0.1, 0.0, 0.0, 0.0, 0.0, 0.5])
C = dispkin.Pose.from_xyzuvw([0.1, 0.1, 0.0, 0.0, 0.0, 0.0])
XI = [0.1, 0.0, 0.0, 0.0, 0.0, 1.0]
LINE = dispkin.Path.lin(A, B)
LIMITS = dispkin.Limits(0.1, 1.0, 10.0)
TRAPEZOID_LIMITS = dispkin.Limits(0.1, 1.0)


def trajectory():
    return dispkin.plan(dispkin.Path.lin(hexapod().home, hexapod().home * B), good_set(), LIMITS)


def overlapped():
    """A LIN to B and one on to C, overlapped by 0.1 s."""
    return dispkin.OverlappedTrajectory(
        dispkin.plan(LINE, good_set(), LIMITS), dispkin.plan(dispkin.Path.lin(B, C), good_set(), LIMITS), 0.1
    )


# (entry point, bad input, call, exception, message fragment). The fragment is matched with
# re.search after re.escape, so write it literally; it contains the argument and the value.
R = []
_SECTION = [None]


def section(title):
    """Rows from here on form a section of the table under `title`."""
    _SECTION[0] = title


def row(entry, bad, call, exc, fragment, xfail=None):
    R.append(
        dict(
            entry=entry, bad=bad, call=call, exc=exc, fragment=fragment, xfail=xfail, section=_SECTION[0], accepted=None
        )
    )


def accepted(entry, bad, call, check, reason):
    """A row whose input is accepted by design (`reason`): the call returns, and check(result)
    holds the documented behaviour."""
    R.append(
        dict(
            entry=entry,
            bad=bad,
            call=call,
            exc=None,
            fragment="",
            xfail=None,
            section=_SECTION[0],
            accepted=reason,
            check=check,
        )
    )


V = ValueError  # rejections of bad arguments are ValueError; a pose path without a solution is RuntimeError

_TMP = tempfile.mkdtemp(prefix="dispkin_bad_input_")
atexit.register(shutil.rmtree, _TMP, ignore_errors=True)
MALFORMED = pathlib.Path(_TMP) / "malformed.json"
MALFORMED.write_text("{\"format\": \"dispkin.hexapod\", \"legs\": [")

# --- Pose ---------------------------------------------------------------------------------
row(
    "Pose(quaternion, translation)",
    "NaN quaternion",
    lambda: dispkin.Pose((NAN, 0, 0, 0), (0, 0, 0)),
    V,
    "quaternion = (nan, 0, 0, 0)",
)
row(
    "Pose(quaternion, translation)",
    "+inf translation",
    lambda: dispkin.Pose((1, 0, 0, 0), (INF, 0, 0)),
    V,
    "translation = (inf, 0, 0)",
)
row(
    "Pose(quaternion, translation)",
    "-inf translation",
    lambda: dispkin.Pose((1, 0, 0, 0), (0, -INF, 0)),
    V,
    "translation = (0, -inf, 0)",
)
row(
    "Pose(quaternion, translation)",
    "translation beyond the numeric range (1e13 m)",
    lambda: dispkin.Pose((1, 0, 0, 0), (0, 0, 1e13)),
    V,
    "translation = (0, 0, 1e+13): must have coordinates within ±1e12 m",
)
row(
    "Pose(quaternion, translation)",
    "zero quaternion",
    lambda: dispkin.Pose((0, 0, 0, 0), (0, 0, 0)),
    V,
    "quaternion (w, x, y, z) = (0, 0, 0, 0): must be a unit quaternion",
)
row(
    "Pose(quaternion, translation)",
    "non-unit quaternion",
    lambda: dispkin.Pose((2, 0, 0, 0), (0, 0, 0)),
    V,
    "quaternion (w, x, y, z) = (2, 0, 0, 0): must be a unit quaternion",
)
row(
    "Pose(quaternion, translation)",
    "wrong size quaternion (3)",
    lambda: dispkin.Pose((1, 0, 0), (0, 0, 0)),
    V,
    "quaternion: expected an array of shape (4,), got shape (3,)",
)
row(
    "Pose(quaternion, translation)",
    "wrong size translation (2)",
    lambda: dispkin.Pose((1, 0, 0, 0), (0, 0)),
    V,
    "translation: expected an array of shape (3,), got shape (2,)",
)
row(
    "Pose(quaternion, translation)",
    "empty translation",
    lambda: dispkin.Pose((1, 0, 0, 0), ()),
    V,
    "translation: expected an array of shape (3,), got shape (0,)",
)
row(
    "Pose.from_matrix",
    "NaN entry",
    lambda: dispkin.Pose.from_matrix(np.where(np.eye(4) == 1, np.eye(4), NAN)),
    V,
    "matrix = (1, nan, nan, nan, nan, 1,",
)
row(
    "Pose.from_matrix",
    "+inf entry",
    lambda: dispkin.Pose.from_matrix(np.diag([1, 1, 1, 1.0]) + np.pad([[INF]], ((0, 3), (3, 0)))),
    V,
    "matrix = (1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, inf, 0, 0, 1): must be finite",
)
row(
    "Pose.from_matrix",
    "bad last row",
    lambda: dispkin.Pose.from_matrix(np.diag([1, 1, 1, 2.0])),
    V,
    "matrix last row = (0, 0, 0, 2)",
)
row(
    "Pose.from_matrix",
    "not a rotation (scaled)",
    lambda: dispkin.Pose.from_matrix(np.diag([2, 2, 2, 1.0])),
    V,
    "rotation = (2, 0, 0, 0, 2, 0, 0, 0, 2): must be orthonormal with determinant +1",
)
row(
    "Pose.from_matrix",
    "reflection (det -1)",
    lambda: dispkin.Pose.from_matrix(np.diag([1, 1, -1, 1.0])),
    V,
    "rotation = (1, 0, 0, 0, 1, 0, 0, 0, -1): must be orthonormal with determinant +1",
)
row(
    "Pose.from_matrix",
    "wrong shape 3x3",
    lambda: dispkin.Pose.from_matrix(np.eye(3)),
    V,
    "matrix: expected an array of shape (4, 4), got shape (3, 3)",
)
row(
    "Pose.from_matrix",
    "empty",
    lambda: dispkin.Pose.from_matrix(np.zeros((0, 0))),
    V,
    "matrix: expected an array of shape (4, 4), got shape (0, 0)",
)
row(
    "Pose.from_xyzuvw",
    "NaN",
    lambda: dispkin.Pose.from_xyzuvw([0, 0, 0, NAN, 0, 0]),
    V,
    "xyzuvw = (0, 0, 0, nan, 0, 0)",
)
row(
    "Pose.from_xyzuvw",
    "+inf",
    lambda: dispkin.Pose.from_xyzuvw([INF, 0, 0, 0, 0, 0]),
    V,
    "xyzuvw = (inf, 0, 0, 0, 0, 0)",
)
row("Pose.from_xyzuvw", "NaN pivot", lambda: dispkin.Pose.from_xyzuvw([0] * 6, [NAN, 0, 0]), V, "pivot = (nan, 0, 0)")
row(
    "Pose.from_xyzuvw",
    "wrong size (5)",
    lambda: dispkin.Pose.from_xyzuvw([0] * 5),
    V,
    "xyzuvw: expected an array of shape (6,), got shape (5,)",
)
row(
    "Pose.from_xyzuvw",
    "empty",
    lambda: dispkin.Pose.from_xyzuvw([]),
    V,
    "xyzuvw: expected an array of shape (6,), got shape (0,)",
)
row("Pose.to_xyzuvw", "NaN pivot", lambda: B.to_xyzuvw([NAN, 0, 0]), V, "pivot = (nan, 0, 0)")
row("Pose.to_xyzuvw", "-inf pivot", lambda: B.to_xyzuvw([0, 0, -INF]), V, "pivot = (0, 0, -inf)")
row(
    "Pose.to_xyzuvw",
    "wrong size pivot (4)",
    lambda: B.to_xyzuvw([0, 0, 0, 0]),
    V,
    "pivot: expected an array of shape (3,), got shape (4,)",
)
row("Pose.rotated_about_pivot", "NaN pivot", lambda: A.rotated_about_pivot(B, [NAN, 0, 0]), V, "pivot = (nan, 0, 0)")
row("Pose.rotated_about_pivot", "+inf pivot", lambda: A.rotated_about_pivot(B, [0, INF, 0]), V, "pivot = (0, inf, 0)")
row(
    "Pose.rotated_about_pivot",
    "wrong size pivot (2)",
    lambda: A.rotated_about_pivot(B, [0, 0]),
    V,
    "pivot: expected an array of shape (3,), got shape (2,)",
)
row("Pose.exp", "NaN twist", lambda: dispkin.Pose.exp([NAN, 0, 0, 0, 0, 0]), V, "twist = (nan, 0, 0, 0, 0, 0)")
row(
    "Pose.exp",
    "wrong size twist (3)",
    lambda: dispkin.Pose.exp([0, 0, 0]),
    V,
    "twist: expected an array of shape (6,), got shape (3,)",
)
row("Pose.transform", "NaN point", lambda: A.transform([NAN, 0, 0]), V, "points[0] = (nan, 0, 0)")
row(
    "Pose.transform",
    "wrong shape points (N, 2)",
    lambda: A.transform(np.zeros((4, 2))),
    V,
    "points: expected an array of shape (3,) or (N, 3), got shape (4, 2)",
)

# --- MetricSet ----------------------------------------------------------------------------
row(
    "MetricSet.add_relative",
    "NaN point",
    lambda: dispkin.MetricSet().add_relative([[0, 0, 0], [NAN, 0, 0]]),
    V,
    "points[1] = (nan, 0, 0)",
)
row(
    "MetricSet.add_relative",
    "+inf point",
    lambda: dispkin.MetricSet().add_relative([0, INF, 0]),
    V,
    "points[0] = (0, inf, 0): must be finite",
)
row(
    "MetricSet.add_relative",
    "wrong shape (N, 2)",
    lambda: dispkin.MetricSet().add_relative(np.zeros((3, 2))),
    V,
    "points: expected an array of shape (3,) or (N, 3), got shape (3, 2)",
)
row(
    "MetricSet.add_relative",
    "negative group",
    lambda: dispkin.MetricSet().add_relative([0, 0, 0], group=-1),
    V,
    "group = -1",
)
row(
    "MetricSet.add_absolute",
    "-inf point",
    lambda: dispkin.MetricSet().add_absolute([[0, 0, -INF]]),
    V,
    "points[0] = (0, 0, -inf): must be finite",
)
row(
    "MetricSet.add_absolute",
    "point beyond the numeric range (1e13 m)",
    lambda: dispkin.MetricSet().add_absolute([[0, 1e13, 0]]),
    V,
    "points[0] = (0, 1e+13, 0): must have coordinates within ±1e12 m",
)
row(
    "MetricSet.add_absolute",
    "wrong shape (N, 4)",
    lambda: dispkin.MetricSet().add_absolute(np.zeros((2, 4))),
    V,
    "points: expected an array of shape (3,) or (N, 3), got shape (2, 4)",
)
row(
    "MetricSet.add_absolute",
    "negative group",
    lambda: dispkin.MetricSet().add_absolute([0, 0, 0], group=-3),
    V,
    "group = -3",
)
row(
    "MetricSet.add_sphere",
    "NaN center",
    lambda: dispkin.MetricSet().add_sphere([NAN, 0, 0], 0.1),
    V,
    "center = (nan, 0, 0)",
)
row(
    "MetricSet.add_sphere",
    "negative radius",
    lambda: dispkin.MetricSet().add_sphere([0, 0, 0], -0.1),
    V,
    "radius = -0.1",
)
row(
    "MetricSet.add_sphere",
    "radius beyond the numeric range (1e13 m)",
    lambda: dispkin.MetricSet().add_sphere([0, 0, 0], 1e13),
    V,
    "radius = 1e+13: must be finite and not negative, at most 1e12 m",
)
row("MetricSet.add_sphere", "NaN radius", lambda: dispkin.MetricSet().add_sphere([0, 0, 0], NAN), V, "radius = nan")
row("MetricSet.add_sphere", "+inf radius", lambda: dispkin.MetricSet().add_sphere([0, 0, 0], INF), V, "radius = inf")
row(
    "MetricSet.add_sphere",
    "wrong size center (2)",
    lambda: dispkin.MetricSet().add_sphere([0, 0], 0.1),
    V,
    "center: expected an array of shape (3,), got shape (2,)",
)
row(
    "MetricSet.add_sphere",
    "negative group",
    lambda: dispkin.MetricSet().add_sphere([0, 0, 0], 0.1, group=-1),
    V,
    "group = -1",
)
row("MetricSet.set_group_speed", "zero speed", lambda: dispkin.MetricSet().set_group_speed(1, 0.0), V, "speed = 0")
row(
    "MetricSet.set_group_speed", "negative speed", lambda: dispkin.MetricSet().set_group_speed(1, -1.0), V, "speed = -1"
)
row(
    "MetricSet.set_group_speed",
    "speed above the numeric range (1e13)",
    lambda: dispkin.MetricSet().set_group_speed(1, 1e13),
    V,
    "speed = 1e+13: must be in [1e-12, 1e12]",
)
row("MetricSet.set_group_speed", "NaN speed", lambda: dispkin.MetricSet().set_group_speed(1, NAN), V, "speed = nan")
row("MetricSet.set_group_speed", "+inf speed", lambda: dispkin.MetricSet().set_group_speed(1, INF), V, "speed = inf")
row(
    "MetricSet.set_group_speed", "negative group", lambda: dispkin.MetricSet().set_group_speed(-1, 1.0), V, "group = -1"
)
row("MetricSet.relative_points", "unknown group", lambda: good_set().relative_points(7), V, "group = 7: no such group")
row(
    "MetricSet.require_well_formed",
    "empty set",
    lambda: dispkin.MetricSet().require_well_formed(),
    V,
    "metric_set = \"MetricSet\": is not well-formed: the set is empty",
)
row(
    "MetricSet.require_well_formed",
    "collinear set",
    lambda: collinear_set().require_well_formed(),
    V,
    "metric_set = \"MetricSet\": is not well-formed",
)

# --- shapes -------------------------------------------------------------------------------
row("shapes.box", "zero edge", lambda: shapes.box([0, 1, 1]), V, "size = (0, 1, 1)")
row("shapes.box", "negative edge", lambda: shapes.box([1, -1, 1]), V, "size = (1, -1, 1)")
row("shapes.box", "NaN edge", lambda: shapes.box([1, 1, NAN]), V, "size = (1, 1, nan)")
row("shapes.box", "+inf center", lambda: shapes.box([1, 1, 1], [INF, 0, 0]), V, "center = (inf, 0, 0)")
row(
    "shapes.box",
    "wrong size (2)",
    lambda: shapes.box([1, 1]),
    V,
    "size: expected an array of shape (3,), got shape (2,)",
)
row("shapes.icosahedron", "zero radius", lambda: shapes.icosahedron(0.0), V, "radius = 0")
row("shapes.icosahedron", "negative radius", lambda: shapes.icosahedron(-1.0), V, "radius = -1")
row("shapes.icosahedron", "NaN radius", lambda: shapes.icosahedron(NAN), V, "radius = nan")
row("shapes.icosahedron", "+inf radius", lambda: shapes.icosahedron(INF), V, "radius = inf")
row("shapes.icosahedron", "NaN center", lambda: shapes.icosahedron(1.0, [NAN, 0, 0]), V, "center = (nan, 0, 0)")
row("shapes.icosphere", "zero radius", lambda: shapes.icosphere(0.0, 1), V, "radius = 0")
row("shapes.icosphere", "negative subdivisions", lambda: shapes.icosphere(1.0, -1), V, "subdivisions = -1")
row("shapes.icosphere", "too many subdivisions", lambda: shapes.icosphere(1.0, 8), V, "subdivisions = 8")
row("shapes.icosphere", "-inf center", lambda: shapes.icosphere(1.0, 1, [0, -INF, 0]), V, "center = (0, -inf, 0)")
row("shapes.spherical_shell", "negative radius", lambda: shapes.spherical_shell(-1.0, 10), V, "radius = -1")
row("shapes.spherical_shell", "count too small", lambda: shapes.spherical_shell(1.0, 3), V, "count = 3")
row("shapes.spherical_shell", "zero count", lambda: shapes.spherical_shell(1.0, 0), V, "count = 0")
row(
    "shapes.spherical_shell",
    "NaN center",
    lambda: shapes.spherical_shell(1.0, 10, [NAN, 0, 0]),
    V,
    "center = (nan, 0, 0)",
)

# --- convex hull --------------------------------------------------------------------------
row(
    "convex_hull_vertices",
    "NaN point",
    lambda: dispkin.convex_hull_vertices([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, NAN]]),
    V,
    "points[3] = (0, 0, nan): must be finite",
)
row(
    "convex_hull_vertices",
    "+inf point",
    lambda: dispkin.convex_hull_vertices([[0, 0, 0], [1, 0, 0], [0, 1, 0], [INF, 0, 1]]),
    V,
    "points[3] = (inf, 0, 1): must be finite",
)
row(
    "convex_hull_vertices",
    "wrong shape (N, 2)",
    lambda: dispkin.convex_hull_vertices(np.zeros((4, 2))),
    V,
    "points: expected an array of shape (N, 3), got shape (4, 2)",
)

# --- DISP functions -----------------------------------------------------------------------
row(
    "disp_distance",
    "empty set",
    lambda: dispkin.disp_distance(dispkin.MetricSet(), A, B),
    V,
    "metric_set = \"MetricSet\": is not well-formed: the set is empty",
)
row(
    "disp_distance",
    "collinear set",
    lambda: dispkin.disp_distance(collinear_set(), A, B),
    V,
    "metric_set = \"MetricSet\": is not well-formed",
)
row(
    "disp_distance",
    "unknown norm",
    lambda: dispkin.disp_distance(good_set(), A, B, norm="manhattan"),
    V,
    "norm = \"manhattan\"",
)
row(
    "disp_distance",
    "zero system_velocity",
    lambda: dispkin.disp_distance(good_set(), A, B, system_velocity=0.0),
    V,
    "system_velocity = 0",
)
row(
    "disp_distance",
    "negative system_velocity",
    lambda: dispkin.disp_distance(good_set(), A, B, system_velocity=-1.0),
    V,
    "system_velocity = -1",
)
row(
    "disp_distance",
    "NaN system_velocity",
    lambda: dispkin.disp_distance(good_set(), A, B, system_velocity=NAN),
    V,
    "system_velocity = nan",
)
row(
    "section_length",
    "empty set",
    lambda: dispkin.section_length(dispkin.MetricSet(), A, B),
    V,
    "metric_set = \"MetricSet\": is not well-formed",
)
row(
    "section_length",
    "unknown interpolation",
    lambda: dispkin.section_length(good_set(), A, B, interpolation="slerp"),
    V,
    "interpolation = \"slerp\"",
)
row(
    "section_length",
    "NaN pivot",
    lambda: dispkin.section_length(good_set(), A, B, pivot=[NAN, 0, 0]),
    V,
    "pivot = (nan, 0, 0)",
)
row(
    "section_length",
    "pivot beyond the numeric range (1e13 m)",
    lambda: dispkin.section_length(good_set(), A, B, pivot=[0, 1e13, 0]),
    V,
    "pivot = (0, 1e+13, 0): must have coordinates within ±1e12 m",
)
row(
    "section_length",
    "wrong size pivot (2)",
    lambda: dispkin.section_length(good_set(), A, B, pivot=[0, 0]),
    V,
    "pivot: expected an array of shape (3,), got shape (2,)",
)
row(
    "section_length",
    "zero system_velocity",
    lambda: dispkin.section_length(good_set(), A, B, system_velocity=0.0),
    V,
    "system_velocity = 0",
)
row(
    "section_length",
    "+inf system_velocity",
    lambda: dispkin.section_length(good_set(), A, B, system_velocity=INF),
    V,
    "system_velocity = inf",
)
row(
    "max_point_speed",
    "empty set",
    lambda: dispkin.max_point_speed(dispkin.MetricSet(), A, XI),
    V,
    "metric_set = \"MetricSet\": is empty",
)
row(
    "max_point_speed",
    "NaN twist",
    lambda: dispkin.max_point_speed(good_set(), A, [NAN, 0, 0, 0, 0, 0]),
    V,
    "twist = (nan, 0, 0, 0, 0, 0)",
)
row(
    "max_point_speed",
    "+inf twist",
    lambda: dispkin.max_point_speed(good_set(), A, [INF, 0, 0, 0, 0, 0]),
    V,
    "twist = (inf, 0, 0, 0, 0, 0)",
)
row(
    "max_point_speed",
    "wrong size twist (5)",
    lambda: dispkin.max_point_speed(good_set(), A, [0] * 5),
    V,
    "twist: expected an array of shape (6,), got shape (5,)",
)
row(
    "max_point_speed",
    "negative system_velocity",
    lambda: dispkin.max_point_speed(good_set(), A, XI, system_velocity=-2.0),
    V,
    "system_velocity = -2",
)
row("point_speed", "NaN point", lambda: dispkin.point_speed(XI, (NAN, 0.0, 0.0)), V, "point = (nan, 0, 0)")
row(
    "point_speed",
    "wrong size twist (4)",
    lambda: dispkin.point_speed([0] * 4, (0.0, 0.0, 0.0)),
    V,
    "twist: expected an array of shape (6,), got shape (4,)",
)
row("sphere_speed", "negative radius", lambda: dispkin.sphere_speed(XI, [0, 0, 0], -1.0), V, "radius = -1")
row("sphere_speed", "NaN center", lambda: dispkin.sphere_speed(XI, [NAN, 0, 0], 1.0), V, "center = (nan, 0, 0)")
row("interpolate", "NaN tau", lambda: dispkin.interpolate(A, B, NAN), V, "tau = nan")
accepted(
    "interpolate",
    "tau above 1",
    lambda: dispkin.interpolate(A, B, 2.0),
    lambda p: np.allclose(p.translation, [0.2, 0, 0], atol=1e-15),
    "extrapolates along the same motion (x = 0.2 at tau = 2): the motion is defined for every tau, as derivatives at the ends use",
)
row(
    "interpolate",
    "unknown interpolation",
    lambda: dispkin.interpolate(A, B, 0.5, interpolation="cubic"),
    V,
    "interpolation = \"cubic\"",
)
row("interpolate", "NaN pivot", lambda: dispkin.interpolate(A, B, 0.5, pivot=[0, NAN, 0]), V, "pivot = (0, nan, 0)")
row(
    "interpolate",
    "pivot beyond the numeric range (1e13 m)",
    lambda: dispkin.interpolate(A, B, 0.5, pivot=[0, 0, 1e13]),
    V,
    "pivot = (0, 0, 1e+13): must have coordinates within ±1e12 m",
)
row(
    "xyzuvw_for_new_pivot",
    "NaN xyzuvw",
    lambda: dispkin.xyzuvw_for_new_pivot([NAN, 0, 0, 0, 0, 0], [0, 0, 0], [0, 0, 1]),
    V,
    "xyzuvw = (nan, 0, 0, 0, 0, 0)",
)
row(
    "xyzuvw_for_new_pivot",
    "+inf new_pivot",
    lambda: dispkin.xyzuvw_for_new_pivot([0] * 6, [0, 0, 0], [0, 0, INF]),
    V,
    "new_pivot = (0, 0, inf): must be finite",
)

# --- Path / JointPath ---------------------------------------------------------------------
row(
    "Path.lin",
    "unknown interpolation",
    lambda: dispkin.Path.lin(A, B, interpolation="spline"),
    V,
    "interpolation = \"spline\"",
)
row("Path.lin", "NaN pivot", lambda: dispkin.Path.lin(A, B, pivot=[NAN, 0, 0]), V, "pivot = (nan, 0, 0)")
row(
    "Path.lin",
    "pivot beyond the numeric range (6.3e257 m)",
    lambda: dispkin.Path.lin(A, B, pivot=[117, 6.3e257, 117]),
    V,
    "pivot = (117, 6.3e+257, 117): must have coordinates within ±1e12 m",
)
row(
    "Path.lin",
    "wrong size pivot (4)",
    lambda: dispkin.Path.lin(A, B, pivot=[0, 0, 0, 0]),
    V,
    "pivot: expected an array of shape (3,), got shape (4,)",
)
row(
    "Path.circ",
    "collinear via",
    lambda: dispkin.Path.circ(
        A, dispkin.Pose.from_xyzuvw([0.05, 0, 0, 0, 0, 0]), dispkin.Pose.from_xyzuvw([0.1, 0, 0, 0, 0, 0])
    ),
    V,
    "via = (0.05, 0, 0): is collinear with the start and end points",
)
row(
    "Path.circ",
    "via equals start",
    lambda: dispkin.Path.circ(A, A, C),
    V,
    "via = (0, 0, 0): coincides with the start point",
)
row("Path.circ", "zero tolerance", lambda: dispkin.Path.circ(A, B, C, tolerance=0.0), V, "tolerance = 0")
row("Path.circ", "negative tolerance", lambda: dispkin.Path.circ(A, B, C, tolerance=-1e-3), V, "tolerance = -0.001")
row("Path.circ", "NaN tolerance", lambda: dispkin.Path.circ(A, B, C, tolerance=NAN), V, "tolerance = nan")
row("Path.circ", "NaN pivot", lambda: dispkin.Path.circ(A, B, C, pivot=[NAN, 0, 0]), V, "pivot = (nan, 0, 0)")
row(
    "Path.circ",
    "pivot beyond the numeric range (1e13 m)",
    lambda: dispkin.Path.circ(A, B, C, pivot=[1e13, 0, 0]),
    V,
    "pivot = (1e+13, 0, 0): must have coordinates within ±1e12 m",
)
row(
    "Path.spline",
    "two poses",
    lambda: dispkin.Path.spline([A, B]),
    V,
    "poses = 2: key poses given: a SPLINE needs at least three",
)
row(
    "Path.spline",
    "repeated key pose",
    lambda: dispkin.Path.spline([A, B, B, C]),
    V,
    "poses[2] = (0.1, 0, 0): coincides with the key pose before it",
)
row("Path.spline", "NaN tolerance", lambda: dispkin.Path.spline([A, B, C], tolerance=NAN), V, "tolerance = nan")
row(
    "Path.spline",
    "wrong size pivot (2)",
    lambda: dispkin.Path.spline([A, B, C], pivot=[0, 0]),
    V,
    "pivot: expected an array of shape (3,), got shape (2,)",
)
row(
    "Path.then",
    "negative blend",
    lambda: dispkin.Path.lin(A, B).then(dispkin.Path.lin(B, C), blend=-0.01),
    V,
    "before = -0.01: must be a positive distance",
)
row(
    "Path.then",
    "blend over half a move",
    lambda: dispkin.Path.lin(A, B).then(dispkin.Path.lin(B, C), blend=0.08),
    V,
    "before = 0.08: exceeds half of the move before the via point",
)
row(
    "Path.then",
    "before without after",
    lambda: dispkin.Path.lin(A, B).then(dispkin.Path.lin(B, C), before=0.01),
    V,
    "after is missing",
)
row(
    "Path.then",
    "blend and before",
    lambda: dispkin.Path.lin(A, B).then(dispkin.Path.lin(B, C), blend=0.01, before=0.01),
    V,
    "blend: give either blend or before/after",
)
row(
    "Path.then",
    "discontinuous join",
    lambda: dispkin.Path.lin(A, B).then(dispkin.Path.lin(C, A)),
    V,
    "next = (0.1, 0.1, 0): must start where the path ends",
)
row("Path.sample", "NaN u", lambda: LINE.sample(NAN), V, "u = nan: must be finite")
accepted(
    "Path.sample",
    "u below 0",
    lambda: LINE.sample(-0.5),
    lambda p: p.is_approx(LINE.start, 0.0),
    'clamped to u = 0, the start pose (documented: "Clamped outside"; the sampling side never throws)',
)
accepted(
    "Path.sample",
    "u above 1",
    lambda: LINE.sample(1.5),
    lambda p: p.is_approx(LINE.end, 0.0),
    'clamped to u = 1, the end pose (documented: "Clamped outside"; the sampling side never throws)',
)
row("Path.sample", "+inf u", lambda: LINE.sample(INF), V, "u = inf: must be finite")
row(
    "Section.length",
    "empty set",
    lambda: LINE.sections()[0].length(dispkin.MetricSet()),
    V,
    "metric_set = \"MetricSet\": is not well-formed: the set is empty",
)
accepted(
    "Section.pose",
    "tau above 1",
    lambda: LINE.sections()[0].pose(2.0),
    lambda p: np.allclose(p.translation, [0.2, 0, 0], atol=1e-15),
    "extrapolates along the section's motion (x = 0.2 at tau = 2): central differences at tau = 0 and 1 evaluate just outside",
)
row(
    "Path.section_lengths",
    "empty set",
    lambda: LINE.section_lengths(dispkin.MetricSet()),
    V,
    "metric_set = \"MetricSet\": is not well-formed",
)
row("Path.ptp", "NaN joint", lambda: dispkin.Path.ptp([0, NAN], [0, 1]), V, "q_start = (0, nan): must be finite")
row("Path.ptp", "+inf joint", lambda: dispkin.Path.ptp([0, INF], [0, 1]), V, "q_start = (0, inf)")
row("Path.ptp", "size mismatch", lambda: dispkin.Path.ptp([0, 0], [0, 1, 2]), V, "q_end size = 3")
row("Path.ptp", "empty", lambda: dispkin.Path.ptp([], []), V, "q_start = 0: must have at least one joint")
row("JointPath.sample", "NaN u", lambda: dispkin.Path.ptp([0, 0], [1, 1]).sample(NAN), V, "u = nan")
accepted(
    "JointPath.sample",
    "u above 1",
    lambda: dispkin.Path.ptp([0, 0], [1, 1]).sample(2.0),
    lambda q: np.array_equal(q, [1, 1]),
    'clamped, returns [1, 1] (documented: "u clamped to [0, 1]")',
)
row("Section.pose", "NaN tau", lambda: LINE.sections()[0].pose(NAN), V, "tau = nan")

# --- Profile ------------------------------------------------------------------------------
row("Profile.trapezoid", "NaN distance", lambda: dispkin.Profile.trapezoid(NAN, 1, 1), V, "distance = nan")
row("Profile.trapezoid", "negative distance", lambda: dispkin.Profile.trapezoid(-1, 1, 1), V, "distance = -1")
row("Profile.trapezoid", "+inf distance", lambda: dispkin.Profile.trapezoid(INF, 1, 1), V, "distance = inf")
row("Profile.trapezoid", "zero v_max", lambda: dispkin.Profile.trapezoid(1, 0, 1), V, "v_max = 0")
row("Profile.trapezoid", "negative a_max", lambda: dispkin.Profile.trapezoid(1, 1, -1), V, "a_max = -1")
row("Profile.trapezoid", "+inf v_max", lambda: dispkin.Profile.trapezoid(1, INF, 1), V, "v_max = inf")
row(
    "Profile.trapezoid",
    "negative v_start",
    lambda: dispkin.Profile.trapezoid(1, 1, 1, v_start=-0.5),
    V,
    "v_start = -0.5",
)
row("Profile.trapezoid", "v_end above v_max", lambda: dispkin.Profile.trapezoid(1, 1, 1, v_end=2.0), V, "v_end = 2")
row("Profile.scurve", "zero j_max", lambda: dispkin.Profile.scurve(1, 1, 1, 0), V, "j_max = 0")
row("Profile.scurve", "NaN j_max", lambda: dispkin.Profile.scurve(1, 1, 1, NAN), V, "j_max = nan")
row("Profile.scurve", "negative v_max", lambda: dispkin.Profile.scurve(1, -1, 1, 1), V, "v_max = -1")
row("Profile.scurve", "NaN distance", lambda: dispkin.Profile.scurve(NAN, 1, 1, 1), V, "distance = nan")
row(
    "Profile.from_state",
    "NaN v_start",
    lambda: dispkin.Profile.from_state(1, 1, 1, 10, v_start=NAN),
    V,
    "v_start = nan",
)
row(
    "Profile.from_state",
    "+inf a_start",
    lambda: dispkin.Profile.from_state(1, 1, 1, 10, a_start=INF),
    V,
    "a_start = inf",
)
row(
    "Profile.from_state",
    "v_end above v_max",
    lambda: dispkin.Profile.from_state(1, 1, 1, 10, v_end=2.0),
    V,
    "v_end = 2",
)
row("Profile.from_state", "negative jerk", lambda: dispkin.Profile.from_state(1, 1, 1, -1), V, "j_max = -1")
row(
    "Profile.from_state",
    "too short to stop (names the shortfall)",
    lambda: dispkin.Profile.from_state(0.001, 1, 1, 10, v_start=1.0),
    V,
    "distance = 0.001: too short",
)
row(
    "Profile.from_state",
    "braking that turns the velocity negative",
    lambda: dispkin.Profile.from_state(1, 1, 1, 10, v_start=0.01, a_start=-1.0),
    V,
    "a_start = -1: brakes too hard",
)
row(
    "Profile.trapezoid_from_state",
    "negative v_start",
    lambda: dispkin.Profile.trapezoid_from_state(1, 1, 1, v_start=-1.0),
    V,
    "v_start = -1",
)
row(
    "Profile.trapezoid_from_state",
    "too short to brake",
    lambda: dispkin.Profile.trapezoid_from_state(0.001, 1, 1, v_start=1.0),
    V,
    "distance = 0.001: too short",
)
row(
    "velocity_limited_chain",
    "segments of the wrong shape",
    lambda: dispkin.velocity_limited_chain(np.ones((2, 3)), 1.0),
    V,
    "segments: expected an array of shape (N, 2)",
)
row(
    "velocity_limited_law",
    "negative limit in a segment",
    lambda: dispkin.velocity_limited_law(np.array([[1.0, 1.0], [1.0, -1.0]]), 1.0, 10.0),
    V,
    "segments[1].limit = -1",
)
row("Profile.sample", "NaN time", lambda: dispkin.Profile.trapezoid(1, 1, 1).sample([NAN]), V, "times[0] = nan")

# --- Limits / plan ------------------------------------------------------------------------
row("Limits", "zero velocity", lambda: dispkin.Limits(0.0, 1.0), V, "velocity = 0")
row("Limits", "negative acceleration", lambda: dispkin.Limits(1.0, -1.0), V, "acceleration = -1")
row("Limits", "NaN velocity", lambda: dispkin.Limits(NAN, 1.0), V, "velocity = nan")
row("Limits", "+inf acceleration", lambda: dispkin.Limits(1.0, INF), V, "acceleration = inf")
row(
    "Limits",
    "velocity below the numeric range (1e-13)",
    lambda: dispkin.Limits(1e-13, 1.0),
    V,
    "velocity = 1e-13: must be in [1e-12, 1e12]",
)
row(
    "Limits",
    "jerk above the numeric range (1e13)",
    lambda: dispkin.Limits(1.0, 1.0, 1e13),
    V,
    "jerk = 1e+13: must be in [1e-12, 1e12]",
)
row("Limits", "zero jerk", lambda: dispkin.Limits(1.0, 1.0, 0.0), V, "jerk = 0")
row("Limits", "negative jerk", lambda: dispkin.Limits(1.0, 1.0, -5.0), V, "jerk = -5")
row(
    "plan",
    "empty set",
    lambda: dispkin.plan(LINE, dispkin.MetricSet(), LIMITS),
    V,
    "metric_set = \"MetricSet\": is not well-formed",
)
row(
    "plan",
    "collinear set",
    lambda: dispkin.plan(LINE, collinear_set(), LIMITS),
    V,
    "metric_set = \"MetricSet\": is not well-formed",
)
row("plan", "unknown profile", lambda: dispkin.plan(LINE, good_set(), LIMITS, profile="sine"), V, "profile = \"sine\"")
row(
    "plan",
    "scurve without jerk",
    lambda: dispkin.plan(LINE, good_set(), dispkin.Limits(0.1, 1.0), profile="scurve"),
    V,
    "jerk is missing: the S-curve profile needs a jerk limit",
)
row(
    "Trajectory.sample",
    "NaN time",
    lambda: dispkin.plan(LINE, good_set(), LIMITS).sample([NAN]),
    V,
    "times = nan: must be finite",
)
row("Trajectory.stopped_at", "NaN time", lambda: trajectory().stopped_at(NAN), V, "t = nan: must be finite")
row(
    "Trajectory.with_override",
    "factor 0",
    lambda: trajectory().with_override(0.1, 0.0),
    V,
    "factor = 0: must be in [0.001, 10]",
)
row(
    "Trajectory.with_override",
    "factor above 10",
    lambda: trajectory().with_override(0.1, 11.0),
    V,
    "factor = 11: must be in [0.001, 10]",
)
row(
    "Trajectory.with_override",
    "factor not a number",
    lambda: trajectory().with_override(0.1, "fast"),
    TypeError,
    "incompatible function arguments",
)
row(
    "Trajectory.resumed_at",
    "not stopped",
    lambda: trajectory().resumed_at(0.1),
    V,
    "t = 0.1: resumes a stopped trajectory only",
)
row(
    "plan",
    "negative start velocity",
    lambda: dispkin.plan(LINE, good_set(), LIMITS, start_velocity=-1.0),
    V,
    "start_velocity = -1: must be finite and ≥ 0",
)
row(
    "plan",
    "start velocity above the limit",
    lambda: dispkin.plan(LINE, good_set(), LIMITS, start_velocity=1e3),
    V,
    "start_velocity = 1000: must be at most the velocity limit at the start",
)
row(
    "plan",
    "NaN start acceleration",
    lambda: dispkin.plan(LINE, good_set(), LIMITS, start_acceleration=NAN),
    V,
    "start_acceleration = nan: must be finite",
)
row(
    "Trajectory.starting_from",
    "acceleration beyond the limit",
    lambda: trajectory().starting_from(0.0, 1e3),
    V,
    "acceleration = 1000: must be within the acceleration limit",
)


def stream(*requests):
    """A MotionStream of LINE's tool and limits after `requests` (callables on it)."""
    s = dispkin.MotionStream(good_set(), LIMITS)
    for request in requests:
        request(s)
    return s


row(
    "MotionStream",
    "negative corner tolerance",
    lambda: dispkin.MotionStream(good_set(), LIMITS, corner_tolerance=-1.0),
    V,
    "corner_tolerance = -1: must be finite and not negative",
)
row(
    "MotionStream",
    "S-curve without jerk",
    lambda: dispkin.MotionStream(good_set(), TRAPEZOID_LIMITS),
    V,
    "jerk is missing",
)
row(
    "MotionStream.append",
    "a move that does not start where the last ends",
    lambda: stream(lambda s: s.append(LINE, 0.0), lambda s: s.append(LINE, 1.0)),
    V,
    "path.start",
)
row(
    "MotionStream.append",
    "a request before the last one",
    lambda: stream(lambda s: s.append(LINE, 2.0), lambda s: s.set_override(1.0, 0.5)),
    V,
    "t = 1: must be finite and not before the last request",
)
row("MotionStream.append", "NaN time", lambda: stream(lambda s: s.append(LINE, NAN)), V, "t = nan")
row("MotionStream.stop", "nothing appended", lambda: stream(lambda s: s.stop(0.0)), V, "nothing was appended yet")
row(
    "MotionStream.stop",
    "stopped already",
    lambda: stream(lambda s: s.append(LINE, 0.0), lambda s: s.stop(0.1), lambda s: s.stop(0.2)),
    V,
    "it is stopped already",
)
row(
    "MotionStream.resume",
    "not stopped",
    lambda: stream(lambda s: s.append(LINE, 0.0), lambda s: s.resume(0.1)),
    V,
    "resumes a stopped motion only",
)
row(
    "MotionStream.set_override",
    "factor 0",
    lambda: stream(lambda s: s.set_override(0.0, 0.0)),
    V,
    "factor = 0: must be in [0.001, 10]",
)
row("Trajectory.sample", "+inf time", lambda: dispkin.plan(LINE, good_set(), LIMITS).sample([INF]), V, "times = inf")
accepted(
    "Trajectory.sample",
    "negative time",
    lambda: dispkin.plan(LINE, good_set(), LIMITS).sample([-1.0]),
    lambda m: np.allclose(m[0], A.matrix(), atol=0),
    "clamped to t = 0, the start pose, as t beyond the duration gives the end (documented: times clamped)",
)

row(
    "Trajectory.sample",
    "out of dtype int64",
    lambda: dispkin.plan(LINE, good_set(), LIMITS).sample([0.0, 0.1], out=np.zeros((2, 4, 4), dtype=np.int64)),
    V,
    "out: expected a writeable C-contiguous float64 array of shape (2, 4, 4), got dtype int64",
)
row(
    "Trajectory.sample",
    "out of one sample for two times",
    lambda: dispkin.plan(LINE, good_set(), LIMITS).sample([0.0, 0.1], out=np.zeros((4, 4))),
    V,
    "out: expected a writeable C-contiguous float64 array of shape (2, 4, 4), got shape (4, 4)",
)
row(
    "Trajectory.sample_xyzuvw",
    "out a list",
    lambda: dispkin.plan(LINE, good_set(), LIMITS).sample_xyzuvw(0.1, out=[0.0] * 6),
    V,
    "out: expected a writeable C-contiguous float64 array of shape (6,), got list",
)
row(
    "Trajectory.body_twist",
    "out not contiguous (every other row)",
    lambda: dispkin.plan(LINE, good_set(), LIMITS).body_twist([0.0, 0.1], out=np.zeros((4, 6))[::2]),
    V,
    "out: expected a writeable C-contiguous float64 array of shape (2, 6), got a non-contiguous array (strides (96, 8))",
)
row(
    "Trajectory.path_velocity",
    "read-only out",
    lambda: dispkin.plan(LINE, good_set(), LIMITS).path_velocity([0.0, 0.1], out=np.frombuffer(bytes(16))),
    V,
    "out: expected a writeable C-contiguous float64 array of shape (2,), got a read-only array",
)
row(
    "Trajectory.path_position",
    "out of shape (2,) for a number",
    lambda: dispkin.plan(LINE, good_set(), LIMITS).path_position(0.1, out=np.zeros(2)),
    V,
    "out: expected a writeable C-contiguous float64 array of shape () or (1,), got shape (2,)",
)
row(
    "Trajectory.body_acceleration",
    "out of dtype float32",
    lambda: dispkin.plan(LINE, good_set(), LIMITS).body_acceleration(0.1, out=np.zeros(6, dtype=np.float32)),
    V,
    "out: expected a writeable C-contiguous float64 array of shape (6,), got dtype float32",
)
row(
    "OverlappedTrajectory.sample",
    "out of dtype float32",
    lambda: overlapped().sample(0.1, out=np.zeros((4, 4), dtype=np.float32)),
    V,
    "out: expected a writeable C-contiguous float64 array of shape (4, 4), got dtype float32",
)
row(
    "TrajectoryCursor.sample",
    "NaN time",
    lambda: dispkin.plan(LINE, good_set(), LIMITS).cursor().sample(NAN, np.zeros(15)),
    V,
    "t = nan: must be finite",
)
row(
    "TrajectoryCursor.sample",
    "+inf time",
    lambda: dispkin.plan(LINE, good_set(), LIMITS).cursor().sample(INF, np.zeros(15)),
    V,
    "t = inf: must be finite",
)
row(
    "TrajectoryCursor.sample",
    "out of shape (17,)",
    lambda: dispkin.plan(LINE, good_set(), LIMITS).cursor().sample(0.1, np.zeros(17)),
    V,
    "out: expected a writeable C-contiguous float64 array of shape (15,), got shape (17,)",
)
row(
    "TrajectoryCursor.sample",
    "out of dtype int64",
    lambda: dispkin.plan(LINE, good_set(), LIMITS).cursor().sample(0.1, np.zeros(15, dtype=np.int64)),
    V,
    "out: expected a writeable C-contiguous float64 array of shape (15,), got dtype int64",
)
row(
    "TrajectoryCursor.sample",
    "read-only out",
    lambda: dispkin.plan(LINE, good_set(), LIMITS).cursor().sample(0.1, np.frombuffer(bytes(120))),
    V,
    "out: expected a writeable C-contiguous float64 array of shape (15,), got a read-only array",
)

row(
    "OverlappedTrajectory",
    "negative overlap",
    lambda: dispkin.OverlappedTrajectory(trajectory(), trajectory(), -0.5),
    V,
    "overlap = -0.5",
)
row(
    "OverlappedTrajectory",
    "overlap longer than a move",
    lambda: dispkin.OverlappedTrajectory(trajectory(), trajectory(), 1e3),
    V,
    "overlap = 1000: must be between 0 and the shorter move's duration",
)
row(
    "OverlappedTrajectory",
    "moves not joining",
    lambda: dispkin.OverlappedTrajectory(trajectory(), trajectory(), 0.1),
    V,
    "must start where `before` ends",
)
row(
    "OverlappedTrajectory",
    "wrong size pivot (2)",
    lambda: dispkin.OverlappedTrajectory(trajectory(), trajectory(), 0.1, pivot=[0, 0]),
    V,
    "pivot: expected an array of shape (3,), got shape (2,)",
)

# --- Hexapod ------------------------------------------------------------------------------
HJ = hexapod()
row(
    "Hexapod(...)",
    "NaN base joint",
    lambda: dispkin.Hexapod(
        np.where(np.arange(18).reshape(6, 3) == 0, NAN, HJ.base_joints), HJ.platform_joints, 0.15, 0.32, 0.01
    ),
    V,
    "base_joints = (nan, -0.02604722665, 0, 0.147721162952, 0.026",
)
row(
    "Hexapod(...)",
    "wrong shape base_joints (5, 3)",
    lambda: dispkin.Hexapod(HJ.base_joints[:5], HJ.platform_joints, 0.15, 0.32, 0.01),
    V,
    "base_joints: expected an array of shape (6, 3), got shape (5, 3)",
)
row(
    "Hexapod(...)",
    "wrong shape platform_joints (6, 2)",
    lambda: dispkin.Hexapod(HJ.base_joints, HJ.platform_joints[:, :2], 0.15, 0.32, 0.01),
    V,
    "platform_joints: expected an array of shape (6, 3), got shape (6, 2)",
)
row(
    "Hexapod(...)",
    "leg_min above leg_max",
    lambda: dispkin.Hexapod(HJ.base_joints, HJ.platform_joints, 0.4, 0.32, 0.01),
    V,
    "leg_max[0] = 0.32: must be finite",
)
row(
    "Hexapod(...)",
    "negative leg_min",
    lambda: dispkin.Hexapod(HJ.base_joints, HJ.platform_joints, -0.1, 0.32, 0.01),
    V,
    "leg_min[0] = -0.1: must be finite",
)
row(
    "Hexapod(...)",
    "zero leg_speed",
    lambda: dispkin.Hexapod(HJ.base_joints, HJ.platform_joints, 0.15, 0.32, 0.0),
    V,
    "leg_speed[0] = 0: must be in [1e-12, 1e12]",
)
row(
    "Hexapod(...)",
    "NaN leg_max",
    lambda: dispkin.Hexapod(HJ.base_joints, HJ.platform_joints, 0.15, NAN, 0.01),
    V,
    "leg_max[0] = nan: must be finite",
)
row(
    "Hexapod(...)",
    "wrong size leg_speed (5)",
    lambda: dispkin.Hexapod(HJ.base_joints, HJ.platform_joints, 0.15, 0.32, [0.01] * 5),
    V,
    "leg_speed: expected a number or an array of shape (6,), got shape (5,)",
)
accepted(
    "Hexapod(...)",
    "unreachable home",
    lambda: dispkin.Hexapod(
        HJ.base_joints, HJ.platform_joints, 0.15, 0.32, 0.01, home=dispkin.Pose((1, 0, 0, 0), (0, 0, 5.0))
    ),
    lambda h: h.home.translation[2] == 5.0,
    "home is only the pose forward() starts its search from; it need not be reachable (the default, the identity, puts the platform in the base plane)",
)
row(
    "Hexapod.symmetric",
    "zero base_radius",
    lambda: dispkin.Hexapod.symmetric(0.0, 0.3, 0.1, 0.3, 0.2, 0.1, 0.3, 0.01),
    V,
    "base_radius = 0",
)
row(
    "Hexapod.symmetric",
    "NaN height",
    lambda: dispkin.Hexapod.symmetric(0.15, 0.3, 0.1, 0.3, NAN, 0.1, 0.3, 0.01),
    V,
    "height = nan",
)
row(
    "Hexapod.symmetric",
    "negative leg_speed",
    lambda: dispkin.Hexapod.symmetric(0.15, 0.3, 0.1, 0.3, 0.2, 0.1, 0.3, -0.01),
    V,
    "leg_speed[0] = -0.01",
)
row(
    "Hexapod.symmetric",
    "+inf platform_radius",
    lambda: dispkin.Hexapod.symmetric(0.15, 0.3, INF, 0.3, 0.2, 0.1, 0.3, 0.01),
    V,
    "platform_radius = inf",
)
row(
    "Hexapod.symmetric",
    "leg_max below leg_min",
    lambda: dispkin.Hexapod.symmetric(0.15, 0.3, 0.1, 0.3, 0.2, 0.3, 0.1, 0.01),
    V,
    "leg_max[0] = 0.1: must be finite",
)
row(
    "Hexapod.symmetric",
    "negative base_gap",
    lambda: dispkin.Hexapod.symmetric(0.15, -0.3, 0.1, 0.3, 0.2, 0.1, 0.3, 0.01),
    V,
    "base_gap = -0.3",
)
row(
    "Hexapod.from_json",
    "truncated JSON",
    lambda: dispkin.Hexapod.from_json("{"),
    V,
    "description = \"<text>\": is not JSON",
)
row(
    "Hexapod.from_json", "empty text", lambda: dispkin.Hexapod.from_json(""), V, "description = \"<text>\": is not JSON"
)
row(
    "Hexapod.from_json",
    "not an object",
    lambda: dispkin.Hexapod.from_json("[1, 2]"),
    V,
    "description = \"[1,2]\": must be a JSON object",
)
row(
    "Hexapod.from_json",
    "missing legs",
    lambda: dispkin.Hexapod.from_json(without("legs")),
    V,
    "legs = \"<missing>\": required key is missing",
)
row("Hexapod.from_json", "5 legs", lambda: dispkin.Hexapod.from_json(hexapod_json(legs=LEGS[:5])), V, "legs = \"[{\"")
row(
    "Hexapod.from_json",
    "string speed",
    lambda: dispkin.Hexapod.from_json(hexapod_json(legs=leg_changed(speed="fast"))),
    V,
    "legs[0].speed = \"fast\": must be a number",
)
row(
    "Hexapod.from_json",
    "negative speed",
    lambda: dispkin.Hexapod.from_json(hexapod_json(legs=leg_changed(speed=-1.0))),
    V,
    "leg_speed[0] = -1: must be in [1e-12, 1e12]",
)
row(
    "Hexapod.from_json",
    "min above max",
    lambda: dispkin.Hexapod.from_json(hexapod_json(legs=leg_changed(min=0.5))),
    V,
    "leg_max[0] = 0.32: must be finite",
)
row(
    "Hexapod.from_json",
    "base with 2 coordinates",
    lambda: dispkin.Hexapod.from_json(hexapod_json(legs=leg_changed(base=[0.1, 0.0]))),
    V,
    "legs[0].base = \"[0.1,0.0]\": must be an array of 3 numbers",
)
row(
    "Hexapod.from_json",
    "NaN literal",
    lambda: dispkin.Hexapod.from_json(hexapod_json().replace('"speed": 0.01', '"speed": NaN', 1)),
    V,
    "description = \"<text>\": is not JSON",
)
row(
    "Hexapod.from_json",
    "wrong format tag",
    lambda: dispkin.Hexapod.from_json(hexapod_json(format="urdf")),
    V,
    "format = \"urdf\"",
)
row(
    "Hexapod.from_json",
    "non-unit home quaternion",
    lambda: dispkin.Hexapod.from_json(hexapod_json(home={"quaternion_wxyz": [2, 0, 0, 0], "translation": [0, 0, 0.2]})),
    V,
    "quaternion (w, x, y, z) = (2, 0, 0, 0): must be a unit quaternion",
)
row(
    "Hexapod.from_json",
    "unknown top-level key",
    lambda: dispkin.Hexapod.from_json(hexapod_json(leg_speed=-1.0)),
    V,
    "leg_speed = -1: unknown key (allowed here: format, version, units, legs, home)",
)
row(
    "Hexapod.load",
    "missing file",
    lambda: dispkin.Hexapod.load("/nonexistent/hexapod.json"),
    V,
    "path = \"/nonexistent/hexapod.json\": cannot be opened",
)
row("Hexapod.load", "directory", lambda: dispkin.Hexapod.load("/"), V, "/: description = \"<text>\": is not JSON")
row(
    "Hexapod.load",
    "malformed file",
    lambda: dispkin.Hexapod.load(str(MALFORMED)),
    V,
    "description = \"<text>\": is not JSON",
)
row("Hexapod.forward", "NaN legs", lambda: HJ.forward([NAN, 0.2, 0.2, 0.2, 0.2, 0.2]), V, "legs[0] = nan")
row(
    "Hexapod.forward",
    "wrong size legs (5)",
    lambda: HJ.forward([0.2] * 5),
    V,
    "legs: expected an array of shape (6,), got shape (5,)",
)
row("Hexapod.forward", "out-of-range legs", lambda: HJ.forward([5.0] * 6), V, "legs = (5, 5, 5, 5, 5, 5)")
row("Hexapod.forward", "negative legs", lambda: HJ.forward([-0.2] * 6), V, "legs[0] = -0.2")
row("Hexapod.forward", "NaN guess", lambda: HJ.forward([0.2] * 6, guess=np.full((4, 4), NAN)), V, "matrix = (nan, nan")
row(
    "Hexapod.require_reachable",
    "unreachable pose",
    lambda: HJ.require_reachable(dispkin.Pose((1, 0, 0, 0), (0, 0, 5.0))),
    V,
    "leg 0 length = 5.00095177608: outside the leg's range [0.15, 0.32]",
)
row(
    "Hexapod.require_reachable",
    "wrong shape pose (6,)",
    lambda: HJ.require_reachable([0, 0, 0.2, 0, 0, 0]),
    V,
    "pose: expected an array of shape (4, 4), got shape (6,)",
)
row("Hexapod.require_reachable", "NaN matrix", lambda: HJ.require_reachable(np.full((4, 4), NAN)), V, "matrix = (nan")
row("Hexapod.inverse", "NaN matrix", lambda: HJ.inverse(np.full((4, 4), NAN)), V, "matrix = (nan")
row(
    "Hexapod.inverse_xyzuvw",
    "NaN xyzuvw",
    lambda: HJ.inverse_xyzuvw([NAN, 0, 0.2, 0, 0, 0]),
    V,
    "xyzuvw = (nan, 0, 0.2, 0, 0, 0)",
)
row(
    "Hexapod.inverse",
    "wrong shape (N, 5)",
    lambda: HJ.inverse(np.zeros((2, 5))),
    V,
    "pose: expected an array of shape (4, 4), got shape (2, 5)",
)
row(
    "Hexapod.check",
    "wrong shape pose (6,)",
    lambda: HJ.check([0, 0, NAN, 0, 0, 0]),
    V,
    "pose: expected an array of shape (4, 4), got shape (6,)",
)
row("Hexapod.leg_jacobian", "NaN matrix", lambda: HJ.leg_jacobian(np.full((4, 4), NAN)), V, "matrix = (nan, nan")
row("Hexapod.check_trajectory", "zero dt", lambda: HJ.check_trajectory(trajectory(), 0.0), V, "dt = 0")
row("Hexapod.check_trajectory", "negative dt", lambda: HJ.check_trajectory(trajectory(), -0.01), V, "dt = -0.01")
row("Hexapod.check_trajectory", "NaN dt", lambda: HJ.check_trajectory(trajectory(), NAN), V, "dt = nan")
row("Hexapod.check_trajectory", "+inf dt", lambda: HJ.check_trajectory(trajectory(), INF), V, "dt = inf")
row("Hexapod.add_leg_speed_group", "negative group", lambda: HJ.add_leg_speed_group(good_set(), -1), V, "group = -1")
HEX_LINE = dispkin.Path.lin(HJ.home, HJ.home * B)


class _LegLengths:
    # A stand-in joint metric returning whatever it is given.
    def __init__(self, value):
        self.value = value

    def leg_section_lengths(self, path, system_velocity):
        return self.value


row(
    "Hexapod.leg_section_lengths",
    "zero system_velocity",
    lambda: HJ.leg_section_lengths(HEX_LINE, 0.0),
    V,
    "system_velocity = 0",
)
row(
    "Hexapod.leg_section_lengths",
    "NaN system_velocity",
    lambda: HJ.leg_section_lengths(HEX_LINE, NAN),
    V,
    "system_velocity = nan",
)
row(
    "check_joint_limits",
    "hexapod, negative samples_between",
    lambda: dispkin.check_joint_limits(dispkin.plan(HEX_LINE, good_set(), LIMITS), HJ, samples_between=-1),
    V,
    "samples_between = -1",
)
row(
    "retime",
    "hexapod, scaling method",
    lambda: dispkin.retime(HEX_LINE, good_set(), TRAPEZOID_LIMITS, HJ, method="scaling"),
    V,
    "method = \"scaling\"",
)
row(
    "retime",
    "hexapod, joint_acceleration of wrong size",
    lambda: dispkin.retime(HEX_LINE, good_set(), TRAPEZOID_LIMITS, HJ, joint_acceleration=[1.0]),
    V,
    "joint_acceleration size = 1",
)
row(
    "Hexapod.leg_section_lengths",
    "+inf system_velocity",
    lambda: HJ.leg_section_lengths(HEX_LINE, INF),
    V,
    "system_velocity = inf",
)
row(
    "Hexapod.leg_section_lengths",
    "zero tolerance",
    lambda: HJ.leg_section_lengths(HEX_LINE, 0.1, tolerance=0.0),
    V,
    "tolerance = 0: must be in (0, 1]",
)
row("Hexapod.leg_rate_bounds", "NaN tolerance", lambda: HJ.leg_rate_bounds(HEX_LINE, NAN), V, "tolerance = nan")
row("Hexapod.leg_rate_bounds", "tolerance above 1", lambda: HJ.leg_rate_bounds(HEX_LINE, 2.0), V, "tolerance = 2")
row(
    "plan",
    "joint_metric without the method",
    lambda: dispkin.plan(HEX_LINE, good_set(), LIMITS, joint_metric=42),
    V,
    "joint_metric = \"42\": must have a method leg_section_lengths",
)
row(
    "plan",
    "joint_metric wrong count",
    lambda: dispkin.plan(HEX_LINE, good_set(), LIMITS, joint_metric=_LegLengths([0.1, 0.2])),
    V,
    "joint_metric(path, limits) size = 2: must be 0 or the path's section count 1",
)
row(
    "plan",
    "joint_metric negative length",
    lambda: dispkin.plan(HEX_LINE, good_set(), LIMITS, joint_metric=_LegLengths([-0.5])),
    V,
    "joint_metric(path, limits)[0] = -0.5",
)
row(
    "plan",
    "joint_metric NaN length",
    lambda: dispkin.plan(HEX_LINE, good_set(), LIMITS, joint_metric=_LegLengths([NAN])),
    V,
    "joint_metric(path, limits)[0] = nan",
)
row(
    "plan",
    "joint_metric wrong shape (1, 1)",
    lambda: dispkin.plan(HEX_LINE, good_set(), LIMITS, joint_metric=_LegLengths([[0.1]])),
    V,
    "joint_metric.leg_section_lengths(path, velocity): expected an array of shape (1,), got shape (1, 1)",
)
row(
    "plan",
    "joint_metric not numbers",
    lambda: dispkin.plan(HEX_LINE, good_set(), LIMITS, joint_metric=_LegLengths("long")),
    V,
    "joint_metric.leg_section_lengths(path, velocity): expected an array of shape (1,)",
)

# --- WorkToolFrames -----------------------------------------------------------------------
FRAMES = dispkin.WorkToolFrames()
row(
    "WorkToolFrames(...)",
    "NaN work matrix",
    lambda: dispkin.WorkToolFrames(work=np.full((4, 4), NAN)),
    V,
    "matrix = (nan",
)
row(
    "WorkToolFrames(...)",
    "wrong shape tool (3, 3)",
    lambda: dispkin.WorkToolFrames(tool=np.eye(3)),
    V,
    "tool: expected an array of shape (4, 4), got shape (3, 3)",
)
row(
    "WorkToolFrames.platform_pose", "NaN matrix", lambda: FRAMES.platform_pose(np.full((4, 4), NAN)), V, "matrix = (nan"
)
row(
    "WorkToolFrames.tool_in_work",
    "wrong shape (6,)",
    lambda: FRAMES.tool_in_work([0, 0, 0.2, 0, 0, 0]),
    V,
    "platform: expected an array of shape (4, 4), got shape (6,)",
)
row(
    "WorkToolFrames.platform_pose_xyzuvw",
    "NaN U",
    lambda: FRAMES.platform_pose_xyzuvw([0, 0, 0, NAN, 0, 0]),
    V,
    "xyzuvw = (0, 0, 0, nan, 0, 0)",
)
row(
    "WorkToolFrames.platform_pose_xyzuvw",
    "wrong size (5)",
    lambda: FRAMES.platform_pose_xyzuvw([0] * 5),
    V,
    "xyzuvw: expected an array of shape (6,), got shape (5,)",
)
row(
    "WorkToolFrames.add_tool_envelope",
    "zero radius",
    lambda: FRAMES.add_tool_envelope(good_set(), 0.0),
    V,
    "radius = 0",
)
row(
    "WorkToolFrames.add_tool_envelope",
    "NaN radius",
    lambda: FRAMES.add_tool_envelope(good_set(), NAN, "sphere"),
    V,
    "radius = nan",
)
row(
    "WorkToolFrames.add_tool_envelope",
    "unknown envelope",
    lambda: FRAMES.add_tool_envelope(good_set(), 0.1, "cube"),
    V,
    "envelope = \"cube\": must be \"icosahedron\" or \"sphere\"",
)
row(
    "WorkToolFrames.add_work_envelope",
    "negative radius",
    lambda: FRAMES.add_work_envelope(good_set(), -0.1),
    V,
    "radius = -0.1",
)
row(
    "WorkToolFrames.add_work_envelope",
    "negative group",
    lambda: FRAMES.add_work_envelope(good_set(), 0.1, group=-1),
    V,
    "group = -1",
)

# --- SerialArm (tests/data/urdf/arm_*.urdf) -------------------------------------------------
URDF = pathlib.Path(__file__).resolve().parents[1] / "data" / "urdf"
PLANAR = str(URDF / "arm_planar_two_link.urdf")


def arm():
    return dispkin.SerialArm.from_urdf(PLANAR, "base", "link2")


row(
    "SerialArm.from_urdf",
    "missing file",
    lambda: dispkin.SerialArm.from_urdf("/nonexistent/arm.urdf", "a", "b"),
    V,
    "path = \"/nonexistent/arm.urdf\": cannot be opened",
)
row(
    "SerialArm.from_urdf",
    "not XML",
    lambda: dispkin.SerialArm.from_urdf(str(URDF / "arm_bad_not_xml.urdf"), "base", "l1"),
    V,
    "URDF: not a valid robot description",
)
row(
    "SerialArm.from_urdf",
    "XML text without <robot>",
    lambda: dispkin.SerialArm.from_urdf("<model/>", "base", "l1"),
    V,
    "URDF: not a valid robot description: Could not find the 'robot' element",
)
row(
    "SerialArm.from_urdf",
    "unknown base link",
    lambda: dispkin.SerialArm.from_urdf(PLANAR, "nowhere", "link2"),
    V,
    "base_link = \"nowhere\": is not a link of robot \"planar_two_link\"",
)
row(
    "SerialArm.from_urdf",
    "unknown tip link",
    lambda: dispkin.SerialArm.from_urdf(PLANAR, "base", "nowhere"),
    V,
    "tip_link = \"nowhere\": is not a link",
)
row(
    "SerialArm.from_urdf",
    "base not an ancestor",
    lambda: dispkin.SerialArm.from_urdf(PLANAR, "link2", "link1"),
    V,
    "base_link = \"link2\": is not an ancestor of tip_link \"link1\"",
)
row(
    "SerialArm.from_urdf",
    "prismatic joint on the path",
    lambda: dispkin.SerialArm.from_urdf(PLANAR, "base", "finger"),
    V,
    "joint \"finger_joint\" between \"link2\" and \"finger\": only revolute, continuous and fixed joints",
)
row(
    "SerialArm.from_urdf",
    "lower above upper",
    lambda: dispkin.SerialArm.from_urdf(str(URDF / "arm_bad_limits.urdf"), "base", "l1"),
    V,
    "joint \"j1\" limit (lower, upper) = (1, -1): needs lower < upper",
)
row(
    "SerialArm.from_urdf",
    "empty base link",
    lambda: dispkin.SerialArm.from_urdf(PLANAR, "", "link2"),
    V,
    "base_link = \"\": must name a link",
)
row(
    "SerialArm.forward",
    "wrong size q (3)",
    lambda: arm().forward([0, 0, 0]),
    V,
    "q = (0, 0, 0): expected 2 joint values, got 3",
)
row(
    "SerialArm.forward",
    "wrong shape q (2, 1)",
    lambda: arm().forward([[0], [0]]),
    V,
    "q: expected an array of shape (n,), got shape (2, 1)",
)
row("SerialArm.forward", "NaN q", lambda: arm().forward([0, NAN]), V, "q = (0, nan): must be finite")
row("SerialArm.inverse", "NaN matrix", lambda: arm().inverse(np.full((4, 4), NAN)), V, "matrix = (nan")
row(
    "SerialArm.inverse_many",
    "one (4, 4) matrix",
    lambda: arm().inverse_many(np.eye(4)),
    V,
    "poses: expected an array of shape (N, 4, 4) or a sequence of Poses, got shape (4, 4)",
)
row(
    "SerialArm.inverse_many",
    "NaN in the second pose",
    lambda: arm().inverse_many(np.array([np.eye(4), np.full((4, 4), NAN)])),
    V,
    "poses[1] matrix = (nan",
)
row(
    "SerialArm.inverse_many",
    "sheared rotation in a list",
    lambda: arm().inverse_many(
        [dispkin.Pose(), np.array([[1, 0.5, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1.0]])]
    ),
    V,
    "poses[1] rotation = (",
)
row(
    "SerialArm.inverse_solutions",
    "zero max_attempts",
    lambda: arm().inverse_solutions(dispkin.Pose(), max_attempts=0),
    V,
    "max_attempts = 0: must be greater than zero",
)
row(
    "SerialArm.inverse_solutions",
    "negative time_budget",
    lambda: arm().inverse_solutions(dispkin.Pose(), time_budget=-1.0),
    V,
    "time_budget = -1: must be finite and greater than zero",
)
row("SerialArm.jacobian", "+inf q", lambda: arm().jacobian([INF, 0]), V, "q = (inf, 0): must be finite")
row(
    "SerialArm.torques",
    "wrong size qd (1)",
    lambda: arm().torques([0, 0], [0], [0, 0]),
    V,
    "qd = (0): expected 2 joint values, got 1",
)
row(
    "SerialArm.torques", "NaN qdd", lambda: arm().torques([0, 0], [0, 0], [NAN, 0]), V, "qdd = (nan, 0): must be finite"
)
row(
    "SerialArm.static_torques",
    "empty q",
    lambda: arm().static_torques(np.zeros(0)),
    V,
    "q = (): expected 2 joint values, got 0",
)
row(
    "SerialArm.gravity",
    "NaN gravity",
    lambda: setattr(arm(), "gravity", [0, 0, NAN]),
    V,
    "gravity = (0, 0, nan): must be finite",
)
row(
    "SerialArm.gravity",
    "wrong size gravity (2)",
    lambda: setattr(arm(), "gravity", [0, 0]),
    V,
    "gravity: expected an array of shape (3,), got shape (2,)",
)
row(
    "SerialArm.configuration",
    "not a 6R arm",
    lambda: arm().configuration([0, 0]),
    V,
    "dof = 2: configuration flags are defined for 6R arms",
)
row(
    "SerialArm.nearest",
    "no solutions",
    lambda: dispkin.SerialArm.nearest([], [0, 0]),
    V,
    "solutions = 0: must not be empty",
)
row(
    "SerialArm.nearest",
    "wrong size q_ref",
    lambda: dispkin.SerialArm.nearest([np.zeros(6)], [0, 0]),
    V,
    "q_ref = (0, 0): expected 6 joint values like the solutions, got 2",
)
row(
    "SerialArm.follow",
    "unreachable pose",
    lambda: arm().follow([dispkin.Pose((1, 0, 0, 0), (5, 0, 0))], [0, 0]),
    RuntimeError,
    "poses[0] translation = (5, 0, 0): has no inverse-kinematics solution",
)
row(
    "SerialArm.follow",
    "negative gain",
    lambda: arm().follow([dispkin.Pose()], [0, 0], gain=-1.0),
    V,
    "redundancy_rule.gain = -1: must be finite and at least 0",
)
row(
    "SerialArm.follow",
    "NaN max_rate",
    lambda: arm().follow([dispkin.Pose()], [0, 0], max_rate=NAN),
    V,
    "redundancy_rule.max_rate = nan: must be finite and at least 0",
)
row(
    "SerialArm.follow",
    "+inf singularity_weight",
    lambda: arm().follow([dispkin.Pose()], [0, 0], singularity_weight=INF),
    V,
    "redundancy_rule.singularity_weight = inf: must be finite and at least 0",
)


# --- check_joint_limits / retime (UR5e) ---------------------------------------------------
def ur5e():
    return dispkin.SerialArm.from_urdf(str(URDF / "arm_ur5e_dh.urdf"), "base_link", "tool0")


Q_UR = [0.3, -1.2, 1.5, -1.9, -1.57, 0.2]


def ur_path():
    a = ur5e().forward(Q_UR)
    return dispkin.Path.lin(a, dispkin.Pose(a.quaternion, a.translation + np.array([0.05, 0, 0])))


def ur_trajectory():
    return dispkin.plan(ur_path(), good_set(), LIMITS)


row(
    "SerialArm.with_joint_limits",
    "velocity of the wrong size",
    lambda: ur5e().with_joint_limits(velocity=[1.0, 2.0]),
    V,
    "velocity size = 2",
)
row(
    "SerialArm.with_joint_limits",
    "zero velocity",
    lambda: ur5e().with_joint_limits(velocity=[1, 1, 0, 1, 1, 1]),
    V,
    "joint \"elbow_joint\" velocity = 0",
)
row(
    "SerialArm.with_joint_limits",
    "NaN lower",
    lambda: ur5e().with_joint_limits(lower=[NAN, 0, 0, 0, 0, 0]),
    V,
    "joint \"shoulder_pan_joint\" (lower, upper) = (nan",
)

# --- plan(Path.ptp(...), ..., robot=arm): PTP moves (UR5e) ----------------------------------
PTP_LIMITS = dispkin.Limits(0.1, 1.0, 10.0)
row(
    "plan (PTP)",
    "no robot",
    lambda: dispkin.plan(dispkin.Path.ptp(np.zeros(6), np.full(6, 0.1)), good_set(), PTP_LIMITS),
    V,
    "robot = \"None\": must be a SerialArm",
)
row(
    "plan (PTP)",
    "q_a of the wrong size for the arm",
    lambda: dispkin.plan(dispkin.Path.ptp(np.zeros(5), np.ones(5)), good_set(), PTP_LIMITS, robot=ur5e()),
    V,
    "q_a size = 5: must be the arm's dof 6",
)
row(
    "plan (PTP)",
    "q_b outside the joint range",
    lambda: dispkin.plan(dispkin.Path.ptp(np.zeros(6), [0, 7.0, 0, 0, 0, 0]), good_set(), PTP_LIMITS, robot=ur5e()),
    V,
    "q_b[1] = 7: is outside the position limits",
)
row(
    "plan (PTP)",
    "q_b equal to q_a",
    lambda: dispkin.plan(dispkin.Path.ptp(np.zeros(6), np.zeros(6)), good_set(), PTP_LIMITS, robot=ur5e()),
    V,
    "equals q_a: a PTP move must move",
)
row(
    "plan (PTP)",
    "zero tolerance",
    lambda: dispkin.plan(
        dispkin.Path.ptp(np.zeros(6), np.full(6, 0.1)), good_set(), PTP_LIMITS, robot=ur5e(), tolerance=0.0
    ),
    V,
    "tolerance = 0: must be in (0, 0.5]",
)
row(
    "plan (PTP)",
    "negative joint acceleration",
    lambda: dispkin.plan(
        dispkin.Path.ptp(np.zeros(6), np.full(6, 0.1)),
        good_set(),
        PTP_LIMITS,
        robot=ur5e(),
        joint_acceleration=[1, 1, -1, 1, 1, 1],
    ),
    V,
    "joint_acceleration[2] = -1: must be > 0",
)
row(
    "Path.ptp",
    "NaN q_b",
    lambda: dispkin.Path.ptp(np.zeros(6), [0, 0, NAN, 0, 0, 0]),
    V,
    "q_end = (0, 0, nan, 0, 0, 0): must be finite",
)
row(
    "JointTrajectory.sample",
    "times of shape (2, 2)",
    lambda: dispkin.plan(dispkin.Path.ptp(np.zeros(6), np.full(6, 0.1)), good_set(), PTP_LIMITS, robot=ur5e()).sample(
        np.zeros((2, 2))
    ),
    V,
    "times: expected a number or an array of shape (N,), got shape (2, 2)",
)

# --- limits files (dispkin.limits_files) ----------------------------------------------------
from dispkin import limits_files  # noqa: E402

LIMITS_FILE = pathlib.Path(_TMP) / "limits.yaml"


def limits_file(text):
    LIMITS_FILE.write_text(text)
    return LIMITS_FILE


row(
    "read_moveit_joint_limits",
    "missing file",
    lambda: limits_files.read_moveit_joint_limits("/nonexistent/joint_limits.yaml"),
    V,
    "cannot be read",
)
row(
    "read_moveit_joint_limits",
    "negative max_velocity",
    lambda: limits_files.read_moveit_joint_limits(
        limits_file("joint_limits:\n  j1:\n    has_velocity_limits: true\n    max_velocity: -2\n")
    ),
    V,
    "joint_limits.j1.max_velocity = -2: must be > 0",
)
row(
    "read_moveit_joint_limits",
    "+inf max_acceleration",
    lambda: limits_files.read_moveit_joint_limits(
        limits_file("joint_limits:\n  j1:\n    has_acceleration_limits: true\n    max_acceleration: .inf\n")
    ),
    V,
    "joint_limits.j1.max_acceleration = inf: must be finite",
)
row(
    "apply_moveit_joint_limits",
    "unknown joint",
    lambda: limits_files.apply_moveit_joint_limits(
        ur5e(), limits_file("joint_limits:\n  j1:\n    has_velocity_limits: true\n    max_velocity: 2\n")
    ),
    V,
    "joint_limits.j1: not a joint of the arm",
)
row(
    "read_pilz_cartesian_limits",
    "positive max_trans_dec",
    lambda: limits_files.read_pilz_cartesian_limits(
        limits_file("cartesian_limits: {max_trans_vel: 1, max_trans_acc: 2, max_trans_dec: 3, max_rot_vel: 1}\n")
    ),
    V,
    "cartesian_limits.max_trans_dec = 3: must be < 0",
)
row(
    "read_pilz_cartesian_limits",
    "zero max_rot_vel",
    lambda: limits_files.read_pilz_cartesian_limits(
        limits_file("cartesian_limits: {max_trans_vel: 1, max_trans_acc: 2, max_trans_dec: -3, max_rot_vel: 0}\n")
    ),
    V,
    "cartesian_limits.max_rot_vel = 0: must be > 0",
)

row(
    "check_joint_limits",
    "negative samples_between",
    lambda: dispkin.check_joint_limits(ur_trajectory(), ur5e(), Q_UR, samples_between=-1),
    V,
    "samples_between = -1",
)
row(
    "check_joint_limits",
    "q_start of the wrong size",
    lambda: dispkin.check_joint_limits(ur_trajectory(), ur5e(), Q_UR[:5]),
    V,
    "q_start size = 5",
)
row(
    "check_joint_limits",
    "NaN q_start",
    lambda: dispkin.check_joint_limits(ur_trajectory(), ur5e(), [NAN] * 6),
    V,
    "q_start = (nan",
)
row(
    "retime",
    "unknown method",
    lambda: dispkin.retime(ur_path(), good_set(), LIMITS, ur5e(), Q_UR, method="fastest"),
    V,
    "method = \"fastest\"",
)
row(
    "retime",
    "optimal S-curve without a jerk limit",
    lambda: dispkin.retime(ur_path(), good_set(), TRAPEZOID_LIMITS, ur5e(), Q_UR, method="optimal"),
    V,
    "jerk is missing",
)
row(
    "retime",
    "optimal, 1 grid interval",
    lambda: dispkin.retime(
        ur_path(), good_set(), TRAPEZOID_LIMITS, ur5e(), Q_UR, profile="trapezoid", method="optimal", grid_intervals=1
    ),
    V,
    "grid_intervals = 1",
)
row(
    "retime",
    "optimal, joint_acceleration of wrong size",
    lambda: dispkin.retime(
        ur_path(),
        good_set(),
        TRAPEZOID_LIMITS,
        ur5e(),
        Q_UR,
        profile="trapezoid",
        method="optimal",
        joint_acceleration=[1.0, 2.0],
    ),
    V,
    "joint_acceleration size = 2",
)
row(
    "retime",
    "optimal, negative joint_acceleration",
    lambda: dispkin.retime(
        ur_path(),
        good_set(),
        TRAPEZOID_LIMITS,
        ur5e(),
        Q_UR,
        profile="trapezoid",
        method="optimal",
        joint_acceleration=[1.0, 1.0, -1.0, 1.0, 1.0, 1.0],
    ),
    V,
    "joint_acceleration[2] = -1",
)
row(
    "retime",
    "optimal with a jerk limit",
    lambda: dispkin.retime(ur_path(), good_set(), LIMITS, ur5e(), Q_UR, profile="trapezoid", method="optimal"),
    V,
    "jerk",
)
row(
    "retime",
    "unknown profile",
    lambda: dispkin.retime(ur_path(), good_set(), LIMITS, ur5e(), Q_UR, profile="sine"),
    V,
    "profile = \"sine\"",
)
row(
    "retime",
    "zero max_iterations",
    lambda: dispkin.retime(ur_path(), good_set(), LIMITS, ur5e(), Q_UR, max_iterations=0),
    V,
    "max_iterations = 0",
)

# --- job files (dispkin.jobs.load_job) and the command line (dispkin.cli.main) --------------
import contextlib  # noqa: E402
import io  # noqa: E402
import os  # noqa: E402

from dispkin import cli, jobs  # noqa: E402

JOB_DIR = pathlib.Path(_TMP) / "jobs"
JOB_DIR.mkdir()
GOOD_JOB = """metric_set:
  points:
    - relative: [[0, 0, 0.3]]
    - {shape: sphere, radius: 0.1, center: [0, 0, 0]}
start: {xyzuvw: [0, 0, 0, 0, 0, 0]}
moves:
  - lin: {to: {xyzuvw: [0.05, 0.02, 0, 10, 0, 30]}}
limits: {velocity: 0.1, acceleration: 0.5, jerk: 5.0}
"""


def job_file(name, text=None, data=None):
    """A job file `name` in the table's temporary directory: `text`, or GOOD_JOB with the
    (old, new) replacements in `data` (bytes are written as they are)."""
    path = JOB_DIR / name
    if isinstance(text, bytes):
        path.write_bytes(text)
    else:
        if text is None:
            text = GOOD_JOB
            for old, new in data or ():
                assert old in text, old
                text = text.replace(old, new)
        path.write_text(text)
    return str(path)


class ExitStatus(Exception):
    """A non-zero exit of dispkin.cli.main, as the table's exception: the message is the exit
    status and what the command wrote to stderr (without argparse's usage lines)."""


def run_cli(*argv):
    """dispkin.cli.main(argv) run in the table's job directory (file names in the messages are
    then as given) with stdout and stderr captured; raises ExitStatus if it fails."""
    err = io.StringIO()
    here = os.getcwd()
    os.chdir(JOB_DIR)
    try:
        with contextlib.redirect_stderr(err), contextlib.redirect_stdout(io.StringIO()):
            status = cli.main(list(argv))
    except SystemExit as exit:  # argparse
        status = exit.code
    finally:
        os.chdir(here)
    if status != 0:
        lines = err.getvalue().splitlines()
        while lines and (lines[0].startswith("usage:") or lines[0].startswith(" ")):
            lines.pop(0)
        raise ExitStatus(f"exit status {status}: " + "\n".join(lines))
    return status


def missing_job():
    return str(JOB_DIR / "missing.yaml")


row(
    "jobs.load_job",
    "missing file",
    lambda: jobs.load_job(missing_job()),
    V,
    "missing.yaml: cannot read the job file: No such file or directory",
)
row(
    "jobs.load_job",
    "not UTF-8",
    lambda: jobs.load_job(job_file("latin1.yaml", b"name: d\xe9mo\n")),
    V,
    "latin1.yaml:1:8: the job file is not UTF-8 text: byte 0xe9",
)
row(
    "jobs.load_job",
    "empty file",
    lambda: jobs.load_job(job_file("empty.yaml", "")),
    V,
    "empty.yaml: the job file is empty",
)
row(
    "jobs.load_job",
    "malformed YAML (unclosed bracket)",
    lambda: jobs.load_job(job_file("malformed.yaml", data=[("jerk: 5.0}", "jerk: 5.0")])),
    V,
    "malformed.yaml:9:1: not valid YAML: expected ',' or '}', but got '<stream end>'",
)
row(
    "jobs.load_job",
    "not a mapping",
    lambda: jobs.load_job(job_file("list.yaml", "- lin\n- circ\n")),
    V,
    "list.yaml:1:1: (job): a job is a mapping of keys",
)
row(
    "jobs.load_job",
    "NaN velocity limit",
    lambda: jobs.load_job(job_file("nan_limit.yaml", data=[("velocity: 0.1", "velocity: .nan")])),
    V,
    "nan_limit.yaml:8:10: limits.velocity: nan: must be finite",
)
row(
    "jobs.load_job",
    "+inf acceleration limit",
    lambda: jobs.load_job(job_file("inf_limit.yaml", data=[("acceleration: 0.5", "acceleration: .inf")])),
    V,
    "inf_limit.yaml:8:25: limits.acceleration: inf: must be finite",
)
row(
    "jobs.load_job",
    "zero velocity limit",
    lambda: jobs.load_job(job_file("zero_limit.yaml", data=[("velocity: 0.1", "velocity: 0")])),
    V,
    "zero_limit.yaml:8:10: limits.velocity: 0 is less than or equal to the minimum of 0",
)
row(
    "jobs.load_job",
    "negative sphere radius",
    lambda: jobs.load_job(job_file("radius.yaml", data=[("radius: 0.1", "radius: -0.1")])),
    V,
    "radius.yaml:4:23: metric_set.points[1].radius: -0.1 is less than or equal to the minimum of 0",
)
row(
    "jobs.load_job",
    "both center and centre",
    lambda: jobs.load_job(job_file("both.yaml", data=[("center: [0, 0, 0]", "center: [0, 0, 0], centre: [0, 0, 0]")])),
    V,
    "both.yaml:4:55: metric_set.points[1].centre: `centre` is an alias of `center`: give one of them, not both",
)
row(
    "jobs.load_job",
    "NaN center",
    lambda: jobs.load_job(job_file("nan_center.yaml", data=[("center: [0, 0, 0]", "center: [0, .nan, 0]")])),
    V,
    "nan_center.yaml:4:48: metric_set.points[1].center[1]: nan: must be finite",
)
row(
    "cli.main",
    "unknown option",
    lambda: run_cli("plan", pathlib.Path(job_file("good.yaml")).name, "--bogus"),
    ExitStatus,
    "exit status 2: dispkin: error: unrecognized arguments: --bogus",
)
row(
    "cli.main",
    "no command",
    lambda: run_cli(),
    ExitStatus,
    "exit status 2: dispkin: error: the following arguments are required: COMMAND",
)
row(
    "cli.main",
    "unknown command",
    lambda: run_cli("run", "good.yaml"),
    ExitStatus,
    "exit status 2: dispkin: error: argument COMMAND: invalid choice: 'run'",
)
row(
    "cli.main",
    "demo --moves 0",
    lambda: run_cli("demo", "--moves", "0", "--no-job", "-q"),
    ExitStatus,
    "exit status 2: dispkin demo: error: argument --moves: must be a positive integer, got 0",
)
row(
    "cli.main",
    "demo --moves not a number",
    lambda: run_cli("demo", "--moves", "many", "--no-job", "-q"),
    ExitStatus,
    "exit status 2: dispkin demo: error: argument --moves: must be a positive integer, got 'many'",
)
row(
    "cli.main",
    "check of a missing file",
    lambda: run_cli("check", "missing.yaml"),
    ExitStatus,
    "exit status 1: dispkin check: missing.yaml: cannot read the job file: No such file or directory",
)
row(
    "cli.main",
    "check of malformed YAML",
    lambda: run_cli("check", pathlib.Path(job_file("malformed_cli.yaml", data=[("jerk: 5.0}", "jerk: 5.0")])).name),
    ExitStatus,
    "exit status 1: dispkin check: malformed_cli.yaml:9:1: not valid YAML: expected ',' or '}', but got '<stream end>'",
)
row(
    "cli.main",
    "plan of a job with a NaN limit",
    lambda: run_cli(
        "plan", pathlib.Path(job_file("nan_plan.yaml", data=[("jerk: 5.0", "jerk: .nan")])).name, "-o", "out"
    ),
    ExitStatus,
    "exit status 1: dispkin plan: nan_plan.yaml:8:44: limits.jerk: nan: must be finite",
)

# --- hostile inputs (doc/input-budget.md) -----------------------------------------------
PLANAR_URDF = (URDF / "arm_planar_two_link.urdf").read_text()


def planar(old, new):
    assert old in PLANAR_URDF, old
    return dispkin.SerialArm.from_urdf(PLANAR_URDF.replace(old, new, 1), "base", "link2")


def ur5e_within(bound):
    return ur5e().with_joint_limits(lower=[-bound] * 6, upper=[bound] * 6)


def hostile_job(name, text):
    return jobs.load_job(job_file(name, text))


HOSTILE_JOB_TAIL = "start: {xyzuvw: [0, 0, 0, 0, 0, 0]}\nmoves:\n  - lin: {to: {xyzuvw: [0.1, 0, 0, 0, 0, 0]}}\nlimits: {velocity: 0.1, acceleration: 1.0, jerk: 10}\n"
BOMB = "a: &a [1, 1, 1, 1, 1, 1, 1, 1, 1]\n" + "".join(
    f"{c}: &{c} [{', '.join(['*' + p] * 9)}]\n" for p, c in zip("abcdefgh", "bcdefghi")
)

section("Nesting depth")
row(
    "Hexapod.from_json",
    "arrays nested 10⁵ deep (was a segmentation fault)",
    lambda: dispkin.Hexapod.from_json("[" * 100_000 + "]" * 100_000),
    V,
    "description nesting depth = 101: arrays and objects nest at most 100 deep",
)
row(
    "Hexapod.from_json",
    "objects nested 101 deep",
    lambda: dispkin.Hexapod.from_json('{"a":' * 101 + "1" + "}" * 101),
    V,
    "description nesting depth = 101",
)
row(
    "SerialArm.from_urdf",
    "XML nested 4·10⁴ deep (was a segmentation fault)",
    lambda: planar('<link name="base"/>', '<link name="base"/>' + "<a>" * 40_000 + "</a>" * 40_000),
    V,
    "nests deeper than 100 elements",
)
row(
    "jobs.load_job",
    "lists nested 1000 deep (was a RecursionError)",
    lambda: hostile_job("deep.yaml", "name: " + "[" * 1000 + "]" * 1000 + "\n"),
    V,
    "deep.yaml:1:38: (job): mappings and lists nest deeper than 32 levels",
)
row(
    "jobs.load_job",
    "an alias inside its own anchor",
    lambda: hostile_job("cycle.yaml", "metric_set: &m\n  points: [*m]\n"),
    V,
    "cycle.yaml:2:12: (job): the alias *m is inside its own anchor",
)

section("Sizes and counts")
row(
    "Hexapod.from_json",
    "text over 1 MiB",
    lambda: dispkin.Hexapod.from_json(" " * (2**20 + 1)),
    V,
    "description size = 1048577: more than 1048576 bytes, the limit of a hexapod description",
)
row(
    "Hexapod.from_json",
    "6000 legs (message not echoing them)",
    lambda: dispkin.Hexapod.from_json(hexapod_json(legs=LEGS * 1000)),
    V,
    ", … 6000 items]\": must be an array of 6 leg objects",
)
row(
    "SerialArm.from_urdf",
    "4·10⁴ attributes on <robot> (was 34 s)",
    lambda: planar(
        '<robot name="planar_two_link"', '<robot name="planar_two_link"' + "".join(f' a{i}="1"' for i in range(40_000))
    ),
    V,
    "has more than 100 attributes",
)
row(
    "jobs.load_job",
    "an alias bomb (9 lines, 3.9·10⁸ values)",
    lambda: hostile_job("bomb.yaml", BOMB),
    V,
    "bomb.yaml:6:32: (job): the job expands to more than 500000 values",
)
row(
    "jobs.load_job",
    "a value of 5000 characters",
    lambda: hostile_job("long.yaml", "name: " + "x" * 5000 + "\n"),
    V,
    "long.yaml:1:7: (job): a value of 5000 characters, more than 4096",
)
row(
    "jobs.load_job",
    "sample_period 1e-9",
    lambda: hostile_job("tiny.yaml", GOOD_JOB + "output: {sample_period: 1.0e-9}\n"),
    V,
    "tiny.yaml:9:10: output.sample_period: 1e-09: must be at least 1e-06 s",
)
row(
    "jobs.load_job",
    "integer beyond 64 bits",
    lambda: hostile_job("huge.yaml", GOOD_JOB.replace("jerk: 5.0", "jerk: 123456789012345678901234567890")),
    V,
    "huge.yaml:8:44: limits.jerk: an integer of 97 bits: numbers must be within ±2^53",
)

section("Inverse kinematics with wide joint limits")
accepted(
    "SerialArm.inverse",
    "joint limits ±1e16 rad",
    lambda: ur5e_within(1e16).inverse(ur5e().forward(Q_UR)),
    lambda solutions: len(solutions) == 8 and all(np.abs(q).max() <= np.pi + 1e-9 for q in solutions),
    "the 8 distinct solutions, every joint the 2π copy nearest 0 (was: none)",
)
row(
    "SerialArm.inverse",
    "2π copies of ±100 rad limits (was 23.6 GB)",
    lambda: ur5e_within(100.0).inverse(ur5e().forward(Q_UR), offer_equivalents=True),
    V,
    "offer_equivalents = \"true\": asks for the 2π copies of the 8 solutions inside the joint limits",
)

section("URDF numbers and joint graph")
row(
    "SerialArm.from_urdf",
    "NaN mass (was dropped)",
    lambda: planar('<mass value="2.0"/>', '<mass value="nan"/>'),
    V,
    'link "link1" inertial mass = nan: must be finite (line 22)',
)
row(
    "SerialArm.from_urdf",
    "infinite mass",
    lambda: planar('<mass value="2.0"/>', '<mass value="inf"/>'),
    V,
    'link "link1" inertial mass = inf: must be finite',
)
row(
    "SerialArm.from_urdf",
    "NaN ixx",
    lambda: planar('ixx="0.11"', 'ixx="nan"'),
    V,
    'link "link1" inertial inertia ixx = nan: must be finite',
)
row(
    "SerialArm.from_urdf",
    "NaN inertial origin",
    lambda: planar('<origin xyz="0.4 0 0"', '<origin xyz="0.4 nan 0"'),
    V,
    'link "link1" inertial origin xyz = (0.4, nan, 0): must be finite',
)
row(
    "SerialArm.torques",
    "a link with a negative principal moment",
    lambda: planar('ixx="0.11"', 'ixx="-0.11"').static_torques([0, 0]),
    V,
    'link "link1" inertial inertia (ixx, ixy, ixz, iyy, iyz, izz) = (-0.11, 0, 0, 0.01, 0, 0.12): is not positive semidefinite',
)
row(
    "SerialArm.torques",
    "a link breaking the triangle inequality",
    lambda: planar('ixx="0.11"', 'ixx="0.5"').static_torques([0, 0]),
    V,
    "(0.5, 0, 0, 0.01, 0, 0.12): is not the inertia of a body: its principal moments break the triangle inequality",
)
row(
    "SerialArm.from_urdf",
    "joint origin 1e300 m",
    lambda: planar('<origin xyz="0 0 0.3"', '<origin xyz="0 0 1e300"'),
    V,
    'joint "mount_joint" origin xyz = (0, 0, 1e+300): must be within ±1e12',
)
row(
    "SerialArm.from_urdf",
    "mass not a number",
    lambda: planar('<mass value="2.0"/>', '<mass value="2 kg"/>'),
    V,
    'link "link1" inertial mass = "2 kg": must be a number',
)
row(
    "SerialArm.from_urdf",
    "a link with two parent joints (was: one dropped)",
    lambda: planar(
        "</robot>", '<joint name="again" type="fixed"><parent link="base"/><child link="link2"/></joint></robot>'
    ),
    V,
    'link = "link2": is the child of two joints, "elbow" and "again"',
)

section("Hexapod descriptions and encodings")
row(
    "Hexapod.from_json",
    "leg speed 5e-324 (was accepted)",
    lambda: dispkin.Hexapod.from_json(hexapod_json(legs=leg_changed(speed=5e-324))),
    V,
    "leg_speed[0] = 4.94065645841e-324: must be in [1e-12, 1e12]",
)
row(
    "Hexapod.from_json",
    "leg speed 1e300",
    lambda: dispkin.Hexapod.from_json(hexapod_json(legs=leg_changed(speed=1e300))),
    V,
    "leg_speed[0] = 1e+300: must be in [1e-12, 1e12]",
)
row(
    "Hexapod.from_json",
    "misspelt per-leg key",
    lambda: dispkin.Hexapod.from_json(hexapod_json(legs=leg_changed(sped=0.01))),
    V,
    "legs[0].sped = 0.01: unknown key (allowed here: base, platform, min, max, speed)",
)
row(
    "Hexapod.from_json",
    "invalid UTF-8 in a string (was UnicodeDecodeError)",
    lambda: dispkin.Hexapod.from_json(hexapod_json(units="m").encode().replace(b'"m"', b'"m\xff"')),
    V,
    "ill-formed UTF-8 byte; last read: '\"m\\xff",
)
row(
    "Hexapod.load",
    "invalid UTF-8 bytes in the file",
    lambda: dispkin.Hexapod.load(job_file("latin1.json", hexapod_json(units="m").encode().replace(b'"m"', b'"m\xe9"'))),
    V,
    "ill-formed UTF-8 byte; last read: '\"m\\xe9",
)

section("Ignored arguments and degenerate geometry")
row(
    "retime",
    "scaling method with joint_acceleration (was ignored)",
    lambda: dispkin.retime(ur_path(), good_set(), LIMITS, ur5e(), Q_UR, joint_acceleration=np.ones(6)),
    V,
    'joint_acceleration = (1, 1, 1, 1, 1, 1): is not a limit of method="scaling"',
)
row(
    "Path.circ",
    "via 1e-9 m off the line beyond the end (was a 9.4·10⁷ m arc)",
    lambda: dispkin.Path.circ(A, dispkin.Pose.from_xyzuvw([0.2, 1e-9, 0, 0, 0, 0]), B),
    V,
    "via = (0.2, 1e-09, 0): is almost collinear with the start and end points and outside the segment between them",
)

section("URDF text, per-move limits and gravity")
PERCENT_LINK = '<robot name="r"><link name="l{}n"/></robot>'
for spelling, bad in [
    ("&#0000000000000000000000037;", "'%' as a zero-padded decimal character reference"),
    ("&#x100000025;", "'%' as a hexadecimal reference TinyXML wraps at 2^32"),
    ("&#4294967333;", "'%' as a decimal reference wrapping at 2^32 (Latin-1 document)"),
]:
    text = PERCENT_LINK.format(spelling)
    if "4294967333" in spelling:
        text = '<?xml version="1.0" encoding="ISO-8859-1"?>' + text
    row(
        "SerialArm.from_urdf",
        bad,
        lambda text=text: dispkin.SerialArm.from_urdf(text, "l%n", "b"),
        V,
        '<link> attribute "name" = "l%n": contains \'%\' (character references decoded)',
    )
row(
    "Path.lin",
    "move velocity 1e-17 (below the numeric range)",
    lambda: dispkin.Path.lin(A, B, velocity=1e-17),
    V,
    "velocity = 1e-17: must be in [1e-12, 1e12]",
)
row(
    "Path.lin",
    "move acceleration 1e13",
    lambda: dispkin.Path.lin(A, B, acceleration=1e13),
    V,
    "acceleration = 1e+13: must be in [1e-12, 1e12]",
)
row(
    "Path.circ",
    "move velocity 5e-324",
    lambda: dispkin.Path.circ(A, dispkin.Pose.from_xyzuvw([0.1, 0.05, 0, 0, 0, 0]), B, velocity=5e-324),
    V,
    "velocity = 4.94065645841e-324: must be in [1e-12, 1e12]",
)
row(
    "jobs.load_job",
    "a move's velocity 1e-17 before more moves (the trajectory ended after the first)",
    lambda: jobs.load_job(
        job_file(
            "tiny_move_velocity.yaml",
            data=[
                (
                    "  - lin: {to: {xyzuvw: [0.05, 0.02, 0, 10, 0, 30]}}\n",
                    "  - lin: {to: {xyzuvw: [0.05, 0.02, 0, 10, 0, 30]}}\n    velocity: 1.0e-17\n"
                    "  - lin: {to: {xyzuvw: [0.1, 0.02, 0, 10, 0, 30]}}\n",
                )
            ],
        )
    ),
    V,
    "tiny_move_velocity.yaml:8:5: moves[0].velocity: 1e-17: must be in [1e-12, 1e12]",
)
row(
    "SerialArm.gravity",
    "gravity 1e308 (NaN torques)",
    lambda: setattr(arm(), "gravity", [0, 0, 1e308]),
    V,
    "gravity = (0, 0, 1e+308): must have coordinates within ±1e12 m/s²",
)

section("Command line, second round")
UR_JOB = """name: ur
machine:
  serial_arm: {{urdf: {urdf}, base_link: base_link, tip_link: tool0, q_start: [0.0, -1.9, 1.9, -1.57, -1.57, 0.0]}}
metric_set:
  points:
    - relative: [[0, 0, 0.15]]
    - {{shape: sphere, radius: 0.04, center: [0, 0, 0]}}
moves:
  - lin: {{by: {{xyzuvw: [0.2, 0.1, -0.1, 0, 0, 30]}}}}
limits: {{velocity: 0.25, acceleration: 1.0, jerk: 10.0}}
"""


def ur_job(name, *lines):
    """The UR5e LIN move of examples/jobs/ur5e_lin_move.yaml in the job directory, `lines` appended."""
    return pathlib.Path(
        job_file(name, UR_JOB.format(urdf=URDF / "arm_ur5e_dh.urdf") + "".join(line + "\n" for line in lines))
    ).name


def named_limits_file(name, text):
    path = JOB_DIR / name
    path.write_bytes(text) if isinstance(text, bytes) else path.write_text(text)
    return str(path)


def effort_limit(joint, value):
    return f"joint_limits:\n  {joint}:\n    has_effort_limits: true\n    max_effort: {value}\n"


def special(name, make):
    """A FIFO or directory `name` in the job directory (made once)."""
    path = JOB_DIR / name
    if not path.exists():
        make(path)
    return path.name


# Eight anchors, each repeating the one before nine times: 9^8 = 4.3e7 values from nine lines.
BOMB_LIMITS = (
    "a: &a [x, x, x, x, x, x, x, x, x]\n"
    + "".join(f"{c}: &{c} [" + ", ".join([f"*{p}"] * 9) + "]\n" for p, c in zip("abcdefg", "bcdefgh"))
    + "joint_limits: {elbow_joint: *h}\n"
)

# Between the samples (every 0.01 s) shoulder_pan_joint needs 3.927 N·m, at them at most 3.842.
row(
    "cli.main",
    "plan: an effort limit broken only between samples (was exit 0)",
    lambda: run_cli(
        "plan",
        ur_job(
            "effort_between.yaml",
            f"limits_file: {named_limits_file('pan_3.9.yaml', effort_limit('shoulder_pan_joint', 3.9))}",
        ),
        "-o",
        "out",
    ),
    ExitStatus,
    "exit status 3: dispkin plan: effort_between.yaml: the trajectory breaks 1 machine limit(s) (use --allow-violations to accept it):\n"
    "  effort of shoulder_pan_joint: ",
)
row(
    "cli.main",
    "plan: a static torque beyond its effort limit (was a RuntimeError traceback)",
    lambda: run_cli(
        "plan",
        ur_job(
            "effort_static.yaml",
            f"limits_file: {named_limits_file('lift_5.yaml', effort_limit('shoulder_lift_joint', 5.0))}",
        ),
        "-o",
        "out",
    ),
    ExitStatus,
    "exit status 3: dispkin plan: effort_static.yaml: the trajectory breaks 1 machine limit(s) (use --allow-violations to accept it):\n"
    "  effort of shoulder_lift_joint: ",
)
row(
    "cli.main",
    "plan: output.csv '..' (was an IsADirectoryError traceback)",
    lambda: run_cli("plan", ur_job("dotdot.yaml", "output: {csv: '..'}"), "-o", "out"),
    ExitStatus,
    "exit status 1: dispkin plan: dotdot.yaml:11:10: output.csv: '..': a file name, not a path (the directory is `-o OUTDIR`)",
)
row(
    "cli.main",
    "plan: a 300-character job name (was an OSError traceback)",
    lambda: run_cli(
        "plan",
        pathlib.Path(job_file("long_name.yaml", data=[("metric_set:", "name: " + "n" * 300 + "\nmetric_set:")])).name,
        "-o",
        "out",
    ),
    ExitStatus,
    "exit status 1: dispkin plan: long_name.yaml:1:1: name: 'nnnnn",
)
row(
    "cli.main",
    "plan -o naming an existing file (was a FileExistsError traceback)",
    lambda: run_cli(
        "plan",
        pathlib.Path(job_file("to_file.yaml")).name,
        "-o",
        pathlib.Path(job_file("a_file.txt", "not a directory\n")).name,
    ),
    ExitStatus,
    "exit status 1: dispkin plan: -o OUTDIR = 'a_file.txt': is not a directory",
)
row(
    "cli.main",
    "plan: output.csv is the job file itself (was overwritten)",
    lambda: run_cli(
        "plan", pathlib.Path(job_file("itself.yaml", GOOD_JOB + "output: {csv: itself.yaml}\n")).name, "-o", "."
    ),
    ExitStatus,
    "exit status 1: dispkin plan: itself.yaml:9:10: output.csv: 'itself.yaml': 'itself.yaml' is the job file (itself.yaml): an input is never overwritten",
)
row(
    "cli.main",
    "plan: output.summary is the job's limits file (was overwritten)",
    lambda: run_cli(
        "plan",
        ur_job(
            "over_limits.yaml",
            f"limits_file: {named_limits_file('pan_4.yaml', effort_limit('shoulder_pan_joint', 4.0))}",
            "output: {summary: pan_4.yaml}",
        ),
        "-o",
        ".",
    ),
    ExitStatus,
    "output.summary: 'pan_4.yaml': 'pan_4.yaml' is a file the job reads (",
)
row(
    "cli.main",
    "check: limits_file a FIFO (was 'does not exist')",
    lambda: run_cli("check", ur_job("fifo_limits.yaml", f"limits_file: {special('limits.fifo', os.mkfifo)}")),
    ExitStatus,
    "fifo_limits.yaml:11:1: limits_file: ",
)
row(
    "cli.main",
    "check: limits_file a directory (was 'does not exist')",
    lambda: run_cli("check", ur_job("dir_limits.yaml", f"limits_file: {special('limits.dir', os.mkdir)}")),
    ExitStatus,
    "limits.dir': is a directory, not a file",
)
row(
    "cli.main",
    "check: the job file is a FIFO (would wait for a writer)",
    lambda: run_cli("check", special("job.fifo", os.mkfifo)),
    ExitStatus,
    "exit status 1: dispkin check: job.fifo: is not a regular file (a FIFO, a device or a socket), not a job file",
)
row(
    "read_moveit_joint_limits",
    "alias bomb of 9 lines (was 1 GB and a 226 MB message)",
    lambda: limits_files.read_moveit_joint_limits(named_limits_file("bomb_limits.yaml", BOMB_LIMITS)),
    limits_files.LimitsFileError,
    "(limits file): the limits file expands to more than 500000 values",
)
row(
    "read_moveit_joint_limits",
    "nesting 1000 deep (was a RecursionError)",
    lambda: limits_files.read_moveit_joint_limits(
        named_limits_file("deep_limits.yaml", "joint_limits: " + "[" * 1000 + "]" * 1000 + "\n")
    ),
    limits_files.LimitsFileError,
    "deep_limits.yaml:1:46: (limits file): mappings and lists nest deeper than 32 levels",
)
row(
    "read_moveit_joint_limits",
    "a 401-digit integer (was an OverflowError)",
    lambda: limits_files.read_moveit_joint_limits(
        named_limits_file("bigint_limits.yaml", effort_limit("elbow_joint", "1" + "0" * 400))
    ),
    limits_files.LimitsFileError,
    "bigint_limits.yaml:4:5: joint_limits.elbow_joint.max_effort = an integer of 1329 bits: must be within ±2^53",
)
row(
    "read_moveit_joint_limits",
    "a Latin-1 byte (was a UnicodeDecodeError)",
    lambda: limits_files.read_moveit_joint_limits(
        named_limits_file("latin1_limits.yaml", b"joint_limits:\n  elbow_joint: # d\xe9mo\n")
    ),
    limits_files.LimitsFileError,
    "latin1_limits.yaml:2:19: the limits file is not UTF-8 text: byte 0xe9",
)
row(
    "read_pilz_cartesian_limits",
    "max_rot_vel 1e300 (was accepted)",
    lambda: limits_files.read_pilz_cartesian_limits(
        named_limits_file(
            "pilz_big.yaml", "max_trans_vel: 1\nmax_trans_acc: 2\nmax_trans_dec: -5\nmax_rot_vel: 1e300\n"
        )
    ),
    limits_files.LimitsFileError,
    "pilz_big.yaml:4:1: max_rot_vel = 1e+300: must be in [1e-12, 1e+12] in magnitude",
)
row(
    "jobs.load_job",
    "nested-SLERP blend_weight 1e-300 (was 'planning failed: segments[0].length = 0')",
    lambda: jobs.load_job(
        job_file(
            "tiny_weight.yaml",
            data=[
                (
                    "  - lin: {to: {xyzuvw: [0.05, 0.02, 0, 10, 0, 30]}}",
                    "  - lin: {to: {xyzuvw: [0.05, 0, 0, 0, 0, 0]}}\n"
                    "  - lin: {to: {xyzuvw: [0.05, 0.05, 0, 0, 0, 30]}}\n"
                    "    blend_weight: 1e-300\n    orientation_blend: nested_slerp",
                )
            ],
        )
    ),
    V,
    "tiny_weight.yaml:9:5: moves[1].blend_weight: 1e-300: must be at least 1e-05",
)
row(
    "jobs.load_job",
    "angular_velocity 1e300 deg/s (was shown in rad/s at `limits`)",
    lambda: jobs.load_job(job_file("angular.yaml", data=[("jerk: 5.0}", "jerk: 5.0, angular_velocity: 1e300}")])),
    V,
    "angular.yaml:8:55: limits.angular_velocity: 1e+300: must be in [5.72958e-11, 5.72958e+13] deg/s",
)

section("Pickled states")


def unpickled(cls, state):
    """What pickle.loads does with `state`: a new instance, then __setstate__."""
    obj = cls.__new__(cls)
    obj.__setstate__(state)
    return obj


def trajectory_state(change):
    """The state of trajectory() with `change(state as a list)` applied."""
    s = list(trajectory().__getstate__())
    change(s)
    return tuple(s)


def faster_law(s, factor=1000.0):
    """Every law of a Trajectory state run `factor` times faster (v × f, a × f², j × f³)."""
    scale = lambda x: (x[0], x[1] * factor, x[2] * factor**2, x[3] * factor**3)  # noqa: E731
    runs, pieces = s[2]
    s[2] = (
        runs,
        tuple(
            (
                (
                    k,
                    tuple((d / factor, j * factor**3, scale(a), scale(b)) for d, j, a, b in ph),
                    tuple(t / factor for t in ts),
                    S,
                    peak * factor,
                    scale(x0),
                    scale(x1),
                ),
                s0,
            )
            for (k, ph, ts, S, peak, x0, x1), s0 in pieces
        ),
    )


def jumping_section(s):
    """A LIN section appended 8.6 m along x from where the path ends."""
    last = s[0][-1]
    end = last[2] if last[0] == "lin" else None
    start = end[:4] + (end[4] + 8.6,) + end[5:]
    s[0] = s[0] + (("lin", start, start[:4] + (start[4] + 0.1,) + start[5:], "decoupled", (0.0, 0.0, 0.0)),)
    s[1] = s[1] + (0.1,)


def short_report_sample():
    """A JointLimitReport state whose sample 1 has two joint positions where the others have six."""
    report = dispkin.check_joint_limits(dispkin.plan(ur_path(), good_set(), LIMITS), ur5e(), Q_UR).__getstate__()
    samples = list(report[0])
    samples[1] = samples[1][:2] + (samples[1][2][:2],) + samples[1][3:]
    return (tuple(samples),) + report[1:]


row(
    "Pose.__setstate__",
    "translation beyond the numeric range (1e300 m)",
    lambda: unpickled(dispkin.Pose, ((1.0, 0.0, 0.0, 0.0), (1e300, 0.0, 0.0))),
    V,
    "Pose.__setstate__: translation = (1e+300, 0, 0): must have coordinates within ±1e12 m",
)
row(
    "Pose.__setstate__",
    "NaN translation",
    lambda: unpickled(dispkin.Pose, ((1.0, 0.0, 0.0, 0.0), (NAN, 0.0, 0.0))),
    V,
    "Pose.__setstate__: translation = (nan, 0, 0): must be finite",
)
row(
    "Pose.__setstate__",
    "a str for the translation",
    lambda: unpickled(dispkin.Pose, ((1.0, 0.0, 0.0, 0.0), "origin")),
    TypeError,
    "Pose.__setstate__: state[1] (translation) = 'origin': must be a tuple of 3 floats",
)
row(
    "Pose.__setstate__",
    "a state of 3 items",
    lambda: unpickled(dispkin.Pose, (1, 2, 3)),
    V,
    "Pose.__setstate__: state: expected a tuple of 2 items, got (1, 2, 3)",
)
row(
    "Pose.__setstate__",
    "called on a live Pose (was ignored)",
    lambda: A.__setstate__(B.__getstate__()),
    TypeError,
    "Pose.__setstate__: the object already holds a Pose",
)
row(
    "Limits.__setstate__",
    "an int-typed field is a str",
    lambda: unpickled(dispkin.Limits, (0.1, "1", None, None, None)),
    TypeError,
    "Limits.__setstate__: state[1] (acceleration) = '1': must be a float",
)
row(
    "Limits.__setstate__",
    "velocity 1e300",
    lambda: unpickled(dispkin.Limits, (1e300, 1.0, None, None, None)),
    V,
    "Limits.__setstate__: velocity = 1e+300: must be in [1e-12, 1e12]",
)
row(
    "Trajectory.__setstate__",
    "laws 1000 times over the velocity-limit curve",
    lambda: unpickled(dispkin.Trajectory, trajectory_state(faster_law)),
    V,
    "Trajectory.__setstate__: time_law pieces[0] peak velocity = 100: must be at most the velocity limit over its span, 0.1 m/s",
)
row(
    "Trajectory.__setstate__",
    "a section 8.6 m away from the one before (the path jumps)",
    lambda: unpickled(dispkin.Trajectory, trajectory_state(jumping_section)),
    V,
    "must start where the path ends (gap 8.6",
)
row(
    "Trajectory.__setstate__",
    "section lengths twice the law's distance",
    lambda: unpickled(dispkin.Trajectory, trajectory_state(lambda s: s.__setitem__(1, tuple(2 * L for L in s[1])))),
    V,
    "Trajectory.__setstate__: time_law distance = ",
)
row(
    "Trajectory.__setstate__",
    "a stopped motion without its stop",
    lambda: unpickled(
        dispkin.Trajectory, tuple(s[:5] + ((),) + s[6:] for s in [trajectory().stopped_at(0.5).__getstate__()])[0]
    ),
    V,
    "Trajectory.__setstate__: time_law distance = ",
)
row(
    "Trajectory.__setstate__",
    "override factor 0",
    lambda: unpickled(dispkin.Trajectory, trajectory_state(lambda s: s.__setitem__(8, 0.0))),
    V,
    "Trajectory.__setstate__: override_factor = 0: must be in [0.001, 10]",
)
row(
    "Trajectory.__setstate__",
    "a cut law cut after its end",
    lambda: unpickled(
        dispkin.Trajectory,
        tuple(
            s[:2] + ((s[2][0], tuple(p if len(p) == 2 else p[:2] + (1e6,) for p in s[2][1])),) + s[3:]
            for s in [trajectory().with_override(0.5, 0.5).__getstate__()]
        )[0],
    ),
    V,
    "cut time = 1000000",
)
row(
    "Trajectory.__setstate__",
    "a law's distance 1e308",
    lambda: unpickled(
        dispkin.Trajectory,
        trajectory_state(
            lambda s: s.__setitem__(
                2, (s[2][0], ((s[2][1][0][0][:3] + (1e308,) + s[2][1][0][0][4:], 0.0),) + s[2][1][1:])
            )
        ),
    ),
    V,
    "Trajectory.__setstate__: state[2] (time_law.pieces[0].profile) end.s = ",
)
row(
    "Trajectory.__setstate__",
    "NaN section length",
    lambda: unpickled(dispkin.Trajectory, trajectory_state(lambda s: s.__setitem__(1, (NAN,) + s[1][1:]))),
    V,
    "Trajectory.__setstate__: state[1] (section_lengths[0]) = nan: must be finite",
)
row(
    "Trajectory.__setstate__",
    "an int where a run count is a str",
    lambda: unpickled(dispkin.Trajectory, trajectory_state(lambda s: s.__setitem__(2, ("1",) + s[2][1:]))),
    TypeError,
    "Trajectory.__setstate__: state[2] (time_law.runs) = '1': must be an int",
)
row(
    "Profile.__setstate__",
    "phase velocities 1000 times its peak",
    lambda: unpickled(
        dispkin.Profile,
        (
            lambda k, ph, ts, S, peak, a, b: (
                k,
                tuple((d, j, (x[0], x[1] * 1000, x[2], x[3]), (y[0], y[1] * 1000, y[2], y[3])) for d, j, x, y in ph),
                ts,
                S,
                peak,
                a,
                b,
            )
        )(*dispkin.Profile.trapezoid(1.0, 0.5, 1.0).__getstate__()),
    ),
    V,
    "Profile.__setstate__: phases[0].end (s, v, a) = (",
)
row(
    "JointLimitReport.__setstate__",
    "per-sample arrays of different sizes (read past the buffer)",
    lambda: unpickled(dispkin.JointLimitReport, short_report_sample()),
    V,
    "JointLimitReport.__setstate__: samples[1].q size = 2: must be 6, as in samples[0]",
)
row(
    "SerialArm.__setstate__",
    "an int for the URDF text",
    lambda: unpickled(dispkin.SerialArm, (5,) + ur5e().__getstate__()[1:]),
    TypeError,
    "SerialArm.__setstate__: state[0] (urdf) = 5: must be a str",
)
row(
    "LegViolation.__setstate__",
    "leg index 7",
    lambda: unpickled(dispkin.LegViolation, (7, 0.1, 0.15, 0.32, 0.05)),
    V,
    "LegViolation.__setstate__: leg = 7: must be a leg index 0 to 5",
)

section("Batches")

BATCH_OUT = str(JOB_DIR / "batch_out")
row("dispkin.batch", "no job file", lambda: dispkin.batch([], BATCH_OUT), V, "jobs: no job file given")
row(
    "dispkin.batch",
    "workers = 0",
    lambda: dispkin.batch([job_file("good.yaml")], BATCH_OUT, workers=0),
    V,
    "workers = 0: must be an integer from 1 to ",
)
row(
    "dispkin.batch",
    "workers = 2.5",
    lambda: dispkin.batch([job_file("good.yaml")], BATCH_OUT, workers=2.5),
    V,
    "workers = 2.5: must be an integer from 1 to ",
)
row(
    "dispkin.batch",
    "workers and a scheduler",
    lambda: dispkin.batch([job_file("good.yaml")], BATCH_OUT, workers=2, scheduler="tcp://127.0.0.1:8786"),
    V,
    "workers = 2: give either workers (local processes) or scheduler (a Dask cluster), not both",
)
row(
    "dispkin.batch",
    "scheduler = 42",
    lambda: dispkin.batch([job_file("good.yaml")], BATCH_OUT, scheduler=42),
    V,
    "scheduler = 42: must be the address of a Dask scheduler (e.g. 'tcp://host:8786') or a distributed.Client",
)
row(
    "cli.main",
    "batch -o naming an existing file",
    lambda: run_cli("batch", "good.yaml", "-o", pathlib.Path(job_file("batch_file.txt", "not a directory\n")).name),
    ExitStatus,
    "exit status 1: dispkin batch: -o DIR = 'batch_file.txt': is not a directory",
)
row(
    "cli.main",
    "batch --scheduler without a port",
    lambda: run_cli("batch", "good.yaml", "-o", "out", "--scheduler", "nowhere"),
    ExitStatus,
    "exit status 1: dispkin batch: --scheduler = 'nowhere': cannot connect to a Dask scheduler there: missing port number in address 'nowhere'",
)
row(
    "cli.main",
    "batch --workers 0",
    lambda: run_cli("batch", "good.yaml", "-o", "out", "--workers", "0"),
    ExitStatus,
    "exit status 2: dispkin batch: error: argument --workers: must be a positive integer, got 0",
)
row(
    "cli.main",
    "batch with --workers and --scheduler",
    lambda: run_cli("batch", "good.yaml", "-o", "out", "--workers", "2", "--scheduler", "tcp://h:1"),
    ExitStatus,
    "exit status 2: dispkin batch: error: argument --scheduler: not allowed with argument --workers",
)
row(
    "cli.main",
    "batch without -o",
    lambda: run_cli("batch", "good.yaml"),
    ExitStatus,
    "exit status 2: dispkin batch: error: the following arguments are required: -o/--outdir",
)

section("Job events (stops, resumptions, speed overrides)")


def events_job(name, *lines):
    """GOOD_JOB with an `events` list of `lines` (the list on line 9, its first entry on line 10)."""
    return job_file(name, GOOD_JOB + "events:\n" + "".join(line + "\n" for line in lines))


def ptp_events_job():
    """The UR5e job with a PTP move before its LIN move, and a stop."""
    text = UR_JOB.format(urdf=URDF / "arm_ur5e_dh.urdf").replace(
        "moves:\n", "moves:\n  - ptp: {joints: [0.1, -1.9, 1.9, -1.57, -1.57, 0.0]}\n"
    )
    return pathlib.Path(job_file("events_ptp.yaml", text + "events:\n  - {at: 0.5, stop: true}\n")).name


row(
    "jobs.load_job",
    "events out of time order",
    lambda: jobs.load_job(events_job("events_order.yaml", "  - {at: 2, stop: true}", "  - {at: 1, resume: true}")),
    V,
    "events_order.yaml:11:6: events[1].at: 1: before the event before it (events[0].at = 2): give the events in time order",
)
row(
    "jobs.load_job",
    "a resume without a stop before it",
    lambda: jobs.load_job(events_job("events_resume.yaml", "  - {at: 1, resume: true}")),
    V,
    "events_resume.yaml:10:13: events[0].resume: true: no stop before it",
)
row(
    "jobs.load_job",
    "two stops in a row",
    lambda: jobs.load_job(events_job("events_stops.yaml", "  - {at: 0.5, stop: true}", "  - {at: 1, stop: true}")),
    V,
    "events_stops.yaml:11:13: events[1].stop: true: the motion is already stopped, by events[0] at t = 0.5 s",
)
row(
    "jobs.load_job",
    "override factor 0",
    lambda: jobs.load_job(events_job("events_zero.yaml", "  - {at: 0.5, override: 0}")),
    V,
    "events_zero.yaml:10:15: events[0].override: 0: must be in [0.001, 10]",
)
row(
    "jobs.load_job",
    "override factor 20",
    lambda: jobs.load_job(events_job("events_twenty.yaml", "  - {at: 0.5, override: 20}")),
    V,
    "events_twenty.yaml:10:15: events[0].override: 20: must be in [0.001, 10]",
)
row(
    "jobs.load_job",
    "an unknown key in an event",
    lambda: jobs.load_job(events_job("events_key.yaml", "  - {at: 0.5, stop: true, speed: 2}")),
    V,
    "events_key.yaml:10:27: events[0].speed: unknown key (allowed here: at, override, resume, stop)",
)
row(
    "jobs.load_job",
    "an event time that is a word",
    lambda: jobs.load_job(events_job("events_word.yaml", "  - {at: soon, stop: true}")),
    V,
    "events_word.yaml:10:6: events[0].at: 'soon' is not of type 'number'",
)
row(
    "jobs.load_job",
    "stop: false",
    lambda: jobs.load_job(events_job("events_false.yaml", "  - {at: 1, stop: false}")),
    V,
    "events_false.yaml:10:13: events[0].stop: false: a `stop` event is written `stop: true`",
)
row(
    "jobs.load_job",
    "a negative event time",
    lambda: jobs.load_job(events_job("events_negative.yaml", "  - {at: -1, stop: true}")),
    V,
    "events_negative.yaml:10:6: events[0].at: -1 is less than the minimum of 0",
)
row(
    "jobs.load_job",
    "a NaN event time",
    lambda: jobs.load_job(events_job("events_nan.yaml", "  - {at: .nan, stop: true}")),
    V,
    "events_nan.yaml:10:6: events[0].at: nan: must be finite",
)
row(
    "jobs.load_job",
    "a stop and an override in one event",
    lambda: jobs.load_job(events_job("events_two.yaml", "  - {at: 1, stop: true, override: 0.5}")),
    V,
    "events_two.yaml:10:5: events[0]: expected exactly one of `stop` | `resume` | `override`; found `at`, `stop`, `override`",
)
row(
    "jobs.load_job",
    "1001 events",
    lambda: jobs.load_job(events_job("events_many.yaml", *(f"  - {{at: {k}, override: 0.5}}" for k in range(1001)))),
    V,
    "events_many.yaml:9:1: events: 1001 events, more than 1000, the most a job may have",
)
row(
    "cli.main",
    "check: events in a job with a PTP move (planned part by part)",
    lambda: run_cli("check", ptp_events_job()),
    ExitStatus,
    "exit status 1: dispkin check: events_ptp.yaml:12:1: events: events apply to a job planned as one Cartesian trajectory; moves[0] is a PTP move",
)
row(
    "cli.main",
    "check: events in a re-timed job",
    lambda: run_cli(
        "check", ur_job("events_retime.yaml", "retime: {method: optimal}", "events:", "  - {at: 0.5, override: 0.5}")
    ),
    ExitStatus,
    "exit status 1: dispkin check: events_retime.yaml:12:1: events: a re-timed trajectory (`retime`) keeps to the joint limits",
)
row(
    "cli.main",
    "plan: a stop after the motion has ended",
    lambda: run_cli("plan", pathlib.Path(events_job("events_late.yaml", "  - {at: 50, stop: true}")).name, "-o", "out"),
    ExitStatus,
    "exit status 1: dispkin plan: events_late.yaml:10:6: events[0].at: 50: the motion ends at t = 1.38066 s; a stop at or after its end changes nothing",
)
row(
    "cli.main",
    "plan: a resume of a stop that came to rest at the end of the path",
    lambda: run_cli(
        "plan",
        pathlib.Path(events_job("events_end.yaml", "  - {at: 1.1, stop: true}", "  - {at: 2, resume: true}")).name,
        "-o",
        "out",
    ),
    ExitStatus,
    "exit status 1: dispkin plan: events_end.yaml:11:13: events[1].resume: true: nothing to resume",
)
row(
    "jobs.plan_job",
    "a stop at 0 never resumed (no motion)",
    lambda: jobs.plan_job(jobs.load_job(events_job("events_never.yaml", "  - {at: 0, stop: true}"))),
    V,
    "events_never.yaml:10:6: events[0].at: 0: the stop comes before the motion starts and no resumption follows",
)

ROWS = R


def _id(r):
    text = f"{r['entry']}__{r['bad']}".replace("+inf", "posinf").replace("-inf", "neginf")
    return re.sub(r"[^A-Za-z0-9]+", "_", text).strip("_")


def _params():
    out = []
    for r in ROWS:
        marks = [pytest.mark.xfail(strict=True, reason=r["xfail"])] if r["xfail"] else []
        out.append(pytest.param(r, id=_id(r), marks=marks))
    return out


def test_row_ids_are_unique():
    ids = [_id(r) for r in ROWS]
    assert len(ids) == len(set(ids))


@pytest.mark.parametrize("r", _params())
def test_bad_input(r):
    if r["accepted"]:
        assert r["check"](r["call"]()), f"the documented behaviour does not hold: {r['accepted']}"
        return
    with pytest.raises(r["exc"]) as info:
        r["call"]()
    assert type(info.value) is r["exc"] or issubclass(type(info.value), r["exc"])
    message = str(info.value)
    assert r["fragment"] in message, f"{message!r} lacks {r['fragment']!r}"


def markdown():
    """The table as Markdown (tests/BAD_INPUT.md), generated from ROWS."""
    lines = [
        "# Bad-input table",
        "",
        "Generated by `tests/python/make_bad_input_table.py` from `tests/python/test_bad_input_table.py`",
        "(do not edit by hand; `test_markdown_is_up_to_date` fails when it is stale). The C++ table",
        "is `tests/cpp/test_bad_input_table.cpp`. Every row asserts the exception type and a fragment",
        "of the message `<argument> = <value>: <reason>`. Rows marked **GAP** are strict xfails: the",
        "entry point does not give the expected error (it accepts the input, or its message is",
        "malformed); the observed behaviour is given. A fix makes the row fail until it is promoted.",
        "Job files (`jobs.load_job`) name the key and where it is: `FILE:LINE:COLUMN: key.path: <reason>`.",
        "Rows of `cli.main` run the command (`dispkin ...`, in the directory of the job files): its",
        "non-zero exit status and its stderr (without the usage lines) are the `ExitStatus` message.",
        "Rows **accepted by design** give no error on purpose (the reason is given) and assert the",
        "documented result instead. The sections after the first hold hostile inputs: nesting, sizes",
        "and counts, wide joint limits, impossible numbers (doc/input-budget.md).",
    ]
    header = [
        "",
        "| # | Entry point | Bad input | Expected error | Message fragment | Status |",
        "|---|---|---|---|---|---|",
    ]
    current = object()
    for i, r in enumerate(ROWS, 1):
        if r["section"] != current:
            current = r["section"]
            lines += (["", f"## {current}"] if current else []) + header
        fragment = r["fragment"].replace("|", "\\|")
        code = f"`` {fragment} ``" if "`" in fragment else f"`{fragment}`"  # a code span holding backticks
        if r["accepted"]:
            reason = r["accepted"].replace("|", "\\|")
            lines.append(f"| {i} | `{r['entry']}` | {r['bad']} | none | — | accepted by design: {reason} |")
            continue
        status = "**GAP** (strict xfail), " + r["xfail"].replace("|", "\\|") if r["xfail"] else "rejected"
        lines.append(f"| {i} | `{r['entry']}` | {r['bad']} | {r['exc'].__name__} | {code} | {status} |")
    rejected = sum(1 for r in ROWS if not r["xfail"] and not r["accepted"])
    by_design = sum(1 for r in ROWS if r["accepted"])
    gaps = len(ROWS) - rejected - by_design
    lines += [
        "",
        f"{len(ROWS)} rows: {rejected} rejected as expected, {by_design} accepted by design, {gaps} gaps.",
        "",
    ]
    return "\n".join(lines)


MARKDOWN_PATH = pathlib.Path(__file__).resolve().parents[1] / "BAD_INPUT.md"


def test_markdown_is_up_to_date():
    assert MARKDOWN_PATH.exists(), "run tests/python/make_bad_input_table.py"
    assert MARKDOWN_PATH.read_text() == markdown(), (
        "tests/BAD_INPUT.md is stale: run tests/python/make_bad_input_table.py"
    )
