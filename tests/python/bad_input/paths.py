"""The rows of the bad-input table (tests/python/test_bad_input_table.py) of one area: Path,
JointPath and Section: construction and sampling."""

import numpy as np

import dispkin

from .rows import A, B, C, INF, LINE, NAN, V, accepted, row

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
