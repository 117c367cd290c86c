"""The rows of the bad-input table (tests/python/test_bad_input_table.py) of one area:
MetricSet, the point shapes (dispkin.shapes) and the convex hull."""

import numpy as np

from dispkin import shapes
import dispkin

from .rows import INF, NAN, V, collinear_set, good_set, row

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
