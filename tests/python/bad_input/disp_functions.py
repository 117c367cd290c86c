"""The rows of the bad-input table (tests/python/test_bad_input_table.py) of one area: The DISP
functions: distances, speeds, section lengths, interpolation."""

import numpy as np

import dispkin

from .rows import A, B, INF, NAN, V, XI, accepted, collinear_set, good_set, row

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
