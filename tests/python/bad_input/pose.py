"""The rows of the bad-input table (tests/python/test_bad_input_table.py) of one area: Pose:
construction, conversions, interpolation about a pivot."""

import numpy as np

import dispkin

from .rows import A, B, INF, NAN, V, row

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
